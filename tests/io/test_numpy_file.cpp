#include "hyst/io/numpy_file.hpp"

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/temp_folder_test.hpp"
#include "hyst/io/limits.hpp"

namespace hyst::io {
namespace {
// The tests are compiled in unity batches: a named namespace keeps these helpers apart.
namespace numpy_test {

namespace fs = std::filesystem;

// ---- .npy files built byte by byte ----------------------------------------------------------

//! `bits` as `size` bytes, least significant first unless `big_endian`.
std::string bytes_of(std::uint64_t bits, std::size_t size, bool big_endian) {
  std::string out(size, '\0');
  for (std::size_t b = 0; b < size; ++b) {
    out[big_endian ? size - 1 - b : b] = static_cast<char>((bits >> (8 * b)) & 0xff);
  }
  return out;
}

std::string f8(const std::vector<double>& values, bool big_endian = false) {
  std::string out;
  for (const double value : values)
    out += bytes_of(std::bit_cast<std::uint64_t>(value), 8, big_endian);
  return out;
}

std::string f4(const std::vector<float>& values, bool big_endian = false) {
  std::string out;
  for (const float value : values)
    out += bytes_of(std::bit_cast<std::uint32_t>(value), 4, big_endian);
  return out;
}

//! A .npy file as NumPy lays it out: magic, version, header length (2 bytes for 1.0, 4 for 2.0
//! and 3.0), the header padded with blanks and a newline to a multiple of 64 bytes, the data.
std::string npy(std::string_view dict, std::string_view data, int major = 1) {
  const std::size_t preamble = major == 1 ? 10 : 12;
  std::string header(dict);
  while ((preamble + header.size() + 1) % 64 != 0)
    header += ' ';
  header += '\n';
  std::string out = "\x93NUMPY";
  out += static_cast<char>(major);
  out += '\0';
  out += bytes_of(header.size(), major == 1 ? 2 : 4, false);
  return out + header + std::string(data);
}

//! A version 1.0 file whose header is exactly `header`, without the padding NumPy adds.
std::string bare_npy(std::string_view header, std::string_view data) {
  std::string out("\x93NUMPY\x01\x00", 8);
  return out + bytes_of(header.size(), 2, false) + std::string(header) + std::string(data);
}

//! The dictionary NumPy writes for a C-order array.
std::string dict(std::string_view descr, std::string_view shape, bool fortran = false) {
  return fmt::format("{{'descr': '{}', 'fortran_order': {}, 'shape': {}, }}", descr,
                     fortran ? "True" : "False", shape);
}

//! 0.25, 0.75, 1.25, ...: exact in float32 and float64, so NumPy's files and these agree bit for
//! bit.
std::vector<double> ramp(std::size_t count) {
  std::vector<double> values(count);
  for (std::size_t k = 0; k < count; ++k)
    values[k] = static_cast<double>(k) * 0.5 + 0.25;
  return values;
}

using Shape = std::vector<std::size_t>;

class NumpyFile : public test::TempFolderTest {
 protected:
  fs::path write(const std::string& name, std::string_view bytes) const {
    const fs::path path = dir_ / name;
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return path;
  }
};

// ---- Reading ---------------------------------------------------------------------------------

TEST(NumpyBenchmarkData, ReadsTheMeasuredFloat64File) {
  // Values printed by NumPy 1.24 (repr: round-trip exact):
  //   a = np.load("u_200mV_test.npy"); a.shape, a[0, 0, 0, 0], a[1, 2, 1, 0], ...
  const NumpyArray a = read_npy(HYST_SHARED_DATA_DIR "/fsm_piezo_mimo_multisine/u_200mV_test.npy");
  ASSERT_EQ(a.shape, (Shape{8192, 3, 3, 2}));
  ASSERT_EQ(a.values.size(), 8192u * 3 * 3 * 2);
  const auto at = [&](std::size_t n, std::size_t c, std::size_t r, std::size_t p) {
    return a.values[((n * 3 + c) * 3 + r) * 2 + p];
  };
  EXPECT_EQ(at(0, 0, 0, 0), 0.2661575972555421);
  EXPECT_EQ(at(1, 2, 1, 0), -0.07465718879179928);
  EXPECT_EQ(at(4096, 1, 0, 1), 0.14935712761771947);
  EXPECT_EQ(at(8191, 2, 2, 1), 0.24912721820624606);
  EXPECT_EQ(a.values[1], 0.266238519204683);
  EXPECT_EQ(a.values[2], -0.09127537711623002);
}

TEST_F(NumpyFile, ReadsVersion1LittleEndianFloat64) {
  const auto bytes = npy(dict("<f8", "(2, 3)"), f8({1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(bytes.size() % 64, 48u);  // header padded so that the data start at byte 128
  const NumpyArray a = read_npy(write("a.npy", bytes));
  EXPECT_EQ(a.shape, (Shape{2, 3}));
  EXPECT_EQ(a.values, (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST_F(NumpyFile, ReadsVersions2And3) {
  for (const int major : {2, 3}) {
    SCOPED_TRACE(major);
    const NumpyArray a = parse_npy(npy(dict("<f8", "(3,)"), f8({-1.5, 0, 1e300}), major), "v.npy");
    EXPECT_EQ(a.shape, (Shape{3}));
    EXPECT_EQ(a.values, (std::vector<double>{-1.5, 0, 1e300}));
  }
}

TEST_F(NumpyFile, ReadsBothByteOrdersOfFloat32AndFloat64) {
  const std::vector<double> expected = {0.1, -2.5, 3e-300, 7};
  EXPECT_EQ(parse_npy(npy(dict(">f8", "(4,)"), f8(expected, true)), "b.npy").values, expected);
  EXPECT_EQ(parse_npy(npy(dict("<f8", "(4,)"), f8(expected, false)), "l.npy").values, expected);
  const std::vector<float> single = {0.1f, -2.5f, 1e-30f, 7.f};
  const std::vector<double> widened(single.begin(), single.end());
  EXPECT_EQ(parse_npy(npy(dict(">f4", "(2, 2)"), f4(single, true)), "b.npy").values, widened);
  EXPECT_EQ(parse_npy(npy(dict("<f4", "(2, 2)"), f4(single, false)), "l.npy").values, widened);
}

TEST_F(NumpyFile, TransposesFortranOrder) {
  // a = [[1, 2, 3], [4, 5, 6]] in Fortran order stores the columns: 1 4 2 5 3 6.
  const NumpyArray a = parse_npy(npy(dict("<f8", "(2, 3)", true), f8({1, 4, 2, 5, 3, 6})), "f");
  EXPECT_EQ(a.shape, (Shape{2, 3}));
  EXPECT_EQ(a.values, (std::vector<double>{1, 2, 3, 4, 5, 6}));

  // Shape (2, 3, 2): the file holds a[i, j, k] at i + 2 * (j + 3 * k); the value encodes the
  // index as 100 i + 10 j + k.
  std::vector<double> stored(12);
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 2; ++k)
        stored[i + 2 * (j + 3 * k)] = static_cast<double>(100 * i + 10 * j + k);
  const NumpyArray b = parse_npy(npy(dict(">f8", "(2, 3, 2)", true), f8(stored, true)), "f");
  std::vector<double> expected;
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 2; ++k)
        expected.push_back(static_cast<double>(100 * i + 10 * j + k));
  EXPECT_EQ(b.values, expected);

  // One axis: Fortran and C order are the same.
  EXPECT_EQ(parse_npy(npy(dict("<f4", "(3,)", true), f4({1, 2, 3})), "f").values,
            (std::vector<double>{1, 2, 3}));
}

TEST_F(NumpyFile, ReadsZeroAndOneDimensionalArrays) {
  const NumpyArray scalar = parse_npy(npy(dict("<f8", "()"), f8({2.5})), "s.npy");
  EXPECT_TRUE(scalar.shape.empty());
  EXPECT_EQ(scalar.values, (std::vector<double>{2.5}));

  const NumpyArray line = parse_npy(npy(dict("<f8", "(5,)"), f8({1, 2, 3, 4, 5})), "l.npy");
  EXPECT_EQ(line.shape, (Shape{5}));
  EXPECT_EQ(line.values.size(), 5u);

  const NumpyArray empty = parse_npy(npy(dict("<f8", "(0,)"), ""), "e.npy");
  EXPECT_EQ(empty.shape, (Shape{0}));
  EXPECT_TRUE(empty.values.empty());
  // An empty axis makes any other axis length harmless.
  EXPECT_TRUE(parse_npy(npy(dict("<f8", "(0, 99999999999999)"), ""), "e.npy").values.empty());
}

TEST_F(NumpyFile, AcceptsTheHeaderVariantsPythonAllows) {
  const std::vector<std::string> headers = {
      "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }",          // NumPy's own
      "{'shape': (2, 2), 'fortran_order': False, 'descr': '<f8'}",            // any order
      R"({"descr": "<f8", "fortran_order": False, "shape": (2, 2)})",         // double quotes
      "{ 'descr' :'<f8' ,\n 'fortran_order':False,'shape':( 2 ,2 , ) , }",    // blanks, commas
      "{'descr': '<f8', 'fortran_order': False, 'shape': (2L, 2L), }",        // Python 2 longs
      "\t{'descr': '<f8', 'fortran_order': False, 'shape': ((2), 2)}\n\n  ",  // (2) is 2
  };
  for (const auto& header : headers) {
    SCOPED_TRACE(header);
    const NumpyArray a = parse_npy(npy(header, f8({1, 2, 3, 4})), "h.npy");
    EXPECT_EQ(a.shape, (Shape{2, 2}));
    EXPECT_EQ(a.values, (std::vector<double>{1, 2, 3, 4}));
  }
  // No padding at all, and a header that is not a multiple of 16 bytes long.
  const NumpyArray bare = parse_npy(
      bare_npy("{'descr':'<f8','fortran_order':False,'shape':(1,)}", f8({9})), "bare.npy");
  EXPECT_EQ(bare.values, (std::vector<double>{9}));
}

// ---- Files NumPy wrote (at test time, with the system's Python) ------------------------------

//! The system's Python with NumPy, which writes the reference files of the tests below.
bool have_numpy() {
  static const bool available =
      std::system("/usr/bin/python3 -c 'import numpy' > /dev/null 2>&1") == 0;
  return available;
}

//! Writes the reference files into `folder`. ramp(n) is np.arange(n) * 0.5 + 0.25.
constexpr std::string_view kMakeFiles = R"(
import sys, zipfile
import numpy as np
from numpy.lib import format as npformat

d = sys.argv[1]
def ramp(*shape):
    return (np.arange(int(np.prod(shape)), dtype=np.float64) * 0.5 + 0.25).reshape(shape)

for major in (1, 2, 3):
    with open(f"{d}/v{major}.npy", "wb") as f:
        npformat.write_array(f, ramp(2, 3, 4), version=(major, 0))
np.save(f"{d}/f4_big_endian.npy", ramp(3, 5).astype(">f4"))
np.save(f"{d}/fortran.npy", np.asfortranarray(ramp(2, 3, 4)))
np.save(f"{d}/scalar.npy", np.float64(2.5))
np.save(f"{d}/ints.npy", np.arange(6).reshape(2, 3))
np.save(f"{d}/objects.npy", np.array([1, "a"], dtype=object), allow_pickle=True)
np.save(f"{d}/records.npy", np.zeros(2, dtype=[("x", "<f8"), ("y", "<f8")]))

arrays = dict(u=ramp(4, 3), y=ramp(2, 2).astype(">f4"), f=np.asfortranarray(ramp(3, 2)))
np.savez(f"{d}/stored.npz", **arrays)
np.savez_compressed(f"{d}/deflated.npz", **arrays)
np.savez(f"{d}/single.npz", ramp(5))
np.savez(f"{d}/none.npz")
np.savez(f"{d}/mixed.npz", good=ramp(2), ints=np.arange(3), bad=np.array([1.0, np.nan]))
with zipfile.ZipFile(f"{d}/extra.npz", "w") as z:
    z.writestr("notes.txt", "not an array")
    z.writestr("a.npy", open(f"{d}/v1.npy", "rb").read())

# A member that claims 2 GiB (local and central headers patched).
with zipfile.ZipFile(f"{d}/claims_2gb.npz", "w", zipfile.ZIP_DEFLATED) as z:
    z.writestr("a.npy", open(f"{d}/v1.npy", "rb").read())
b = bytearray(open(f"{d}/claims_2gb.npz", "rb").read())
for signature, offset in ((b"PK\x03\x04", 22), (b"PK\x01\x02", 24)):
    at = b.find(signature) + offset
    b[at:at + 4] = (2**31).to_bytes(4, "little")
open(f"{d}/claims_2gb.npz", "wb").write(b)

# A stored member with one data byte changed: its CRC no longer matches.
np.savez(f"{d}/crc.npz", a=ramp(4))
b = bytearray(open(f"{d}/crc.npz", "rb").read())
b[b.find(b"\x93NUMPY") + 130] ^= 0xFF
open(f"{d}/crc.npz", "wb").write(b)
)";

//! A member that inflates to 258 MiB of zeros but claims 1 000 bytes (libzip inflates to the end
//! of the deflate stream, whatever the claim).
constexpr std::string_view kMakeInflating = R"(
import sys, zipfile
d = sys.argv[1]
with zipfile.ZipFile(f"{d}/inflating.npz", "w", zipfile.ZIP_DEFLATED) as z:
    with z.open("a.npy", "w") as member:
        for _ in range(258):
            member.write(bytes(2**20))
b = bytearray(open(f"{d}/inflating.npz", "rb").read())
for signature, offset in ((b"PK\x03\x04", 22), (b"PK\x01\x02", 24)):
    at = b.find(signature) + offset
    b[at:at + 4] = (1000).to_bytes(4, "little")
open(f"{d}/inflating.npz", "wb").write(b)
)";

class NumpyWrittenFiles : public NumpyFile {
 protected:
  void SetUp() override {
    NumpyFile::SetUp();
    if (!have_numpy()) GTEST_SKIP() << "/usr/bin/python3 with NumPy is not available";
    run_python(kMakeFiles);
  }
  void run_python(std::string_view script) const {
    const fs::path path = write("make_files.py", script);
    const std::string command =
        fmt::format("/usr/bin/python3 '{}' '{}'", path.string(), dir_.string());
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }
  std::string file(std::string_view name) const { return (dir_ / name).string(); }
};

TEST_F(NumpyWrittenFiles, ReadsEveryNumpyVersionAndDtype) {
  for (const char* name : {"v1.npy", "v2.npy", "v3.npy", "fortran.npy"}) {
    SCOPED_TRACE(name);
    const NumpyArray a = read_npy(file(name));
    EXPECT_EQ(a.shape, (Shape{2, 3, 4}));
    EXPECT_EQ(a.values, ramp(24));
  }
  const NumpyArray f4 = read_npy(file("f4_big_endian.npy"));
  EXPECT_EQ(f4.shape, (Shape{3, 5}));
  EXPECT_EQ(f4.values, ramp(15));
  const NumpyArray scalar = read_numpy_array(file("scalar.npy"));
  EXPECT_TRUE(scalar.shape.empty());
  EXPECT_EQ(scalar.values, (std::vector<double>{2.5}));
}

TEST_F(NumpyWrittenFiles, RefusesWhatNumpyWritesForOtherDtypes) {
  EXPECT_HYST_ERROR(read_npy(file("ints.npy")),
                    "ints.npy: .npy header: dtype '<i8' (int64) is not supported; hyst reads "
                    "float64 ('<f8', '>f8') and float32 ('<f4', '>f4') arrays");
  EXPECT_HYST_ERROR(read_npy(file("objects.npy")),
                    "objects.npy: .npy header: dtype '|O' (Python objects, stored with pickle) "
                    "is not supported: hyst does not unpickle");
  EXPECT_HYST_ERROR(read_npy(file("records.npy")),
                    "records.npy: .npy header: a structured dtype [('x', '<f8'), ('y', '<f8')] "
                    "(named fields) is not supported");
}

TEST_F(NumpyWrittenFiles, ReadsSavezAndSavezCompressed) {
  for (const char* name : {"stored.npz", "deflated.npz"}) {
    SCOPED_TRACE(name);
    const std::string path = file(name);
    EXPECT_EQ(npz_array_names(path), (std::vector<std::string>{"u", "y", "f"}));
    const NumpyArray u = read_npz_array(path, "u");
    EXPECT_EQ(u.shape, (Shape{4, 3}));
    EXPECT_EQ(u.values, ramp(12));
    const NumpyArray y = read_npz_array(path, "y.npy");  // the member's own name works too
    EXPECT_EQ(y.shape, (Shape{2, 2}));
    EXPECT_EQ(y.values, ramp(4));
    const NumpyArray f = read_numpy_array(path + ":f");
    EXPECT_EQ(f.shape, (Shape{3, 2}));
    EXPECT_EQ(f.values, ramp(6));
  }
  const NumpyArray single = read_numpy_array(file("single.npz"));
  EXPECT_EQ(single.shape, (Shape{5}));
  EXPECT_EQ(single.values, ramp(5));
  EXPECT_EQ(npz_array_names(file("single.npz")), (std::vector<std::string>{"arr_0"}));
  // Members that are not .npy files are not arrays.
  EXPECT_EQ(npz_array_names(file("extra.npz")), (std::vector<std::string>{"a"}));
  EXPECT_EQ(read_numpy_array(file("extra.npz")).values, ramp(24));
}

TEST_F(NumpyWrittenFiles, NamesTheArchiveAndTheArrayInErrors) {
  EXPECT_HYST_ERROR(read_numpy_array(file("stored.npz")),
                    "stored.npz: 3 arrays (u, y, f) where one was expected; name one as " +
                        file("stored.npz") + ":NAME");
  EXPECT_HYST_ERROR(read_numpy_array(file("none.npz")),
                    "none.npz: no array in the archive (no .npy member)");
  EXPECT_HYST_ERROR(read_npz_array(file("none.npz"), "u"),
                    "none.npz: no array 'u' (the archive holds no array (no .npy member))");
  EXPECT_HYST_ERROR(read_numpy_array(file("stored.npz") + ":v"),
                    "stored.npz: no array 'v' (arrays: u, y, f)");
  EXPECT_HYST_ERROR(read_npz_array(file("mixed.npz"), "ints"),
                    "mixed.npz:ints: .npy header: dtype '<i8' (int64) is not supported");
  EXPECT_HYST_ERROR(read_numpy_array(file("mixed.npz") + ":bad"),
                    "mixed.npz:bad: the value at index (1,) (flat index 1 in C order) is nan");
  EXPECT_EQ(read_npz_array(file("mixed.npz"), "good").values, ramp(2));
  EXPECT_HYST_ERROR(read_npz_array(file("v1.npy"), "a"),
                    "v1.npy: not an .npz file (a zip archive): Not a zip archive (it is a .npy "
                    "file)");
  EXPECT_HYST_ERROR(read_numpy_array(file("v1.npy") + ":a"), "cannot open '");
  EXPECT_HYST_ERROR(read_npy(file("stored.npz")),
                    "stored.npz: not a .npy file: it does not start with \\x93NUMPY (it is a zip "
                    "archive: an .npz?)");
}

TEST_F(NumpyWrittenFiles, BoundsWhatAMemberInflatesTo) {
  EXPECT_HYST_ERROR(read_npz_array(file("claims_2gb.npz"), "a"),
                    fmt::format("claims_2gb.npz:a: the member claims 2147483648 bytes, more than "
                                "the limit of {} (the largest .npy of 33554432 values)",
                                limits::kMaxNpzMemberBytes));
  run_python(kMakeInflating);
  EXPECT_HYST_ERROR(read_npz_array(file("inflating.npz"), "a"),
                    fmt::format("inflating.npz:a: the member inflates to more than {} bytes, the "
                                "limit (the largest .npy of 33554432 values)",
                                limits::kMaxNpzMemberBytes));
  EXPECT_HYST_ERROR(read_npz_array(file("crc.npz"), "a"),
                    "crc.npz:a: cannot read the member: CRC error");
}

// ---- Errors of .npy files ----------------------------------------------------------------------

TEST_F(NumpyFile, RefusesBadPreambles) {
  EXPECT_HYST_ERROR(parse_npy("", "x.npy"), "x.npy: not a .npy file: it is empty");
  EXPECT_HYST_ERROR(parse_npy("a,b\n1,2\n", "x.npy"),
                    "x.npy: not a .npy file: it does not start with \\x93NUMPY");
  EXPECT_HYST_ERROR(parse_npy("\x93NUMPY", "x.npy"),
                    "x.npy: the .npy file ends inside its format version");
  EXPECT_HYST_ERROR(parse_npy(std::string("\x93NUMPY\x04\x00", 8), "x.npy"),
                    "x.npy: .npy format version 4.0 is not supported (1.0, 2.0 and 3.0 are)");
  EXPECT_HYST_ERROR(parse_npy(std::string("\x93NUMPY\x01\x01", 8), "x.npy"),
                    "format version 1.1 is not supported");
  EXPECT_HYST_ERROR(parse_npy(std::string("\x93NUMPY\x02\x00\x10\x00", 10), "x.npy"),
                    "x.npy: the .npy file ends inside its header length");
  EXPECT_HYST_ERROR(parse_npy(std::string("\x93NUMPY\x01\x00\x76\x00{'descr'", 17), "x.npy"),
                    "x.npy: the .npy header is cut short: it claims 118 bytes, the file has 7 "
                    "after the preamble");
  EXPECT_HYST_ERROR(parse_npy(std::string("\x93NUMPY\x02\x00\x11\x27\x00\x00", 12), "x.npy"),
                    "x.npy: the .npy header claims 10001 bytes, more than the limit of 10000 "
                    "(NumPy's own)");
}

TEST_F(NumpyFile, SaysWhatIsWrongWithAMalformedHeader) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"",
       "h.npy: malformed .npy header at byte 54: the header ends where a value should start "
       "(header: )"},
      {"{'descr': '<f8' 'fortran_order': False, 'shape': (1,)}",
       "h.npy: malformed .npy header at byte 16: expected ',' or '}' (header: {'descr': '<f8' "
       "'fortran_order': False, 'shape': (1,)})"},
      {"{'descr' '<f8'}", "malformed .npy header at byte 9: expected ':' after a key"},
      {"{'descr': '<f8}", "a string runs to the end of the line"},
      {"{'descr': <f8}", "malformed .npy header at byte 10: unexpected character '<'"},
      {"{'shape': (1.5,)}", "a number that is not a whole decimal number"},
      {"{'shape': (0x10,)}", "a number that is not a whole decimal number"},
      {"{'shape': (-,)}", "a '-' without digits"},
      {"{'fortran_order': false}", "unknown name 'false' (expected True, False or None)"},
      {"{'shape': (1, 2}", "expected ',' or ')'"},
      {"{'descr': '<f8'} x", "unexpected text after the dictionary"},
      {std::string(40, '(') + "1" + std::string(40, ')'), "values nested deeper than 16"},
      {"['descr', '<f8']",
       ".npy header: not a dictionary {'descr': ..., 'fortran_order': ..., 'shape': ...}"},
      {"{'descr': '<f8', 'fortran_order': False}",
       ".npy header: no key 'shape' (NumPy writes 'descr', 'fortran_order' and 'shape')"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': (1,), 'extra': 1}",
       ".npy header: unknown key 'extra' (NumPy writes"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': (1,), 3: 1}",
       ".npy header: unknown key 3"},
      {"{'descr': '<f8', 'descr': '<f8', 'fortran_order': False, 'shape': (1,)}",
       ".npy header: the key 'descr' appears twice"},
      {"{'descr': '<f8', 'fortran_order': 0, 'shape': (1,)}",
       ".npy header: 'fortran_order' must be True or False, not 0"},
      {"{'descr': '<f8', 'fortran_order': None, 'shape': (1,)}",
       "'fortran_order' must be True or False, not None"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': [1]}",
       ".npy header: 'shape' must be a tuple of whole numbers such as (8192, 3), not [1]"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': 1}", "'shape' must be a tuple"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': (2, '3')}",
       ".npy header: axis 1 of 'shape' is '3', not a whole number"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': (2, -3)}",
       ".npy header: axis 1 of 'shape' is negative (-3)"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': (18446744073709551616,)}",
       ".npy header: axis 0 of 'shape', 18446744073709551616, is too large"},
      {"{'descr': 8, 'fortran_order': False, 'shape': (1,)}",
       ".npy header: 'descr' 8 is not a dtype string such as '<f8'"},
  };
  for (const auto& [header, message] : cases) {
    SCOPED_TRACE(header);
    EXPECT_HYST_ERROR(parse_npy(npy(header, f8({1})), "h.npy"), message);
  }
  EXPECT_HYST_ERROR(parse_npy(bare_npy("{'descr': '<f8", ""), "h.npy"),
                    "h.npy: malformed .npy header at byte 14: a string runs to the end of the "
                    "header (header: {'descr': '<f8)");
  // The header is shown in the message, with bytes that are not printable ASCII escaped.
  EXPECT_HYST_ERROR(parse_npy(npy("{'descr': '<f8', \xff}", ""), "h.npy"),
                    "unexpected character '\\xff' (header: {'descr': '<f8', \\xff}");
}

TEST_F(NumpyFile, NamesTheDtypeItRefuses) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"<i8",
       "dtype '<i8' (int64) is not supported; hyst reads float64 ('<f8', '>f8') and "
       "float32 ('<f4', '>f4') arrays"},
      {"|u1", "dtype '|u1' (uint8) is not supported"},
      {"|b1", "dtype '|b1' (bool) is not supported"},
      {"<f2", "dtype '<f2' (float16) is not supported"},
      {"<f16", "dtype '<f16' (long double) is not supported"},
      {"<c16", "dtype '<c16' (complex128) is not supported"},
      {"<U3", "dtype '<U3' (unicode strings) is not supported"},
      {"<M8[ns]", "dtype '<M8[ns]' is not supported"},
      {"|O",
       "dtype '|O' (Python objects, stored with pickle) is not supported: hyst does not "
       "unpickle"},
      {"=f8", "dtype '=f8' (float64, but not with the byte order '<' or '>' that NumPy writes)"},
      {"f4", "dtype 'f4' (float32, but not with the byte order"},
      {"", "dtype '' is not supported"},
  };
  for (const auto& [descr, message] : cases) {
    SCOPED_TRACE(descr);
    EXPECT_HYST_ERROR(parse_npy(npy(dict(descr, "(1,)"), f8({1})), "d.npy"),
                      "d.npy: .npy header: " + message);
  }
  EXPECT_HYST_ERROR(
      parse_npy(npy("{'descr': [('x', '<f8')], 'fortran_order': False, 'shape': (1,)}", f8({1})),
                "d.npy"),
      "d.npy: .npy header: a structured dtype [('x', '<f8')] (named fields) is not supported");
  EXPECT_HYST_ERROR(
      parse_npy(npy("{'descr': ('<f8', (2,)), 'fortran_order': False, 'shape': (1,)}", f8({1})),
                "d.npy"),
      "d.npy: .npy header: 'descr' ('<f8', (2,)) is not a dtype string");
}

