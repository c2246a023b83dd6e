#pragma once
// Field helpers shared by the text readers of hyst/io: trimming, locale-independent numbers as
// instruments write them ("+1.5E-01"), "key value" header entries, and the "file:line" of a
// message.

#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace hyst::io::detail {

inline constexpr std::string_view kBlank = " \t\r";

inline std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(kBlank);
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(kBlank);
  return text.substr(first, last - first + 1);
}

//! A finite number, surrounding blanks allowed; from_chars rejects a leading '+', which
//! instruments write, so one is accepted (but not "+-1").
inline std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  if (digits.empty() || (digits.size() < text.size() && digits.front() == '-')) {
    return std::nullopt;
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

using HeaderEntries = std::vector<std::pair<std::string, std::string>>;

//! The value of the first entry with this key, or nullopt.
inline std::optional<std::string> entry_text(const HeaderEntries& entries, std::string_view key) {
  for (const auto& [name, value] : entries) {
    if (name == key) return value;
  }
  return std::nullopt;
}

//! The value of the first entry with this key as a number; nullopt if absent or not a number.
inline std::optional<double> entry_number(const HeaderEntries& entries, std::string_view key) {
  const auto text = entry_text(entries, key);
  return text ? parse_number(*text) : std::nullopt;
}

//! The fields of a line between `separator`s, each trimmed; n separators give n + 1 fields.
inline std::vector<std::string_view> split_fields(std::string_view line, char separator) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto end = line.find(separator, start);
    fields.push_back(
        trim(line.substr(start, end == std::string_view::npos ? line.npos : end - start)));
    if (end == std::string_view::npos) return fields;
    start = end + 1;
  }
}

//! "file:line", or "line N" for an unnamed source.
inline std::string location(std::string_view source, std::size_t line) {
  return source.empty() ? fmt::format("line {}", line) : fmt::format("{}:{}", source, line);
}

}  // namespace hyst::io::detail
