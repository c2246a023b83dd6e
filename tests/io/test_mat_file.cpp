#include "hyst/io/mat_file.hpp"

#include <matio.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/expect_error.hpp"

namespace hyst::io {
namespace {

namespace fs = std::filesystem;

using Variables = std::vector<std::pair<std::string, std::vector<double>>>;

// A fresh folder per test, removed afterwards.
class MatFile : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = fmt::format("hyst_test_mat_{}_{}_{}", static_cast<long long>(::getpid()),
                                   info->test_suite_name(), info->name());
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests have '/' in names
    folder_ = fs::temp_directory_path() / name;
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path file(const std::string& name) const { return folder_ / name; }
  std::vector<std::string> folder_entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  // Writes one variable with matio directly (to build what write_mat_vectors() never writes).
  static void write_raw(const fs::path& path, matvar_t* variable, mat_ft version = MAT_FT_MAT5) {
    ASSERT_NE(variable, nullptr);
    mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, version);
    ASSERT_NE(mat, nullptr);
    EXPECT_EQ(Mat_VarWrite(mat, variable, MAT_COMPRESSION_NONE), 0);
    Mat_VarFree(variable);
    Mat_Close(mat);
  }

  fs::path folder_;
};

void expect_identical(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a[k]), std::bit_cast<std::uint64_t>(b[k]))
        << "sample " << k << ": " << a[k] << " vs " << b[k];
  }
}

Variables example_variables() {
  std::mt19937_64 draw(12345);
  std::normal_distribution<double> normal(0.0, 1e3);
  std::vector<double> noise(1000);
  for (double& x : noise)
    x = normal(draw);
  return {{"voltage", {1.5, -2.0, 1e-300, 1e300, 0.1, -0.0, 5e-324}},
          {"empty_one", {}},
          {"Displacement_19kv", noise},
          {"a", {42.0}}};
}

class MatFileVersions : public MatFile, public testing::WithParamInterface<MatVersion> {};

TEST_P(MatFileVersions, WriteReadRoundTripIsExact) {
  const fs::path path = file("data.mat");
  const Variables variables = example_variables();
  write_mat_vectors(path, variables, GetParam());

  auto names = list_mat_variables(path);
  std::vector<std::string> expected;
  for (const auto& [name, values] : variables)
    expected.push_back(name);
  if (GetParam() == MatVersion::v5) {
    EXPECT_EQ(names, expected) << "file order";
  }
  std::sort(names.begin(), names.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names, expected);
  for (const auto& [name, values] : variables) {
    SCOPED_TRACE(name);
    expect_identical(read_mat_vector(path, name), values);
  }
  EXPECT_EQ(folder_entries(), std::vector<std::string>{"data.mat"}) << "no temporary file left";
}

