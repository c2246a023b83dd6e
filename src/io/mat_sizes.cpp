#include "mat_sizes.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/io/limits.hpp"

namespace hyst::io::detail {
namespace {

constexpr std::uint64_t kHeaderBytes = 128;
constexpr std::uint32_t kInt8 = 1;         // miINT8: the name
constexpr std::uint32_t kInt32 = 5;        // miINT32: the dimensions
constexpr std::uint32_t kUint32 = 6;       // miUINT32: the array flags
constexpr std::uint32_t kMatrix = 14;      // miMATRIX: sub-elements follow
constexpr std::uint32_t kCompressed = 15;  // miCOMPRESSED: a zlib stream of one element
constexpr int kMaxNesting = 32;            // cells of cells of ...: deeper is not a real file
// A compressed element holds one variable: its data (at most limits::kMaxMatVariableBytes) and
// headers (names, dimensions, the elements of cells and structs); 1 MiB is room for those.
constexpr std::uint64_t kMaxInflatedElement = limits::kMaxMatVariableBytes + (1u << 20);

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw Error(fmt::format("{}: not a valid MAT file: {}", path.string(), what));
}

std::uint32_t decode_u32(const unsigned char* b, bool swap) {
  return swap ? (std::uint32_t{b[0]} << 24 | std::uint32_t{b[1]} << 16 | std::uint32_t{b[2]} << 8 |
                 b[3])
              : (std::uint32_t{b[3]} << 24 | std::uint32_t{b[2]} << 16 | std::uint32_t{b[1]} << 8 |
                 b[0]);
}

//! The file itself, read anywhere.
class FileBytes {
 public:
  FileBytes(std::ifstream& in, const std::filesystem::path& path) : in_(in), path_(path) {}

  void read(std::uint64_t position, unsigned char* out, std::size_t count) {
    in_.seekg(static_cast<std::streamoff>(position));
    in_.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(count));
    if (!in_) fail(path_, fmt::format("cannot read byte {}", position));
  }

 private:
  std::ifstream& in_;
  const std::filesystem::path& path_;
};

//! The zlib stream of a compressed element, inflated on demand. Reads must go forward (the walk
//! does), so nothing but a 64 kB window is kept, whatever the stream inflates to.
class InflatedBytes {
 public:
  InflatedBytes(FileBytes& file, std::uint64_t begin, std::uint64_t bytes,
                const std::filesystem::path& path, std::uint64_t element)
      : file_(file), next_in_(begin), in_left_(bytes), path_(path), element_(element) {
    if (inflateInit(&stream_) != Z_OK) fail(path_, "zlib cannot start");
  }
  ~InflatedBytes() { inflateEnd(&stream_); }
  InflatedBytes(const InflatedBytes&) = delete;
  InflatedBytes& operator=(const InflatedBytes&) = delete;

  //! Inflates the rest of the stream and returns its total size.
  std::uint64_t size() {
    while (more()) {
    }
    return window_begin_ + window_.size();
  }

  void read(std::uint64_t position, unsigned char* out, std::size_t count) {
    if (position < window_begin_) fail(path_, "compressed element read backwards");
    while (position + count > window_begin_ + window_.size()) {
      if (!more()) {
        fail(path_, fmt::format("the compressed element at byte {} inflates to fewer than {} bytes",
                                element_, position + count));
      }
    }
    std::copy_n(window_.begin() + static_cast<std::ptrdiff_t>(position - window_begin_), count,
                out);
  }

 private:
  //! Inflates the next chunk into the window, dropping what lies before the last 8 bytes.
  bool more() {
    if (finished_) return false;
    if (window_.size() > 8) {
      const auto drop = window_.size() - 8;
      window_.erase(window_.begin(), window_.begin() + static_cast<std::ptrdiff_t>(drop));
      window_begin_ += drop;
    }
    unsigned char output[1 << 16];
    stream_.next_out = output;
    stream_.avail_out = sizeof output;
    while (stream_.avail_out == sizeof output) {
      if (stream_.avail_in == 0 && in_left_ > 0) {
        const auto chunk =
            static_cast<std::size_t>(std::min<std::uint64_t>(in_left_, sizeof input_));
        file_.read(next_in_, input_, chunk);
        next_in_ += chunk;
        in_left_ -= chunk;
        stream_.next_in = input_;
        stream_.avail_in = static_cast<uInt>(chunk);
      }
      const int status = inflate(&stream_, Z_NO_FLUSH);
      if (status == Z_STREAM_END) {
        finished_ = true;
        break;
      }
      if (status == Z_BUF_ERROR && stream_.avail_in == 0 && in_left_ == 0) {
        fail(path_, fmt::format("the compressed element at byte {} is cut", element_));
      }
      if (status != Z_OK) {
        fail(path_,
             fmt::format("the compressed element at byte {} is not valid zlib data", element_));
      }
    }
    window_.insert(window_.end(), output, stream_.next_out);
    if (window_begin_ + window_.size() > kMaxInflatedElement) {
      fail(path_, fmt::format("the compressed element at byte {} inflates to more than {} bytes "
                              "(the limit of one variable is {} bytes of data)",
                              element_, kMaxInflatedElement, limits::kMaxMatVariableBytes));
    }
    return true;
  }

