#include "mat_sizes.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::io::detail {
namespace {

constexpr std::uint64_t kHeaderBytes = 128;
constexpr std::uint32_t kMatrix = 14;     // miMATRIX: sub-elements follow
constexpr int kMatrixHeaderElements = 3;  // array flags, dimensions, name
constexpr int kMaxNesting = 32;           // cells of cells of ...: deeper is not a real file

class V5Walker {
 public:
  V5Walker(std::ifstream& in, const std::filesystem::path& path, bool swap)
      : in_(in), path_(path), swap_(swap) {}

  //! The elements in [begin, end), each fitting inside it; sub-elements of matrices too.
  //! Returns the number of elements found.
  int walk(std::uint64_t begin, std::uint64_t end, int depth, bool top_level) {
    if (depth > kMaxNesting) fail("matrices nested too deep");
    int count = 0;
    std::uint64_t position = begin;
    while (position + 8 <= end) {
      const std::uint32_t type = read_u32(position);
      const std::uint32_t bytes = read_u32(position + 4);
      ++count;
      if ((type >> 16) != 0) {  // small element: type and size in 4 bytes, data in the other 4
        position += 8;
        continue;
      }
      const std::uint64_t left = end - position - 8;
      if (bytes > left) {
        fail(fmt::format("the element at byte {} claims {} bytes but {} has {} left", position,
                         bytes, top_level ? "the file" : "its container", left));
      }
      // A matrix starts with its flags, dimensions and name (an empty one has no bytes at all);
      // matio reads those three even when they lie beyond the matrix.
      if (type == kMatrix && bytes > 0 &&
          walk(position + 8, position + 8 + bytes, depth + 1, false) < kMatrixHeaderElements) {
        fail(fmt::format("the matrix at byte {} ({} bytes) is too short for its header", position,
                         bytes));
      }
      // Sub-elements are padded to 8 bytes; top-level ones (compressed ones) need not be.
      const std::uint64_t padded = top_level ? bytes : (bytes + 7) / 8 * 8;
      position += 8 + padded;
    }
    return count;
  }

 private:
  std::uint32_t read_u32(std::uint64_t position) {
    unsigned char b[4] = {};
    in_.seekg(static_cast<std::streamoff>(position));
    in_.read(reinterpret_cast<char*>(b), 4);
    if (!in_) fail(fmt::format("cannot read byte {}", position));
    return swap_ ? (std::uint32_t{b[0]} << 24 | std::uint32_t{b[1]} << 16 |
                    std::uint32_t{b[2]} << 8 | b[3])
                 : (std::uint32_t{b[3]} << 24 | std::uint32_t{b[2]} << 16 |
                    std::uint32_t{b[1]} << 8 | b[0]);
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(fmt::format("{}: not a valid MAT file: {}", path_.string(), what));
  }

  std::ifstream& in_;
  const std::filesystem::path& path_;
  bool swap_;
};

constexpr std::string_view kNoV4Type = "no v4 type at the start";

//! The records of a v4 file: a 20-byte header (type, rows, columns, imaginary flag, name length),
//! the name, then rows x columns values (twice for complex ones). Returns an error text or "".
std::string v4_problem(std::ifstream& in, std::uint64_t size) {
  std::uint64_t position = 0;
  while (position < size) {
    if (size - position < 20) return fmt::format("a record header at byte {} is cut", position);
    unsigned char raw[20];
    in.seekg(static_cast<std::streamoff>(position));
    in.read(reinterpret_cast<char*>(raw), 20);
    if (!in) return fmt::format("cannot read byte {}", position);
    const auto word = [&](int k, bool big) {
      const unsigned char* b = raw + 4 * k;
      return big ? (std::uint32_t{b[0]} << 24 | std::uint32_t{b[1]} << 16 |
                    std::uint32_t{b[2]} << 8 | b[3])
                 : (std::uint32_t{b[3]} << 24 | std::uint32_t{b[2]} << 16 |
                    std::uint32_t{b[1]} << 8 | b[0]);
    };
    // type = 1000 M + 100 O + 10 P + T: machine 0..4, O = 0, precision 0..5, kind 0..2; its
    // machine digit gives the byte order the type itself is written in.
    const auto valid_type = [](std::uint32_t type) {
      return type < 5000 && (type / 100) % 10 == 0 && (type / 10) % 10 <= 5 && type % 10 <= 2;
    };
    bool big = false;
    if (!valid_type(word(0, false))) {
      big = true;
      if (!valid_type(word(0, true))) {
        return position == 0 ? std::string(kNoV4Type)
                             : fmt::format("the record at byte {} has no valid v4 type", position);
      }
    }
    static constexpr std::uint64_t kPrecisionBytes[] = {8, 4, 4, 2, 2, 1};
    const std::uint64_t type = word(0, big), rows = word(1, big), columns = word(2, big);
    const std::uint64_t imaginary = word(3, big), name_length = word(4, big);
    const std::uint64_t left = size - position - 20;
    const std::uint64_t cells = rows * columns;  // below 2^64: both are 32-bit
    const std::uint64_t values = cells > left ? left + 1 : cells * (imaginary != 0 ? 2 : 1);
    if (imaginary > 1 || name_length > left ||
        values > (left - name_length) / kPrecisionBytes[(type / 10) % 10]) {
      return fmt::format("the record at byte {} claims more than the {} bytes after it", position,
                         left);
    }
    position += 20 + name_length + values * kPrecisionBytes[(type / 10) % 10];
  }
  return {};
}

}  // namespace

void check_mat_sizes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return;  // matio reports it
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(in.tellg());
  char header[kHeaderBytes] = {};
  in.seekg(0);
  in.read(header, static_cast<std::streamsize>(std::min<std::uint64_t>(size, kHeaderBytes)));
  in.clear();
  // v7.3 files are HDF5 files with a 512-byte user block: HDF5 judges them.
  if (size >= 520) {
    char signature[8] = {};
    in.seekg(512);
    in.read(signature, 8);
    in.clear();
    if (std::string_view(signature, 8) == std::string_view("\x89HDF\r\n\x1a\n", 8)) return;
  }
  // v5: bytes 124..125 version 0x0100, 126..127 "IM" when the file's byte order is
  // little-endian, "MI" when big-endian.
  const bool little = size >= kHeaderBytes && header[126] == 'I' && header[127] == 'M';
  const bool big = size >= kHeaderBytes && header[126] == 'M' && header[127] == 'I';
  if (little || big) {
    const auto first = static_cast<unsigned char>(header[little ? 125 : 124]);
    const auto second = static_cast<unsigned char>(header[little ? 124 : 125]);
    if (first == 0x01 && second == 0x00) {
      V5Walker(in, path, big).walk(kHeaderBytes, size, 0, true);
      return;
    }
  }
  // Anything else is tried as v4 by matio.
  if (const auto problem = v4_problem(in, size); !problem.empty()) {
    if (problem == kNoV4Type) {
      throw Error(
          fmt::format("{}: not a MAT file (MATLAB v4, v5 or v7.3 expected)", path.string()));
    }
    throw Error(fmt::format("{}: not a valid MAT file: read as v4, {}", path.string(), problem));
  }
}

}  // namespace hyst::io::detail