TEST_P(MatFileVersions, ReplacesAnExistingFileKeepingItsPermissions) {
  const fs::path path = file("data.mat");
  write_mat_vectors(path, {{"old", {1, 2, 3}}}, GetParam());
  ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
  write_mat_vectors(path, {{"new", {4, 5}}}, GetParam());
  EXPECT_EQ(list_mat_variables(path), std::vector<std::string>{"new"});
  expect_identical(read_mat_vector(path, "new"), {4, 5});
  struct stat status {};
  ASSERT_EQ(::stat(path.c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 07777, 0640u);
  EXPECT_EQ(folder_entries(), std::vector<std::string>{"data.mat"});
}

TEST_P(MatFileVersions, ReadsARowVectorAndRejectsAMatrix) {
  const fs::path row = file("row.mat");
  double data[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  const mat_ft version = GetParam() == MatVersion::v7_3 ? MAT_FT_MAT73 : MAT_FT_MAT5;
  std::size_t row_dims[2] = {1, 4};
  write_raw(row, Mat_VarCreate("r", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, row_dims, data, 0), version);
  expect_identical(read_mat_vector(row, "r"), {1, 2, 3, 4});

  const fs::path matrix = file("matrix.mat");
  std::size_t matrix_dims[2] = {3, 4};
  write_raw(matrix, Mat_VarCreate("c", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, matrix_dims, data, 0),
            version);
  EXPECT_HYST_ERROR(read_mat_vector(matrix, "c"),
                    matrix.string() + ": variable 'c' is a 3x4 matrix, expected a vector");
}

INSTANTIATE_TEST_SUITE_P(AllVersions, MatFileVersions,
                         testing::Values(MatVersion::v5, MatVersion::v7_3), [](const auto& info) {
                           return info.param == MatVersion::v5 ? "v5" : "v73";
                         });

TEST_F(MatFile, ReadsNumericClassesAsDouble) {
  const fs::path path = file("classes.mat");
  mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5);
  ASSERT_NE(mat, nullptr);
  std::size_t dims[2] = {3, 1};
  float singles[3] = {0.5f, -1.25f, 3.0f};
  std::int16_t int16s[3] = {-32768, 0, 32767};
  std::uint8_t bytes[3] = {0, 1, 255};
  std::uint64_t big[3] = {0, 1, 1ull << 53};
  std::uint8_t logical[3] = {1, 0, 1};
  matvar_t* variables[] = {
      Mat_VarCreate("s", MAT_C_SINGLE, MAT_T_SINGLE, 2, dims, singles, 0),
      Mat_VarCreate("i", MAT_C_INT16, MAT_T_INT16, 2, dims, int16s, 0),
      Mat_VarCreate("u", MAT_C_UINT8, MAT_T_UINT8, 2, dims, bytes, 0),
      Mat_VarCreate("big", MAT_C_UINT64, MAT_T_UINT64, 2, dims, big, 0),
      Mat_VarCreate("flag", MAT_C_UINT8, MAT_T_UINT8, 2, dims, logical, MAT_F_LOGICAL),
  };
  for (matvar_t* variable : variables) {
    ASSERT_NE(variable, nullptr);
    EXPECT_EQ(Mat_VarWrite(mat, variable, MAT_COMPRESSION_ZLIB), 0);
    Mat_VarFree(variable);
  }
  Mat_Close(mat);
  expect_identical(read_mat_vector(path, "s"), {0.5, -1.25, 3.0});
  expect_identical(read_mat_vector(path, "i"), {-32768, 0, 32767});
  expect_identical(read_mat_vector(path, "u"), {0, 1, 255});
  expect_identical(read_mat_vector(path, "big"), {0, 1, 9007199254740992.0});
  expect_identical(read_mat_vector(path, "flag"), {1, 0, 1});
}

TEST_F(MatFile, ReadsAnEmptyVariableAsAnEmptyVector) {
  const fs::path path = file("empty.mat");
  std::size_t dims[2] = {0, 0};
  write_raw(path, Mat_VarCreate("e", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, nullptr, 0));
  EXPECT_TRUE(read_mat_vector(path, "e").empty());
}

TEST_F(MatFile, RejectsWhatIsNotARealVector) {
  double data[24] = {};
  const fs::path cube = file("cube.mat");
  std::size_t cube_dims[3] = {2, 3, 4};
  write_raw(cube, Mat_VarCreate("a", MAT_C_DOUBLE, MAT_T_DOUBLE, 3, cube_dims, data, 0));
  EXPECT_HYST_ERROR(read_mat_vector(cube, "a"),
                    cube.string() + ": variable 'a' is a 2x3x4 array, expected a vector");

  const fs::path complex = file("complex.mat");
  double re[3] = {1, 2, 3}, im[3] = {0, 1, 0};
  mat_complex_split_t z{re, im};
  std::size_t dims[2] = {3, 1};
  write_raw(complex, Mat_VarCreate("z", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, &z, MAT_F_COMPLEX));
  EXPECT_HYST_ERROR(read_mat_vector(complex, "z"),
                    complex.string() + ": variable 'z' is complex, expected a real vector");

  const fs::path text = file("char.mat");
  char hello[] = "hello";
  std::size_t char_dims[2] = {1, 5};
  write_raw(text, Mat_VarCreate("t", MAT_C_CHAR, MAT_T_UINT8, 2, char_dims, hello, 0));
  EXPECT_HYST_ERROR(read_mat_vector(text, "t"),
                    text.string() +
                        ": variable 't' is a char array, expected a real numeric "
                        "vector");

  const fs::path cell = file("cell.mat");
  std::size_t one[2] = {1, 1};
  matvar_t* cell_variable = Mat_VarCreate("c", MAT_C_CELL, MAT_T_CELL, 2, one, nullptr, 0);
  Mat_VarSetCell(cell_variable, 0,
                 Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, re, 0));
  write_raw(cell, cell_variable);
  EXPECT_HYST_ERROR(read_mat_vector(cell, "c"),
                    cell.string() +
                        ": variable 'c' is a cell array, expected a real numeric "
                        "vector");

  const fs::path structure = file("struct.mat");
  const char* fields[] = {"x", nullptr};  // null-terminated
  matvar_t* struct_variable = Mat_VarCreateStruct2("s", 2, one, fields);
  Mat_VarSetStructFieldByName(struct_variable, "x", 0,
                              Mat_VarCreate("x", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, re, 0));
  write_raw(structure, struct_variable);
  EXPECT_HYST_ERROR(read_mat_vector(structure, "s"),
                    structure.string() +
                        ": variable 's' is a struct, expected a real numeric "
                        "vector");

  const fs::path nan = file("nan.mat");
  double samples[4] = {1, 2, std::numeric_limits<double>::quiet_NaN(), 4};
  std::size_t nan_dims[2] = {4, 1};
  write_raw(nan, Mat_VarCreate("n", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, nan_dims, samples, 0));
  EXPECT_HYST_ERROR(read_mat_vector(nan, "n"),
                    nan.string() + ": variable 'n': n[2] = nan is not finite");
}