TEST_F(NumpyFile, RefusesShapesBeyondTheLimits) {
  EXPECT_HYST_ERROR(
      parse_npy(npy(dict("<f8", "(4294967296, 4294967296)"), ""), "s.npy"),
      "s.npy: the shape (4294967296, 4294967296) has more values than a 64-bit count holds");
  EXPECT_HYST_ERROR(parse_npy(npy(dict("<f8", "(8192, 8192)"), ""), "s.npy"),
                    "s.npy: the shape (8192, 8192) holds 67108864 values, more than the limit "
                    "of 33554432 values of one array");
  std::string many = "(";
  for (int k = 0; k < 65; ++k)
    many += "1, ";
  EXPECT_HYST_ERROR(parse_npy(npy(dict("<f8", many + ")"), f8({1})), "s.npy"),
                    "s.npy: .npy header: 'shape' has 65 axes; NumPy allows at most 64");
}

TEST_F(NumpyFile, RefusesDataOfTheWrongLength) {
  EXPECT_HYST_ERROR(parse_npy(npy(dict("<f8", "(2, 3)"), f8({1, 2, 3, 4, 5})), "d.npy"),
                    "d.npy: the data part is cut short: the shape (2, 3) of float64 needs 48 "
                    "bytes, there are 40 after the header");
  EXPECT_HYST_ERROR(parse_npy(npy(dict(">f4", "(2,)"), f4({1, 2, 3})), "d.npy"),
                    "d.npy: the data part is longer than the shape says: the shape (2,) of "
                    "float32 needs 8 bytes, there are 12 after the header");
  EXPECT_HYST_ERROR(parse_npy(npy(dict("<f8", "()"), ""), "d.npy"),
                    "the data part is cut short: the shape () of float64 needs 8 bytes");
}

