#pragma once
// Physical lines of a text with their 1-based numbers, for the text readers of hyst/io: a UTF-8
// byte order mark at the start is skipped, and a trailing '\r' (CRLF line ends) is removed.

#include <cstddef>
#include <string_view>

namespace hyst::io::detail {

//! The UTF-8 encoding of U+FEFF, which some programs write at the start of a text file.
inline constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

class LineReader {
 public:
  explicit LineReader(std::string_view text) : rest_(text) {
    if (rest_.starts_with(kByteOrderMark)) rest_.remove_prefix(kByteOrderMark.size());
  }

  //! The next line in `line`; false after the last one.
  bool next(std::string_view& line) {
    if (finished_) return false;
    ++number_;
    const auto end = rest_.find('\n');
    if (end == std::string_view::npos) {
      line = rest_;
      finished_ = true;
    } else {
      line = rest_.substr(0, end);
      rest_.remove_prefix(end + 1);
    }
    if (line.ends_with('\r')) line.remove_suffix(1);
    return true;
  }
  //! The number of the line next() returned last.
  std::size_t number() const { return number_; }

 private:
  std::string_view rest_;
  std::size_t number_ = 0;
  bool finished_ = false;
};

}  // namespace hyst::io::detail