TEST_F(MatFile, NamesTheMissingVariableAndTheOthers) {
  const fs::path path = file("data.mat");
  write_mat_vectors(path, {{"a", {1}}, {"b", {2}}});
  EXPECT_HYST_ERROR(read_mat_vector(path, "x"),
                    path.string() + ": no variable 'x' (variables: a, b)");
  EXPECT_HYST_ERROR(read_mat_vector(path, "A"), "no variable 'A'");
}

TEST_F(MatFile, RejectsFilesThatAreNotMatFiles) {
  const fs::path missing = file("missing.mat");
  EXPECT_HYST_ERROR(list_mat_variables(missing),
                    "cannot open '" + missing.string() + "': No such file or directory");
  EXPECT_HYST_ERROR(read_mat_vector(missing, "x"), "cannot open '" + missing.string() + "'");
  EXPECT_HYST_ERROR(list_mat_variables(folder_),
                    "cannot open '" + folder_.string() + "': it is a folder");

  const fs::path empty = file("empty.mat");
  std::ofstream(empty).close();
  EXPECT_HYST_ERROR(list_mat_variables(empty),
                    empty.string() + ": not a MAT file (the file is empty)");

  const fs::path text = file("text.mat");
  std::ofstream(text) << "t,v,y\n0,1,2\n" << std::string(300, 'x') << "\n";
  EXPECT_HYST_ERROR(read_mat_vector(text, "v"),
                    text.string() + ": not a MAT file (MATLAB v4, v5 or v7.3 expected)");
}

TEST_F(MatFile, RejectsInvalidVariablesToWrite) {
  const fs::path path = file("out.mat");
  const std::string prefix = "cannot write '" + path.string() + "': ";
  EXPECT_HYST_ERROR(write_mat_vectors(path, {}), prefix + "no variables given");
  for (const std::string& name :
       std::vector<std::string>{"", "1x", "a b", "_x", "x-y", std::string(64, 'a')}) {
    EXPECT_HYST_ERROR(write_mat_vectors(path, {{name, {1}}}),
                      prefix + "variable name '" + name + "' is not a valid MATLAB name");
  }
  write_mat_vectors(path, {{std::string(63, 'a'), {1}}});  // the longest valid name
  fs::remove(path);
  EXPECT_HYST_ERROR(write_mat_vectors(path, {{"a", {1}}, {"b", {2}}, {"a", {3}}}),
                    prefix + "variable name 'a' is given twice");
  EXPECT_HYST_ERROR(
      write_mat_vectors(path, {{"a", {1}}, {"y", {0, std::numeric_limits<double>::infinity()}}}),
      prefix + "variable 'y': y[1] = inf is not finite");
  EXPECT_FALSE(fs::exists(path)) << "nothing written on error";

  const fs::path plain = file("plain.txt");
  std::ofstream(plain) << "x";
  EXPECT_HYST_ERROR(write_mat_vectors(plain / "out.mat", {{"a", {1}}}),
                    "cannot write '" + (plain / "out.mat").string() + "': '" + plain.string() +
                        "' is not a folder");
  fs::remove(plain);
  EXPECT_HYST_ERROR(write_mat_vectors(folder_ / "..", {{"a", {1}}}),
                    "the path does not name a file");
  EXPECT_TRUE(folder_entries().empty());
}