TEST_F(NumpyFile, NamesTheIndexOfANonFiniteValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_HYST_ERROR(parse_npy(npy(dict("<f8", "(2, 3)"), f8({0, 1, 2, 3, 4, nan})), "n.npy"),
                    "n.npy: the value at index (1, 2) (flat index 5 in C order) is nan; hyst "
                    "reads finite values only");
  // Fortran order: the fourth stored value is a[1, 1], flat index 4 in C order.
  EXPECT_HYST_ERROR(parse_npy(npy(dict("<f8", "(2, 3)", true), f8({0, 1, 2, -inf, 4, 5})), "n"),
                    "n: the value at index (1, 1) (flat index 4 in C order) is -inf");
  EXPECT_HYST_ERROR(
      parse_npy(npy(dict(">f4", "()"), f4({std::numeric_limits<float>::infinity()}, true)), "n"),
      "n: the value at index () (flat index 0 in C order) is inf");
}

TEST_F(NumpyFile, ReadsSpecsByContent) {
  const auto bytes = npy(dict("<f8", "(2,)"), f8({1, 2}));
  EXPECT_EQ(read_numpy_array(write("a.npy", bytes).string()).values, (std::vector<double>{1, 2}));
  // The name does not decide, the content does; a ':' in a file name is no array name.
  EXPECT_EQ(read_numpy_array(write("data.bin", bytes).string()).values.size(), 2u);
  EXPECT_EQ(read_numpy_array(write("a.npz:b", bytes).string()).values.size(), 2u);
  EXPECT_HYST_ERROR(read_numpy_array(write("t.csv", "a,b\n1,2\n").string()),
                    "t.csv: neither a .npy file (it would start with \\x93NUMPY) nor an .npz file "
                    "(a zip archive)");
  EXPECT_HYST_ERROR(read_numpy_array((dir_ / "missing.npy").string()), "cannot open '");
  EXPECT_HYST_ERROR(read_numpy_array((dir_ / "missing.npz:u").string()),
                    "missing.npz': No such file or directory");
  EXPECT_HYST_ERROR(read_npz_array(write("empty.npz", ""), "u"),
                    "empty.npz: not an .npz file: it is empty");
  EXPECT_HYST_ERROR(read_npz_array(write("noise.npz", "PK\x03\x04 not really"), "u"),
                    "noise.npz: not an .npz file (a zip archive): ");
}