  FileBytes& file_;
  std::uint64_t next_in_;
  std::uint64_t in_left_;
  const std::filesystem::path& path_;
  std::uint64_t element_;
  z_stream stream_{};
  unsigned char input_[1 << 16] = {};
  std::vector<unsigned char> window_;
  std::uint64_t window_begin_ = 0;
  bool finished_ = false;
};

//! Checks the elements of a v5 file (or of one inflated compressed element) against the bytes
//! that contain them. Reads go forward only, so that a compressed element need not be inflated in
//! memory.
template <class Bytes>
class V5Walker {
 public:
  //! `where` starts each message ("" for the file, "in the compressed element at byte 128, "
  //! for the element inflated from it: positions then count from the inflated element's start).
  V5Walker(Bytes& bytes, const std::filesystem::path& path, bool swap, std::string where = {})
      : bytes_(bytes), path_(path), swap_(swap), where_(std::move(where)) {}

  //! The elements in [begin, end), each fitting inside it; sub-elements of matrices too. Returns
  //! the number of elements found. `on_compressed(position, bytes)` handles a compressed element.
  template <class OnCompressed>
  int walk(std::uint64_t begin, std::uint64_t end, int depth, bool top_level,
           OnCompressed&& on_compressed, std::uint64_t matrix = kNoMatrix) {
    if (depth > kMaxNesting) fail("matrices nested too deep");
    int count = 0;
    Shape shape;
    std::uint64_t position = begin;
    while (position + 8 <= end) {
      const std::uint32_t type = read_u32(position);
      const std::uint32_t bytes = read_u32(position + 4);
      if (matrix != kNoMatrix) check_matrix_header(matrix, count, position, type, bytes);
      ++count;
      if ((type >> 16) != 0) {  // small element: type and size in 4 bytes, data in the other 4
        if (matrix != kNoMatrix && count == 4) shape.field_name_length = bytes;
        position += 8;
        continue;
      }
      const std::uint64_t left = end - position - 8;
      if (bytes > left) {
        fail(fmt::format("the element at byte {} claims {} bytes but {} has {} left", position,
                         bytes, top_level ? "the file" : "its container", left));
      }
      if (matrix != kNoMatrix) check_matrix_size(matrix, count - 1, position, bytes, end, shape);
      // An empty matrix has no bytes at all (a cell may be one); any other starts with three
      // header elements, which matio reads even when they lie beyond the matrix - so a variable
      // (a top-level matrix) needs them.
      if (type == kMatrix && bytes == 0 && top_level) {
        fail(
            fmt::format("the variable at byte {} is an empty matrix element, without the array "
                        "flags, dimensions and name every variable has",
                        position));
      }
      if (type == kMatrix && bytes > 0 &&
          walk(position + 8, position + 8 + bytes, depth + 1, false, on_compressed, position) <
              kMatrixHeaderElements) {
        fail(fmt::format("the matrix at byte {} ({} bytes) is too short for its header", position,
                         bytes));
      }
      if (type == kCompressed && top_level) on_compressed(position, bytes);
      // Sub-elements are padded to 8 bytes; top-level ones (compressed ones) need not be.
      const std::uint64_t padded = top_level ? bytes : (bytes + 7) / 8 * 8;
      position += 8 + padded;
    }
    return count;
  }

 private:
  static constexpr std::uint64_t kNoMatrix = ~std::uint64_t{0};
  static constexpr int kMatrixHeaderElements = 3;
  static constexpr std::uint32_t kStruct = 2, kChar = 4, kUint64 = 15;  // array classes

  //! What a matrix's header says of its contents.
  struct Shape {
    std::uint32_t array_class = 0;
    double elements = 0.0;           //!< product of the dimensions
    double field_name_length = 0.0;  //!< structs: bytes per field name
  };