TEST(MatVersion, ConvertsToAndFromText) {
  EXPECT_EQ(to_string(MatVersion::v5), "v5");
  EXPECT_EQ(to_string(MatVersion::v7_3), "v7.3");
  EXPECT_EQ(mat_version_from_string("v5"), MatVersion::v5);
  EXPECT_EQ(mat_version_from_string("v7.3"), MatVersion::v7_3);
  EXPECT_HYST_ERROR(mat_version_from_string("v7"),
                    "unknown MAT file version 'v7' (expected v5 or v7.3)");
}

// The measured piezo loops (PROVENANCE.md): ten 401 x 1 double vectors, MATLAB v5.
TEST(MatFileMeasuredData, ReadsThePiezoLoops) {
  const fs::path path = HYST_SHARED_DATA_DIR "/piezo_pzt_aixacct_butterfly/MeasurementData.mat";
  auto names = list_mat_variables(path);
  std::sort(names.begin(), names.end());
  const std::vector<std::string> expected{
      "Displacement_08kv", "Displacement_11kv", "Displacement_15kv", "Displacement_19kv",
      "Displacement_1kv",  "Vplus_08kv",        "Vplus_11kv",        "Vplus_15kv",
      "Vplus_19kv",        "Vplus_1kv"};
  EXPECT_EQ(names, expected);
  for (const auto& name : expected) {
    SCOPED_TRACE(name);
    const auto values = read_mat_vector(path, name);
    EXPECT_EQ(values.size(), 401u);
    if (name.starts_with("Displacement")) {
      EXPECT_EQ(values.front(), 0.0) << "zeroed at the start";
    }
  }
  // Ranges stated in PROVENANCE.md: peaks about +-1895 V, displacement -162..1318 nm at 19kv.
  const auto voltage = read_mat_vector(path, "Vplus_19kv");
  const auto displacement = read_mat_vector(path, "Displacement_19kv");
  EXPECT_NEAR(*std::max_element(voltage.begin(), voltage.end()), 1895, 1);
  EXPECT_NEAR(*std::min_element(voltage.begin(), voltage.end()), -1890, 1);
  EXPECT_NEAR(*std::max_element(displacement.begin(), displacement.end()), 1318, 1);
  EXPECT_NEAR(*std::min_element(displacement.begin(), displacement.end()), -162, 1);
}