// ---- arrange_periodic ---------------------------------------------------------------------------

//! An array whose every value names its index: 1000 n + 100 c + 10 r + p for the axes of
//! `layout_axes` ('n', 'c', 'r', 'p', in the array's order) with lengths `shape`.
NumpyArray indexed_array(std::string_view layout_axes, const Shape& shape) {
  NumpyArray array{.shape = shape, .values = {}};
  std::size_t count = 1;
  for (const auto length : shape)
    count *= length;
  const std::string_view names = "ncrp";
  const double weights[] = {1000, 100, 10, 1};
  for (std::size_t flat = 0; flat < count; ++flat) {
    double value = 0;
    std::size_t rest = flat;
    for (std::size_t d = shape.size(); d-- > 0;) {
      value += weights[names.find(layout_axes[d])] * static_cast<double>(rest % shape[d]);
      rest /= shape[d];
    }
    array.values.push_back(value);
  }
  return array;
}

void expect_indexed(const PeriodicSignals& s) {
  for (std::size_t n = 0; n < s.samples; ++n)
    for (std::size_t c = 0; c < s.channels; ++c)
      for (std::size_t r = 0; r < s.realisations; ++r)
        for (std::size_t p = 0; p < s.periods; ++p)
          ASSERT_EQ(s(n, c, r, p), static_cast<double>(1000 * n + 100 * c + 10 * r + p))
              << n << " " << c << " " << r << " " << p;
}

