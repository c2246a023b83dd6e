#pragma once
// Cells of the comparison tables: yes/no, free text on one line with CSV quoting or Markdown
// escaping.

#include <string>
#include <string_view>

namespace hyst::detail {

inline std::string_view yes_no(bool value) {
  return value ? "yes" : "no";
}

inline std::string csv_quoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

inline std::string markdown_cell(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out;
}

}  // namespace hyst::detail