  //! matio allocates one pointer per cell of a cell array and per field of every struct element
  //! (and per element of the other non-numeric classes) before it reads them, so their count must
  //! fit in the matrix: each one is an element of at least 8 bytes.
  void check_matrix_size(std::uint64_t matrix, int index, std::uint64_t position,
                         std::uint32_t bytes, std::uint64_t end, Shape& shape) {
    const auto room = static_cast<double>(end - position);
    if (index == 0) shape.array_class = read_u32(position + 8) & 0xff;
    if (index == 1) {
      shape.elements = 1.0;
      for (std::uint32_t k = 0; k < bytes / 4; ++k)
        shape.elements *= read_u32(position + 8 + 4 * k);
      // Classes 4..15 (char, sparse and the numeric ones) hold plain data, whose size the data
      // element states; every other one (cell, struct, object, function, opaque, unknown) is
      // read element by element.
      const bool holds_matrices = shape.array_class < kChar || shape.array_class > kUint64;
      if (holds_matrices && shape.elements * 8.0 > room) {
        fail(
            fmt::format("the matrix at byte {} claims {:.0f} elements, more than the {} bytes "
                        "left in it can hold",
                        matrix, shape.elements, end - position));
      }
    }
    if (index == 3 && shape.array_class == kStruct && bytes >= 4) {
      shape.field_name_length = read_u32(position + 8);
    }
    if (index == 4 && shape.array_class == kStruct && shape.field_name_length > 0.0) {
      const double fields = std::floor(bytes / shape.field_name_length);
      if (shape.elements * fields * 8.0 > room) {
        fail(
            fmt::format("the struct at byte {} claims {:.0f} elements of {:.0f} fields, more "
                        "than the {} bytes left in it can hold",
                        matrix, shape.elements, fields, end - position));
      }
    }
  }

  //! Element `index` of the matrix at `matrix`: the array flags, dimensions and name must be what
  //! the format defines. matio reads them at fixed places whatever their tags say, so a
  //! dimensions element of, say, 1 byte (rank 0, no padding for matio) would shift the name tag
  //! matio reads off the one walked here.
  void check_matrix_header(std::uint64_t matrix, int index, std::uint64_t position,
                           std::uint32_t type, std::uint32_t bytes) const {
    if (index == 0 && (type != kUint32 || bytes != 8)) {
      fail(fmt::format("the matrix at byte {} does not start with 8 bytes of array flags", matrix));
    }
    if (index == 1 && (type != kInt32 || bytes < 8 || bytes % 4 != 0)) {
      fail(
          fmt::format("the matrix at byte {} has no valid dimensions (int32, at least "
                      "2 of them) at byte {}",
                      matrix, position));
    }
    if (index == 2 && (type & 0xffff) != kInt8) {
      fail(fmt::format("the matrix at byte {} has no name (int8 characters) at byte {}", matrix,
                       position));
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    hyst::io::detail::fail(path_, where_ + what);
  }

  std::uint32_t read_u32(std::uint64_t position) {
    unsigned char b[4];
    bytes_.read(position, b, 4);
    return decode_u32(b, swap_);
  }

  Bytes& bytes_;
  const std::filesystem::path& path_;
  bool swap_;
  std::string where_;
};

//! The whole v5 file: its elements, and the element inside every compressed one.
void check_v5(std::ifstream& in, const std::filesystem::path& path, std::uint64_t size, bool swap) {
  FileBytes file(in, path);
  const auto no_nested_compression = [&](std::uint64_t position, std::uint32_t) {
    fail(path, fmt::format("a compressed element inside a compressed element (in the one at byte "
                           "{})",
                           position));
  };
  V5Walker<FileBytes>(file, path, swap)
      .walk(kHeaderBytes, size, 0, true, [&](std::uint64_t position, std::uint32_t bytes) {
        const std::uint64_t inflated_size =
            InflatedBytes(file, position + 8, bytes, path, position).size();
        InflatedBytes inflated(file, position + 8, bytes, path, position);
        V5Walker<InflatedBytes>(inflated, path, swap,
                                fmt::format("in the compressed element at byte {}, ", position))
            .walk(0, inflated_size, 0, true, no_nested_compression);
      });
}

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
    const auto word = [&](int k, bool big) { return decode_u32(raw + 4 * k, big); };
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
  // Bytes 124..125: the version, 0x0100 for v5 and 0x0200 for v7.3; 126..127: "IM" when the
  // file's byte order is little-endian, "MI" when big-endian. matio goes by the version alone.
  const bool little = size >= kHeaderBytes && header[126] == 'I' && header[127] == 'M';
  const bool big = size >= kHeaderBytes && header[126] == 'M' && header[127] == 'I';
  if (little || big) {
    const auto first = static_cast<unsigned char>(header[little ? 125 : 124]);
    const auto second = static_cast<unsigned char>(header[little ? 124 : 125]);
    if (first == 0x01 && second == 0x00) {
      check_v5(in, path, size, big);
      return;
    }
    // v7.3 files are HDF5 files with a 512-byte user block: HDF5 judges them.
    if (first == 0x02 && second == 0x00 && size >= 520) {
      char signature[8] = {};
      in.seekg(512);
      in.read(signature, 8);
      in.clear();
      if (std::string_view(signature, 8) == std::string_view("\x89HDF\r\n\x1a\n", 8)) return;
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