TEST(NumpyArrangePeriodic, PutsEveryValueWhereItsIndexSays) {
  const PeriodicSignals s = arrange_periodic(indexed_array("ncrp", {5, 3, 4, 2}),
                                             "N,channel,realisation,period", "u.npy");
  EXPECT_EQ(s.samples, 5u);
  EXPECT_EQ(s.channels, 3u);
  EXPECT_EQ(s.realisations, 4u);
  EXPECT_EQ(s.periods, 2u);
  ASSERT_EQ(s.values.size(), 120u);
  expect_indexed(s);
  // Realisation r is one contiguous record: period 0's samples, then period 1's.
  EXPECT_EQ(s.values[(1 * 2 * 5 + 5) * 3 + 2], 1000 * 0 + 100 * 2 + 10 * 1 + 1);
}

TEST(NumpyArrangePeriodic, FollowsAnyOrderOfTheAxes) {
  const PeriodicSignals s = arrange_periodic(indexed_array("prnc", {2, 3, 4, 2}),
                                             " period , realization,N,channel ", "u.npy");
  EXPECT_EQ(s.samples, 4u);
  EXPECT_EQ(s.channels, 2u);
  EXPECT_EQ(s.realisations, 3u);
  EXPECT_EQ(s.periods, 2u);
  expect_indexed(s);
}

