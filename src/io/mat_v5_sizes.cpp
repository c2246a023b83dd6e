#include "mat_v5_sizes.hpp"

#include <cstdint>
#include <fstream>
#include <string>

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

}  // namespace

void check_mat_v5_element_sizes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return;  // matio reports it
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(in.tellg());
  if (size < kHeaderBytes) return;
  char header[kHeaderBytes];
  in.seekg(0);
  in.read(header, kHeaderBytes);
  if (!in) return;
  // Bytes 124..125: version 0x0100 (v5; 0x0200 is v7.3/HDF5); 126..127: "IM" when the file's byte
  // order is little-endian, "MI" when big-endian.
  const bool little = header[126] == 'I' && header[127] == 'M';
  const bool big = header[126] == 'M' && header[127] == 'I';
  if (!little && !big) return;
  const auto first = static_cast<unsigned char>(header[little ? 125 : 124]);
  const auto second = static_cast<unsigned char>(header[little ? 124 : 125]);
  if (first != 0x01 || second != 0x00) return;
  V5Walker(in, path, big).walk(kHeaderBytes, size, 0, true);
}

}  // namespace hyst::io::detail
