#include "hyst/io/numpy_file.hpp"

#include <zip.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/limits.hpp"

namespace hyst::io {
namespace {
// The library is compiled in unity batches: a named namespace keeps these helpers apart from the
// anonymous helpers of the other readers in the same batch.
namespace npy {

namespace fs = std::filesystem;

constexpr std::string_view kMagic = "\x93NUMPY";
constexpr std::string_view kZipMagic = "PK\x03\x04";
constexpr std::string_view kAccepted =
    "hyst reads float64 ('<f8', '>f8') and float32 ('<f4', '>f4') arrays";
//! NumPy 2 allows 64 axes (NumPy 1: 32).
constexpr std::size_t kMaxAxes = 64;
//! Nesting of the header's values (a structured dtype nests 3 levels).
constexpr int kMaxHeaderDepth = 16;

//! "x.npy: " or "" for an unnamed source.
std::string prefix(std::string_view source) {
  return source.empty() ? std::string() : fmt::format("{}: ", source);
}

//! Header or name text as shown in a message: printable ASCII as is, other bytes as \xNN, cut
//! after `limit` characters, so that a message stays one short ASCII line.
std::string shown(std::string_view text, std::size_t limit = 80) {
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (out.size() >= limit) return fmt::format("{}... ({} bytes)", out, text.size());
    const auto byte = static_cast<unsigned char>(text[k]);
    if (byte >= 0x20 && byte < 0x7f) {
      out += static_cast<char>(byte);
    } else {
      out += fmt::format("\\x{:02x}", byte);
    }
  }
  return out;
}

//! The header without the blanks and newline that pad it, for messages.
std::string_view unpadded(std::string_view header) {
  const auto last = header.find_last_not_of(" \t\n\r\f\v");
  return last == std::string_view::npos ? std::string_view() : header.substr(0, last + 1);
}

//! A shape or index as NumPy prints it: "()", "(5,)", "(8192, 3)".
std::string tuple_text(const std::vector<std::size_t>& items) {
  if (items.size() == 1) return fmt::format("({},)", items[0]);
  return fmt::format("({})", fmt::join(items, ", "));
}

bool ends_with(std::string_view text, std::string_view end) {
  return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

// ---- The header: a Python literal ---------------------------------------------------------

//! One value of the header as Python's literal syntax writes it (the subset NumPy's headers use).
struct Literal {
  enum class Kind { string, integer, name, tuple, list, dict };
  Kind kind = Kind::name;
  std::string_view text;  //!< string: between the quotes, as written; integer, name: as written
  std::vector<Literal> items;  //!< tuple, list; dict: key, value, key, value, ...
  std::string_view source;     //!< the whole value as written, for messages

  static Literal of(Kind kind, std::string_view text = {}) {
    Literal literal;
    literal.kind = kind;
    literal.text = text;
    return literal;
  }
};

//! Recursive descent over the header text; throws naming the byte where the syntax breaks.
class HeaderParser {
 public:
  HeaderParser(std::string_view header, std::string_view source)
      : header_(header), source_(source) {}

  Literal parse() {
    Literal top = value(0);
    skip_blanks();
    if (at_ < header_.size()) fail("unexpected text after the dictionary");
    return top;
  }

 private:
  [[noreturn]] void fail(std::string_view what) const {
    throw Error(fmt::format("{}malformed .npy header at byte {}: {} (header: {})", prefix(source_),
                            at_, what, shown(unpadded(header_))));
  }

  void skip_blanks() {
    while (at_ < header_.size() &&
           std::string_view(" \t\n\r\f\v").find(header_[at_]) != std::string_view::npos) {
      ++at_;
    }
  }

  bool next_is(char c) {
    skip_blanks();
    return at_ < header_.size() && header_[at_] == c;
  }

  Literal value(int depth) {
    skip_blanks();
    if (at_ == header_.size()) fail("the header ends where a value should start");
    if (depth > kMaxHeaderDepth) fail(fmt::format("values nested deeper than {}", kMaxHeaderDepth));
    const std::size_t begin = at_;
    Literal result = value_at(depth, header_[at_]);
    result.source = header_.substr(begin, at_ - begin);
    return result;
  }

  Literal value_at(int depth, char first) {
    if (first == '\'' || first == '"') return string();
    if (first == '(') return sequence(depth, ')', Literal::Kind::tuple);
    if (first == '[') return sequence(depth, ']', Literal::Kind::list);
    if (first == '{') return dict(depth);
    if (first == '-' || is_digit(first)) return integer();
    if (is_name_start(first)) return name();
    fail(fmt::format("unexpected character '{}'", shown(header_.substr(at_, 1))));
  }

  static bool is_digit(char c) { return c >= '0' && c <= '9'; }
  static bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
  static bool is_name_char(char c) { return is_name_start(c) || is_digit(c) || c == '_'; }

  //! '...' or "..."; a backslash keeps the next character in the string (escapes are not
  //! decoded: the strings that matter, keys and dtypes, have none).
  Literal string() {
    const char quote = header_[at_++];
    const std::size_t begin = at_;
    while (at_ < header_.size() && header_[at_] != quote) {
      if (header_[at_] == '\n') fail("a string runs to the end of the line");
      at_ += header_[at_] == '\\' ? 2 : 1;
    }
    if (at_ >= header_.size()) fail("a string runs to the end of the header");
    Literal result = Literal::of(Literal::Kind::string, header_.substr(begin, at_ - begin));
    ++at_;
    return result;
  }

  //! A whole decimal number, possibly negative; Python 2's long suffix 'L' is accepted (NumPy
  //! wrote "(3L, 4L)" there, and reads it still).
  Literal integer() {
    const std::size_t begin = at_;
    if (header_[at_] == '-') ++at_;
    const std::size_t digits = at_;
    while (at_ < header_.size() && is_digit(header_[at_]))
      ++at_;
    if (at_ == digits) fail("a '-' without digits");
    Literal result = Literal::of(Literal::Kind::integer, header_.substr(begin, at_ - begin));
    if (at_ < header_.size() && (header_[at_] == 'L' || header_[at_] == 'l')) ++at_;
    if (at_ < header_.size() && (is_name_char(header_[at_]) || header_[at_] == '.')) {
      fail("a number that is not a whole decimal number");
    }
    return result;
  }

  //! True, False or None.
  Literal name() {
    const std::size_t begin = at_;
    while (at_ < header_.size() && is_name_char(header_[at_]))
      ++at_;
    const std::string_view word = header_.substr(begin, at_ - begin);
    if (word != "True" && word != "False" && word != "None") {
      at_ = begin;
      fail(fmt::format("unknown name '{}' (expected True, False or None)", shown(word)));
    }
    return Literal::of(Literal::Kind::name, word);
  }

  //! (a, b), (a,), () or [a, b]; "(a)" is `a` itself, as in Python.
  Literal sequence(int depth, char close, Literal::Kind kind) {
    ++at_;
    Literal result = Literal::of(kind);
    bool comma = false;
    while (!next_is(close)) {
      result.items.push_back(value(depth + 1));
      if (next_is(',')) {
        ++at_;
        comma = true;
      } else if (!next_is(close)) {
        fail(fmt::format("expected ',' or '{}'", close));
      }
    }
    ++at_;
    if (kind == Literal::Kind::tuple && result.items.size() == 1 && !comma) {
      return std::move(result.items.front());
    }
    return result;
  }

  Literal dict(int depth) {
    ++at_;
    Literal result = Literal::of(Literal::Kind::dict);
    while (!next_is('}')) {
      result.items.push_back(value(depth + 1));
      if (!next_is(':')) fail("expected ':' after a key");
      ++at_;
      result.items.push_back(value(depth + 1));
      if (next_is(',')) {
        ++at_;
      } else if (!next_is('}')) {
        fail("expected ',' or '}'");
      }
    }
    ++at_;
    return result;
  }

  std::string_view header_;
  std::string_view source_;
  std::size_t at_ = 0;
};

// ---- The header's meaning ------------------------------------------------------------------

//! The element types hyst reads.
struct Dtype {
  std::size_t size = 8;  //!< bytes per value: 8 (float64) or 4 (float32)
  bool big_endian = false;
};

struct Header {
  Dtype dtype;
  bool fortran_order = false;
  std::vector<std::size_t> shape;
};

[[noreturn]] void fail_header(std::string_view source, std::string_view header,
                              std::string_view what) {
  throw Error(
      fmt::format("{}.npy header: {} (header: {})", prefix(source), what, shown(unpadded(header))));
}

//! What a dtype string (without its byte order) stands for ("int64", "Python objects"), or ""
//! if unknown.
std::string dtype_meaning(std::string_view descr) {
  if (descr.empty() || descr.size() > 4) return "";
  const char kind = descr[0];
  std::size_t bytes = 0;
  for (const char c : descr.substr(1)) {
    if (c < '0' || c > '9') return "";
    bytes = bytes * 10 + static_cast<std::size_t>(c - '0');
  }
  const std::size_t bits = 8 * bytes;
  switch (kind) {
    case 'f':
      return bytes > 8 ? "long double" : fmt::format("float{}", bits);
    case 'i':
      return fmt::format("int{}", bits);
    case 'u':
      return fmt::format("uint{}", bits);
    case 'c':
      return fmt::format("complex{}", bits);
    case 'b':
      return "bool";
    case 'O':
      return "Python objects, stored with pickle";
    case 'U':
      return "unicode strings";
    case 'S':
    case 'a':
      return "byte strings";
    case 'V':
      return "raw bytes";
    case 'M':
      return "datetime64";
    case 'm':
      return "timedelta64";
    default:
      return "";
  }
}

Dtype read_dtype(const Literal& descr, std::string_view source, std::string_view header) {
  if (descr.kind == Literal::Kind::list) {
    fail_header(source, header,
                fmt::format("a structured dtype {} (named fields) is not supported; {}",
                            shown(descr.source), kAccepted));
  }
  if (descr.kind != Literal::Kind::string) {
    fail_header(source, header,
                fmt::format("'descr' {} is not a dtype string such as '<f8'; {}",
                            shown(descr.source), kAccepted));
  }
  const std::string_view text = descr.text;
  if (text == "<f8") return {8, false};
  if (text == ">f8") return {8, true};
  if (text == "<f4") return {4, false};
  if (text == ">f4") return {4, true};
  std::string_view kind = text;  // without the byte order
  if (!kind.empty() && std::string_view("<>|=").find(kind[0]) != std::string_view::npos) {
    kind.remove_prefix(1);
  }
  std::string meaning = dtype_meaning(kind);
  if (kind == "f8" || kind == "f4") {
    meaning += ", but not with the byte order '<' or '>' that NumPy writes";
  }
  const std::string what = meaning.empty() ? fmt::format("dtype '{}'", shown(text))
                                           : fmt::format("dtype '{}' ({})", shown(text), meaning);
  const bool pickled = kind.starts_with('O');
  fail_header(source, header,
              fmt::format("{} is not supported{}; {}", what,
                          pickled ? ": hyst does not unpickle" : "", kAccepted));
}

bool read_fortran_order(const Literal& value, std::string_view source, std::string_view header) {
  if (value.kind == Literal::Kind::name && value.text != "None") return value.text == "True";
  fail_header(source, header,
              fmt::format("'fortran_order' must be True or False, not {}", shown(value.source)));
}

//! One axis length: a whole number in 0 .. 2^64 - 1.
std::size_t read_axis(const Literal& item, std::size_t axis, std::string_view source,
                      std::string_view header) {
  if (item.kind != Literal::Kind::integer) {
    fail_header(
        source, header,
        fmt::format("axis {} of 'shape' is {}, not a whole number", axis, shown(item.source)));
  }
  if (item.text.front() == '-') {
    fail_header(source, header,
                fmt::format("axis {} of 'shape' is negative ({})", axis, shown(item.text)));
  }
  std::size_t length = 0;
  for (const char digit : item.text) {
    const auto d = static_cast<std::size_t>(digit - '0');
    if (length > (std::numeric_limits<std::size_t>::max() - d) / 10) {
      fail_header(source, header,
                  fmt::format("axis {} of 'shape', {}, is too large", axis, shown(item.text)));
    }
    length = length * 10 + d;
  }
  return length;
}

std::vector<std::size_t> read_shape(const Literal& value, std::string_view source,
                                    std::string_view header) {
  if (value.kind != Literal::Kind::tuple) {
    fail_header(source, header,
                fmt::format("'shape' must be a tuple of whole numbers such as (8192, 3), not {}",
                            shown(value.source)));
  }
  if (value.items.size() > kMaxAxes) {
    fail_header(
        source, header,
        fmt::format("'shape' has {} axes; NumPy allows at most {}", value.items.size(), kMaxAxes));
  }
  std::vector<std::size_t> shape;
  for (std::size_t axis = 0; axis < value.items.size(); ++axis) {
    shape.push_back(read_axis(value.items[axis], axis, source, header));
  }
  return shape;
}

//! The dictionary NumPy writes: exactly the keys 'descr', 'fortran_order' and 'shape'.
Header read_header(std::string_view header, std::string_view source) {
  const Literal top = HeaderParser(header, source).parse();
  if (top.kind != Literal::Kind::dict) {
    fail_header(source, header,
                "not a dictionary {'descr': ..., 'fortran_order': ..., "
                "'shape': ...}");
  }
  constexpr std::array<std::string_view, 3> kKeys = {"descr", "fortran_order", "shape"};
  std::array<const Literal*, 3> values{};
  for (std::size_t k = 0; k + 1 < top.items.size(); k += 2) {
    const Literal& key = top.items[k];
    const auto* known = key.kind == Literal::Kind::string
                            ? std::find(kKeys.begin(), kKeys.end(), key.text)
                            : kKeys.end();
    if (known == kKeys.end()) {
      fail_header(source, header,
                  fmt::format("unknown key {} (NumPy writes 'descr', 'fortran_order' and 'shape')",
                              shown(key.source)));
    }
    const auto slot = static_cast<std::size_t>(known - kKeys.begin());
    if (values[slot] != nullptr) {
      fail_header(source, header, fmt::format("the key '{}' appears twice", *known));
    }
    values[slot] = &top.items[k + 1];
  }
  for (std::size_t slot = 0; slot < kKeys.size(); ++slot) {
    if (values[slot] == nullptr) {
      fail_header(source, header,
                  fmt::format("no key '{}' (NumPy writes 'descr', "
                              "'fortran_order' and 'shape')",
                              kKeys[slot]));
    }
  }
  return {.dtype = read_dtype(*values[0], source, header),
          .fortran_order = read_fortran_order(*values[1], source, header),
          .shape = read_shape(*values[2], source, header)};
}

// ---- The values ----------------------------------------------------------------------------

//! Product of the axis lengths, checked against overflow and limits::kMaxNumpyValues.
std::size_t value_count(const std::vector<std::size_t>& shape, std::string_view source) {
  if (std::find(shape.begin(), shape.end(), std::size_t{0}) != shape.end()) return 0;
  std::size_t count = 1;
  for (const std::size_t length : shape) {
    if (count > std::numeric_limits<std::size_t>::max() / length) {
      throw Error(fmt::format("{}the shape {} has more values than a 64-bit count holds",
                              prefix(source), tuple_text(shape)));
    }
    count *= length;
  }
  if (count > limits::kMaxNumpyValues) {
    throw Error(
        fmt::format("{}the shape {} holds {} values, more than the limit of {} values of "
                    "one array",
                    prefix(source), tuple_text(shape), count, limits::kMaxNumpyValues));
  }
  return count;
}

//! The values as stored, in file order, as doubles (independent of the machine's byte order).
template <class Float, class Bits>
void decode(std::string_view data, bool big_endian, std::vector<double>& out) {
  constexpr std::size_t kSize = sizeof(Bits);
  for (std::size_t k = 0; k < out.size(); ++k) {
    const char* bytes = data.data() + k * kSize;
    Bits bits = 0;
    for (std::size_t b = 0; b < kSize; ++b) {
      const std::size_t at = big_endian ? b : kSize - 1 - b;  // most significant byte first
      bits = static_cast<Bits>((bits << 8) | static_cast<unsigned char>(bytes[at]));
    }
    out[k] = static_cast<double>(std::bit_cast<Float>(bits));
  }
}

//! Row-major strides (in values) of an array of `shape`.
std::vector<std::size_t> c_strides(const std::vector<std::size_t>& shape) {
  std::vector<std::size_t> strides(shape.size(), 1);
  for (std::size_t d = shape.size(); d-- > 1;)
    strides[d - 1] = strides[d] * shape[d];
  return strides;
}

//! Copies `in`, which runs over `shape` in C order, to out[sum of index[d] * strides[d]]; all of
//! the permutations of this file are such a copy. `count` is the product of `shape`.
void scatter(const std::vector<double>& in, const std::vector<std::size_t>& shape,
             const std::vector<std::size_t>& strides, std::vector<double>& out) {
  std::vector<std::size_t> index(shape.size(), 0);
  std::size_t offset = 0;
  for (const double value : in) {
    out[offset] = value;
    for (std::size_t d = shape.size(); d-- > 0;) {  // the last axis runs fastest
      if (index[d] + 1 < shape[d]) {
        ++index[d];
        offset += strides[d];
        break;
      }
      offset -= strides[d] * index[d];
      index[d] = 0;
    }
  }
}

//! Fortran order to C order: the values of a Fortran-order array of shape (a, b, c) are those of
//! a C-order array of shape (c, b, a), whose index (k, j, i) goes to C index (i, j, k).
std::vector<double> from_fortran_order(const std::vector<double>& values,
                                       const std::vector<std::size_t>& shape) {
  std::vector<std::size_t> reversed(shape.rbegin(), shape.rend());
  std::vector<std::size_t> strides = c_strides(shape);
  std::reverse(strides.begin(), strides.end());
  std::vector<double> out(values.size());
  scatter(values, reversed, strides, out);
  return out;
}

void check_finite(const std::vector<double>& values, const std::vector<std::size_t>& shape,
                  std::string_view source) {
  const auto bad = std::find_if(values.begin(), values.end(),
                                [](double value) { return !std::isfinite(value); });
  if (bad == values.end()) return;
  const auto flat = static_cast<std::size_t>(bad - values.begin());
  std::vector<std::size_t> index(shape.size());
  std::size_t rest = flat;
  for (std::size_t d = shape.size(); d-- > 0;) {
    index[d] = rest % shape[d];
    rest /= shape[d];
  }
  throw Error(
      fmt::format("{}the value at index {} (flat index {} in C order) is {}; hyst reads "
                  "finite values only",
                  prefix(source), tuple_text(index), flat, *bad));
}

std::vector<double> read_values(std::string_view data, const Header& header,
                                std::string_view source) {
  const std::size_t count = value_count(header.shape, source);
  const std::size_t needed = count * header.dtype.size;  // <= 2^28: the limit holds it
  if (data.size() != needed) {
    throw Error(fmt::format(
        "{}the data part is {}: the shape {} of float{} needs {} bytes, there are {} after the "
        "header",
        prefix(source), data.size() < needed ? "cut short" : "longer than the shape says",
        tuple_text(header.shape), 8 * header.dtype.size, needed, data.size()));
  }
  std::vector<double> values(count);
  if (header.dtype.size == 8) {
    decode<double, std::uint64_t>(data, header.dtype.big_endian, values);
  } else {
    decode<float, std::uint32_t>(data, header.dtype.big_endian, values);
  }
  if (header.fortran_order && header.shape.size() > 1) {
    values = from_fortran_order(values, header.shape);
  }
  check_finite(values, header.shape, source);
  return values;
}

// ---- The preamble: magic string, version, header length -----------------------------------

std::uint32_t little_endian(std::string_view bytes) {
  std::uint32_t value = 0;
  for (std::size_t b = bytes.size(); b-- > 0;)
    value = (value << 8) | static_cast<unsigned char>(bytes[b]);
  return value;
}

//! Splits a .npy file into its header text and its data part.
std::pair<std::string_view, std::string_view> split_npy(std::string_view bytes,
                                                        std::string_view source) {
  if (bytes.empty()) throw Error(fmt::format("{}not a .npy file: it is empty", prefix(source)));
  if (bytes.substr(0, kMagic.size()) != kMagic) {
    throw Error(
        fmt::format("{}not a .npy file: it does not start with \\x93NUMPY{}", prefix(source),
                    bytes.starts_with(kZipMagic) ? " (it is a zip archive: an .npz?)" : ""));
  }
  if (bytes.size() < 8) {
    throw Error(fmt::format("{}the .npy file ends inside its format version", prefix(source)));
  }
  const int major = static_cast<unsigned char>(bytes[6]);
  const int minor = static_cast<unsigned char>(bytes[7]);
  if (major < 1 || major > 3 || minor != 0) {
    throw Error(fmt::format("{}.npy format version {}.{} is not supported (1.0, 2.0 and 3.0 are)",
                            prefix(source), major, minor));
  }
  const std::size_t length_bytes = major == 1 ? 2 : 4;
  const std::size_t start = 8 + length_bytes;
  if (bytes.size() < start) {
    throw Error(fmt::format("{}the .npy file ends inside its header length", prefix(source)));
  }
  const std::size_t length = little_endian(bytes.substr(8, length_bytes));
  if (length > limits::kMaxNpyHeaderBytes) {
    throw Error(
        fmt::format("{}the .npy header claims {} bytes, more than the limit of {} "
                    "(NumPy's own)",
                    prefix(source), length, limits::kMaxNpyHeaderBytes));
  }
  if (length > bytes.size() - start) {
    throw Error(
        fmt::format("{}the .npy header is cut short: it claims {} bytes, the file has {} "
                    "after the preamble",
                    prefix(source), length, bytes.size() - start));
  }
  return {bytes.substr(start, length), bytes.substr(start + length)};
}

// ---- .npz archives ---------------------------------------------------------------------------

struct ZipDiscard {
  void operator()(zip_t* archive) const { zip_discard(archive); }
};
struct ZipFileClose {
  void operator()(zip_file_t* file) const { zip_fclose(file); }
};

//! An .npz file held in memory and opened with libzip; the archive reads from `bytes_`, so the
//! object is neither copied nor moved.
class NpzArchive {
 public:
  NpzArchive(std::string bytes, std::string path)
      : bytes_(std::move(bytes)), path_(std::move(path)) {
    if (bytes_.empty()) throw Error(fmt::format("{}: not an .npz file: it is empty", path_));
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(bytes_.data(), bytes_.size(), 0, &error);
    zip_t* archive = source ? zip_open_from_source(source, ZIP_RDONLY, &error) : nullptr;
    if (archive == nullptr) {
      if (source != nullptr) zip_source_free(source);
      const std::string reason = zip_error_strerror(&error);
      zip_error_fini(&error);
      throw Error(fmt::format("{}: not an .npz file (a zip archive): {}{}", path_, reason,
                              bytes_.starts_with(kMagic) ? " (it is a .npy file)" : ""));
    }
    zip_error_fini(&error);
    archive_.reset(archive);
    list_members();
  }
  NpzArchive(const NpzArchive&) = delete;
  NpzArchive& operator=(const NpzArchive&) = delete;

  const std::vector<std::string>& names() const { return names_; }

  //! The array `name` (with or without ".npy").
  NumpyArray read(std::string_view name) const {
    if (ends_with(name, ".npy")) name.remove_suffix(4);
    const auto found = std::find(names_.begin(), names_.end(), name);
    if (found == names_.end()) {
      throw Error(fmt::format("{}: no array '{}' ({})", path_, shown(name), listing()));
    }
    const std::string source = fmt::format("{}:{}", path_, *found);
    return parse_npy(
        member_bytes(indices_[static_cast<std::size_t>(found - names_.begin())], source), source);
  }

  //! "arrays: a, b" or "the archive holds no array (no .npy member)", for messages.
  std::string listing() const {
    if (names_.empty()) return "the archive holds no array (no .npy member)";
    return fmt::format("arrays: {}", name_list());
  }

  //! "a, b", cut after 20 names.
  std::string name_list() const {
    constexpr std::size_t kShownNames = 20;
    std::vector<std::string> shown_names;
    for (std::size_t k = 0; k < std::min(names_.size(), kShownNames); ++k)
      shown_names.push_back(shown(names_[k], 40));
    if (names_.size() > kShownNames) shown_names.push_back("...");
    return fmt::format("{}", fmt::join(shown_names, ", "));
  }

 private:
  //! The members named "*.npy", as NumPy lists them (without ".npy"); other members are no arrays.
  void list_members() {
    const zip_int64_t count = zip_get_num_entries(archive_.get(), 0);
    for (zip_int64_t index = 0; index < count; ++index) {
      const char* name = zip_get_name(archive_.get(), static_cast<zip_uint64_t>(index), 0);
      if (name == nullptr || !ends_with(name, ".npy")) continue;
      const std::string_view array(name, std::char_traits<char>::length(name) - 4);
      if (std::find(names_.begin(), names_.end(), array) != names_.end()) continue;  // first wins
      names_.emplace_back(array);
      indices_.push_back(static_cast<zip_uint64_t>(index));
    }
  }

  //! The inflated member, at most limits::kMaxNpzMemberBytes: its claimed size is checked before
  //! reading, and the bytes read are counted, since the claim may lie.
  std::string member_bytes(zip_uint64_t index, std::string_view source) const {
    zip_stat_t status;
    zip_stat_init(&status);
    if (zip_stat_index(archive_.get(), index, 0, &status) == 0 &&
        (status.valid & ZIP_STAT_SIZE) != 0 && status.size > limits::kMaxNpzMemberBytes) {
      throw Error(
          fmt::format("{}: the member claims {} bytes, more than the limit of {} (the "
                      "largest .npy of {} values)",
                      source, status.size, limits::kMaxNpzMemberBytes, limits::kMaxNumpyValues));
    }
    const std::unique_ptr<zip_file_t, ZipFileClose> file(zip_fopen_index(archive_.get(), index, 0));
    if (!file) {
      throw Error(
          fmt::format("{}: cannot open the member: {}", source, zip_strerror(archive_.get())));
    }
    std::string content;
    std::array<char, 65536> buffer;
    while (true) {
      const zip_int64_t count = zip_fread(file.get(), buffer.data(), buffer.size());
      if (count < 0) {
        throw Error(
            fmt::format("{}: cannot read the member: {}", source, zip_file_strerror(file.get())));
      }
      if (count == 0) return content;
      if (static_cast<std::size_t>(count) > limits::kMaxNpzMemberBytes - content.size()) {
        throw Error(
            fmt::format("{}: the member inflates to more than {} bytes, the limit (the "
                        "largest .npy of {} values)",
                        source, limits::kMaxNpzMemberBytes, limits::kMaxNumpyValues));
      }
      // Grow as append() would, but never past the limit (doubling 256 MiB would ask for 512).
      const std::size_t needed = content.size() + static_cast<std::size_t>(count);
      if (needed > content.capacity()) {
        content.reserve(std::min(limits::kMaxNpzMemberBytes, 2 * needed));
      }
      content.append(buffer.data(), static_cast<std::size_t>(count));
    }
  }

  std::string bytes_;  // declared before archive_, which reads from it, so destroyed after it
  std::string path_;
  std::unique_ptr<zip_t, ZipDiscard> archive_;
  std::vector<std::string> names_;
  std::vector<zip_uint64_t> indices_;
};

//! Splits "x.npz:name" into the file and the array name. A spec naming an existing file is that
//! file (its name may hold ':'); otherwise the split is after the last ".npz" that names an
//! existing file, or after the first ".npz" if none does (reading it then says why).
std::pair<std::string, std::optional<std::string>> split_spec(std::string_view spec) {
  std::error_code ignored;
  if (fs::exists(fs::path(spec), ignored)) return {std::string(spec), std::nullopt};
  std::optional<std::size_t> file_end;
  for (std::size_t at = spec.rfind(".npz:"); at != std::string_view::npos;
       at = at == 0 ? std::string_view::npos : spec.rfind(".npz:", at - 1)) {
    file_end = at + 4;
    if (fs::is_regular_file(fs::path(spec.substr(0, *file_end)), ignored)) break;
  }
  if (!file_end) return {std::string(spec), std::nullopt};
  return {std::string(spec.substr(0, *file_end)), std::string(spec.substr(*file_end + 1))};
}

// ---- Layouts ------------------------------------------------------------------------------

enum class Axis : std::size_t { samples, channel, realisation, period };
constexpr std::string_view kAxisNames = "N, channel, realisation, period";

std::optional<Axis> axis_named(std::string_view name) {
  if (name == "N") return Axis::samples;
  if (name == "channel") return Axis::channel;
  if (name == "realisation" || name == "realization") return Axis::realisation;
  if (name == "period") return Axis::period;
  return std::nullopt;
}

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

//! One axis of a layout: which one, and the name the layout gives it.
struct LayoutAxis {
  Axis axis;
  std::string_view name;
};

//! The axes a layout names, in order; throws for an empty, unknown or repeated name.
std::vector<LayoutAxis> parse_layout(std::string_view layout, std::string_view where) {
  std::vector<LayoutAxis> axes;
  std::size_t start = 0;
  while (start <= layout.size()) {
    const std::size_t comma = std::min(layout.find(',', start), layout.size());
    const std::string_view name = trim(layout.substr(start, comma - start));
    start = comma + 1;
    const auto axis = axis_named(name);
    if (!axis) {
      throw Error(fmt::format("{}{} axis name '{}' (known: {})", where,
                              name.empty() ? "an empty" : "unknown", shown(name), kAxisNames));
    }
    const auto seen = std::find_if(
        axes.begin(), axes.end(), [&](const LayoutAxis& earlier) { return earlier.axis == *axis; });
    if (seen != axes.end()) {
      throw Error(
          fmt::format("{}'{}' names the same axis as '{}' before it", where, name, seen->name));
    }
    axes.push_back({*axis, name});
  }
  return axes;
}

}  // namespace npy
}  // namespace

NumpyArray parse_npy(std::string_view bytes, std::string_view source) {
  const auto [header_text, data] = npy::split_npy(bytes, source);
  const npy::Header header = npy::read_header(header_text, source);
  NumpyArray array;
  array.values = npy::read_values(data, header, source);
  array.shape = header.shape;
  return array;
}

NumpyArray read_npy(const std::filesystem::path& path) {
  return parse_npy(read_file(path), path.string());
}

std::vector<std::string> npz_array_names(const std::filesystem::path& path) {
  const npy::NpzArchive archive(read_file(path), path.string());
  return archive.names();
}

NumpyArray read_npz_array(const std::filesystem::path& path, std::string_view name) {
  const npy::NpzArchive archive(read_file(path), path.string());
  return archive.read(name);
}

NumpyArray read_numpy_array(std::string_view spec) {
  const auto [path, name] = npy::split_spec(spec);
  std::string bytes = read_file(path);
  // By content, not by name: a .npy starts with \x93NUMPY, a zip archive with "PK".
  if (!name && bytes.starts_with(npy::kMagic)) return parse_npy(bytes, path);
  if (!name && !bytes.starts_with("PK")) {
    throw Error(
        fmt::format("{}: neither a .npy file (it would start with \\x93NUMPY) nor an .npz "
                    "file (a zip archive)",
                    path));
  }
  const npy::NpzArchive archive(std::move(bytes), path);
  if (name) return archive.read(*name);
  if (archive.names().empty()) {
    throw Error(fmt::format("{}: no array in the archive (no .npy member)", path));
  }
  if (archive.names().size() > 1) {
    throw Error(fmt::format("{}: {} arrays ({}) where one was expected; name one as {}:NAME", path,
                            archive.names().size(), archive.name_list(), path));
  }
  return archive.read(archive.names().front());
}

PeriodicSignals arrange_periodic(const NumpyArray& array, std::string_view layout,
                                 std::string_view source) {
  const std::string where = fmt::format("{}layout '{}': ", npy::prefix(source), npy::shown(layout));
  const std::vector<npy::LayoutAxis> axes = npy::parse_layout(layout, where);
  if (axes.size() != array.shape.size()) {
    throw Error(fmt::format("{}{} axes for an array of {} (shape {})", where, axes.size(),
                            array.shape.size(), npy::tuple_text(array.shape)));
  }
  for (std::size_t d = 0; d < axes.size(); ++d) {
    if (array.shape[d] == 0) {
      throw Error(fmt::format("{}the axis '{}' (axis {} of the shape {}) is empty", where,
                              axes[d].name, d, npy::tuple_text(array.shape)));
    }
  }
  std::array<std::size_t, 4> sizes = {1, 1, 1, 1};  // by npy::Axis
  std::size_t count = 1;
  for (std::size_t d = 0; d < axes.size(); ++d) {
    const std::size_t length = array.shape[d];
    // The shape of an array that parse_npy() did not make may be anything.
    if (count > array.values.size() / length) {
      throw Error(fmt::format("{}the array has {} values, fewer than its shape {} holds",
                              npy::prefix(source), array.values.size(),
                              npy::tuple_text(array.shape)));
    }
    sizes[static_cast<std::size_t>(axes[d].axis)] = length;
    count *= length;
  }
  if (array.values.size() != count) {
    throw Error(fmt::format("{}the array has {} values but its shape {} holds {}",
                            npy::prefix(source), array.values.size(), npy::tuple_text(array.shape),
                            count));
  }
  PeriodicSignals out;
  out.samples = sizes[static_cast<std::size_t>(npy::Axis::samples)];
  out.channels = sizes[static_cast<std::size_t>(npy::Axis::channel)];
  out.realisations = sizes[static_cast<std::size_t>(npy::Axis::realisation)];
  out.periods = sizes[static_cast<std::size_t>(npy::Axis::period)];
  out.values.resize(count);
  // How far one step along each axis moves in PeriodicSignals::index(), by npy::Axis.
  const std::array<std::size_t, 4> steps = {
      out.channels, 1, out.periods * out.samples * out.channels, out.samples * out.channels};
  std::vector<std::size_t> strides;
  for (const auto& axis : axes)
    strides.push_back(steps[static_cast<std::size_t>(axis.axis)]);
  npy::scatter(array.values, array.shape, strides, out.values);
  return out;
}

}  // namespace hyst::io