TEST(NumpyArrangePeriodic, GivesMissingAxesLengthOne) {
  const PeriodicSignals a = arrange_periodic(indexed_array("nc", {6, 2}), "N,channel", "y.npy");
  EXPECT_EQ(a.samples, 6u);
  EXPECT_EQ(a.channels, 2u);
  EXPECT_EQ(a.realisations, 1u);
  EXPECT_EQ(a.periods, 1u);
  expect_indexed(a);
  const PeriodicSignals b = arrange_periodic(indexed_array("pn", {3, 4}), "period,N", "y.npy");
  EXPECT_EQ(b.channels, 1u);
  EXPECT_EQ(b.periods, 3u);
  expect_indexed(b);
  const PeriodicSignals c = arrange_periodic(indexed_array("r", {3}), "realisation", "y.npy");
  EXPECT_EQ(c.samples, 1u);
  EXPECT_EQ(c.realisations, 3u);
  expect_indexed(c);
}

TEST(NumpyArrangePeriodic, RefusesLayoutsThatDoNotFit) {
  const NumpyArray a = indexed_array("nc", {4, 2});
  EXPECT_HYST_ERROR(arrange_periodic(a, "N,chanel", "u.npy"),
                    "u.npy: layout 'N,chanel': unknown axis name 'chanel' (known: N, channel, "
                    "realisation, period)");
  EXPECT_HYST_ERROR(arrange_periodic(a, "N,,channel", "u.npy"),
                    "u.npy: layout 'N,,channel': an empty axis name '' (known:");
  EXPECT_HYST_ERROR(arrange_periodic(a, "N,N", "u.npy"),
                    "u.npy: layout 'N,N': 'N' names the same axis as 'N' before it");
  EXPECT_HYST_ERROR(
      arrange_periodic(indexed_array("nrc", {4, 2, 2}), "N,realisation,realization", "u.npy"),
      "'realization' names the same axis as 'realisation' before it");
  EXPECT_HYST_ERROR(arrange_periodic(a, "N,channel,realisation,period", "u.npy"),
                    "u.npy: layout 'N,channel,realisation,period': 4 axes for an array of 2 "
                    "(shape (4, 2))");
  EXPECT_HYST_ERROR(arrange_periodic(NumpyArray{.shape = {4, 0}, .values = {}}, "N,channel", "u"),
                    "u: layout 'N,channel': the axis 'channel' (axis 1 of the shape (4, 0)) is "
                    "empty");
  EXPECT_HYST_ERROR(
      arrange_periodic(NumpyArray{.shape = {2, 2}, .values = {1, 2, 3}}, "N,channel", "u"),
      "u: the array has 3 values, fewer than its shape (2, 2) holds");
  EXPECT_HYST_ERROR(arrange_periodic(NumpyArray{.shape = {2}, .values = {1, 2, 3}}, "N", "u"),
                    "u: the array has 3 values but its shape (2,) holds 2");
}

}  // namespace numpy_test
}  // namespace
}  // namespace hyst::io