// Sizes a file states must fit in the file: matio trusts them and allocates what they claim
// (inputs found by fuzz/fuzz_mat_file; fuzz/corpus/fuzz_mat_file/regression_*).
TEST_F(MatFile, RejectsSizesLargerThanTheFile) {
  // A v4 file written by hand: type 0 (little-endian doubles), 3 x 1, real, name "v".
  const auto v4_file = [&](const fs::path& path, std::uint32_t name_length) {
    std::ofstream out(path, std::ios::binary);
    const std::uint32_t header[5] = {0, 3, 1, 0, name_length};
    const double values[3] = {0.5, -1.0, 2.0};
    out.write(reinterpret_cast<const char*>(header), sizeof header);
    out.write("v", 2);
    out.write(reinterpret_cast<const char*>(values), sizeof values);
  };
  const fs::path good = file("good_v4.mat");
  v4_file(good, 2);
  EXPECT_EQ(read_mat_vector(good, "v"), (std::vector<double>{0.5, -1.0, 2.0}));
  const fs::path bad = file("bad_v4.mat");
  v4_file(bad, 1'700'000'000);
  EXPECT_HYST_ERROR(list_mat_variables(bad),
                    bad.string() +
                        ": not a valid MAT file: read as v4, the record at byte 0 claims more than "
                        "the 26 bytes after it");

  // The matrix at byte 128 holds 80 bytes after its 8-byte tag, so it ends at 216; its dimensions
  // tag at byte 152 leaves 216 - 160 = 56 bytes, but claims 0x54414d08 = 1413565704.
  const fs::path v5 = fs::path(HYST_TEST_DATA_DIR) / "bad" / "corrupt_element_size.mat";
  EXPECT_HYST_ERROR(list_mat_variables(v5),
                    "not a valid MAT file: the element at byte 152 claims 1413565704 bytes but "
                    "its container has 56 left");
}

// v5 files built byte by byte (little-endian): a 128-byte header, then elements.
std::string le32(std::uint32_t value) {
  std::string bytes(4, '\0');
  for (int k = 0; k < 4; ++k)
    bytes[k] = static_cast<char>((value >> (8 * k)) & 0xff);
  return bytes;
}
std::string element(std::uint32_t type, const std::string& data) {
  std::string padded = data;
  padded.resize((data.size() + 7) / 8 * 8, '\0');
  return le32(type) + le32(static_cast<std::uint32_t>(data.size())) + padded;
}
// A 1 x 1 double matrix named `name`, its dimensions element `dimensions` as given.
std::string scalar_matrix(const std::string& dimensions, const std::string& name) {
  const double value = 0.5;
  const std::string flags = element(6, le32(6) + le32(0));  // miUINT32; class double
  const std::string data = element(9, std::string(reinterpret_cast<const char*>(&value), 8));
  return element(14, flags + dimensions + name + data);
}
void write_v5(const fs::path& path, const std::string& elements) {
  std::string header(116, ' ');
  header.replace(0, 19, "MATLAB 5.0 MAT-file");
  header += std::string(8, '\0') + std::string("\x00\x01IM", 4);  // version 0x0100
  std::ofstream(path, std::ios::binary) << header << elements;
}
std::string deflated(const std::string& bytes) {
  uLongf size = compressBound(bytes.size());
  std::string out(size, '\0');
  EXPECT_EQ(compress(reinterpret_cast<Bytef*>(out.data()), &size,
                     reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()),
            Z_OK);
  out.resize(size);
  return le32(15) + le32(static_cast<std::uint32_t>(out.size())) + out;  // miCOMPRESSED
}

// The three header elements of a matrix must be what the format defines: matio reads them at
// fixed places whatever their tags say (input found by fuzz/fuzz_mat_file: a 1-byte dimensions
// element, read by matio as rank 0 with no padding, so that it took the next 8 bytes as a name tag
// claiming 1.98 GB and allocated that).
TEST_F(MatFile, RejectsMatrixHeadersOtherThanTheFormatDefines) {
  const std::string dimensions = element(5, le32(1) + le32(1));  // miINT32, 1 x 1
  const std::string name = element(1, "v");
  const fs::path good = file("good.mat");
  write_v5(good, scalar_matrix(dimensions, name));
  EXPECT_EQ(read_mat_vector(good, "v"), std::vector<double>{0.5});

  const fs::path one_byte = file("one_byte_dimensions.mat");
  write_v5(one_byte, scalar_matrix(element(5, "\x01"), name));
  EXPECT_HYST_ERROR(list_mat_variables(one_byte),
                    "not a valid MAT file: the matrix at byte 128 has no valid dimensions (int32, "
                    "at least 2 of them) at byte 152");
  const fs::path no_flags = file("no_flags.mat");
  write_v5(no_flags, element(14, dimensions + dimensions + name));
  EXPECT_HYST_ERROR(list_mat_variables(no_flags),
                    "not a valid MAT file: the matrix at byte 128 does not start with 8 bytes of "
                    "array flags");
  const fs::path no_name = file("no_name.mat");
  write_v5(no_name, scalar_matrix(dimensions, element(9, "v")));
  EXPECT_HYST_ERROR(list_mat_variables(no_name),
                    "not a valid MAT file: the matrix at byte 128 has no name (int8 characters) at "
                    "byte 168");
}

// matio allocates a pointer per cell before reading the cells (input found by fuzz/fuzz_mat_file:
// a 300-byte cell array claiming 3 x 3107953306 cells, i.e. 74 GB of pointers).
TEST_F(MatFile, RejectsCellArraysClaimingMoreCellsThanTheyHold) {
  const std::string flags = element(6, le32(1) + le32(0));  // class 1: cell array
  const std::string cells = element(14, "");                // one empty matrix as its only cell
  const fs::path good = file("one_cell.mat");
  write_v5(good, element(14, flags + element(5, le32(1) + le32(1)) + element(1, "c") + cells));
  EXPECT_NO_THROW(list_mat_variables(good));
  // A variable without header elements: matio reads them from whatever follows.
  const fs::path bare = file("bare_variable.mat");
  write_v5(bare, element(14, "") + element(6, le32(6) + le32(0)));
  EXPECT_HYST_ERROR(list_mat_variables(bare),
                    "not a valid MAT file: the variable at byte 128 is an empty matrix element, "
                    "without the array flags, dimensions and name every variable has");
  // An HDF5 signature at byte 512 does not make a v5 file an HDF5 file: matio reads it as v5.
  std::string padding = element(6, std::string(512 - 128 - 8, '\0'));
  padding += std::string("\x89HDF\r\n\x1a\n", 8);
  const fs::path disguised = file("disguised.mat");
  write_v5(disguised, padding + element(14, ""));
  EXPECT_HYST_ERROR(list_mat_variables(disguised),
                    "not a valid MAT file: the variable at byte 520 is an empty matrix element");
  const fs::path huge = file("huge_cell.mat");
  write_v5(huge, element(14, flags + element(5, le32(3) + le32(3107953306u)) + element(1, "c")));
  // The dimensions element starts at byte 152 and the matrix ends at 136 + 48 = 184.
  EXPECT_HYST_ERROR(list_mat_variables(huge),
                    "not a valid MAT file: the matrix at byte 128 claims 9323859918 elements, more "
                    "than the 32 bytes left in it can hold");
  // The same for the other classes matio reads element by element (16: function handle).
  const fs::path function = file("huge_function.mat");
  write_v5(function, element(14, element(6, le32(16) + le32(0)) +
                                     element(5, le32(3) + le32(4253456185u)) + element(1, "f")));
  EXPECT_HYST_ERROR(list_mat_variables(function),
                    "not a valid MAT file: the matrix at byte 128 claims 12760368555 elements");
}

// A compressed element is inflated and checked like the file: a few bytes of zlib data can
// claim gigabytes.
TEST_F(MatFile, ChecksTheElementInsideACompressedOne) {
  const std::string dimensions = element(5, le32(1) + le32(1));
  const fs::path good = file("good_compressed.mat");
  write_v5(good, deflated(scalar_matrix(dimensions, element(1, "v"))));
  EXPECT_EQ(read_mat_vector(good, "v"), std::vector<double>{0.5});

  // The name tag claims 0x76000000 bytes; the matrix holds 56 after the name tag.
  const std::string huge_name = le32(1) + le32(0x76000000) + std::string(8, 'v');
  const fs::path bomb = file("huge_name_compressed.mat");
  write_v5(bomb, deflated(scalar_matrix(dimensions, huge_name)));
  EXPECT_HYST_ERROR(list_mat_variables(bomb),
                    "not a valid MAT file: in the compressed element at byte 128, the element at "
                    "byte 40 claims 1979711488 bytes but its container has 24 left");

  const std::string compressed = deflated(scalar_matrix(dimensions, element(1, "v")));
  const fs::path cut = file("cut_compressed.mat");
  std::string cut_element = compressed.substr(0, compressed.size() - 6);
  cut_element.replace(4, 4, le32(static_cast<std::uint32_t>(cut_element.size() - 8)));
  write_v5(cut, cut_element);
  EXPECT_HYST_ERROR(list_mat_variables(cut),
                    "not a valid MAT file: the compressed element at byte 128 is cut");
  const fs::path garbage = file("garbage_compressed.mat");
  write_v5(garbage, le32(15) + le32(16) + std::string(16, '\x55'));
  EXPECT_HYST_ERROR(list_mat_variables(garbage),
                    "not a valid MAT file: the compressed element at byte 128 is not valid zlib "
                    "data");
}

}  // namespace
}  // namespace hyst::io
