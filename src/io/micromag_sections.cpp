#include "micromag_sections.hpp"

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "micromag_lines.hpp"
#include "text_encoding.hpp"

namespace hyst::io::detail {

bool is_comma_row(std::string_view content) {
  if (content.empty() || content.find(',') == std::string_view::npos) return false;
  const char first = content.front();
  return (first >= '0' && first <= '9') || first == '+' || first == '-' || first == '.';
}

bool MicromagSectionReader::next_content(std::string_view& line) {
  if (!lines_.next(raw_line_)) return false;
  line = trim(raw_line_);
  return true;
}

void MicromagSectionReader::throw_truncated() const {
  throw Error(fmt::format(
      "{}: the file ends without the line 'MicroMag 2900/3900 Data File ends' (truncated?)",
      location(source_, lines_.number())));
}

std::size_t MicromagSectionReader::read_head(HeaderEntries& header) {
  // Header entries up to the first comma row. The text lines just above that row (after the last
  // blank line) are the titles of the table it starts, not entries.
  std::string_view line;
  std::size_t entries_since_blank = 0;
  bool found = false;
  bool ended = false;
  while (!found && next_content(line)) {
    if (line.empty()) {
      entries_since_blank = 0;
      titles_.clear();
      continue;
    }
    if (is_micromag_end_marker(line)) {
      ended = true;
      break;
    }
    if (is_comma_row(line)) {
      header.resize(header.size() - entries_since_blank);
      first_row_ = line;
      found = true;
      break;
    }
    titles_.push_back(raw_line_);
    const auto split =
        line.find('\t') != std::string_view::npos ? line.find('\t') : line.find("  ");
    if (split == std::string_view::npos) continue;  // a section name such as "INSTRUMENT"
    header.emplace_back(utf8_from_latin1(trim(line.substr(0, split))),
                        utf8_from_latin1(trim(line.substr(split))));
    ++entries_since_blank;
  }
  if (ended) {
    throw Error(fmt::format("{}: the end marker follows the header: the file has no data rows",
                            location(source_, lines_.number())));
  }
  if (!found) {
    throw Error(fmt::format("{}: the file ends in its header, before any data (truncated?)",
                            location(source_, lines_.number())));
  }
  std::size_t rows = 0;
  if (const auto declared = entry_number(header, "Number of segments")) {
    read_segment_table(*declared, rows);
  }
  return rows;
}

void MicromagSectionReader::read_segment_table(double declared, std::size_t& rows) {
  std::string_view line = first_row_;
  titles_.clear();
  bool more = true;
  for (; more && is_comma_row(line); more = next_content(line)) {
    const auto fields = split_fields(line, ',');
    for (std::size_t j = 0; j < fields.size(); ++j) {
      if (!parse_number(fields[j])) {
        throw Error(fmt::format("{}: segment table, field {}: '{}' is not a finite number",
                                location(source_, lines_.number()), j + 1, fields[j]));
      }
    }
    ++rows;
  }
  if (static_cast<double>(rows) != declared) {
    throw Error(
        fmt::format("{}: the header says 'Number of segments {}' but the segment table has {} rows",
                    location(source_, lines_.number()), declared, rows));
  }
  // Column titles: the text lines after the last blank line before the data.
  while (more && !is_comma_row(line)) {
    if (is_micromag_end_marker(line)) {
      throw Error(fmt::format("{}: the file has a segment table but no data rows",
                              location(source_, lines_.number())));
    }
    if (line.empty()) {
      titles_.clear();
    } else {
      titles_.push_back(raw_line_);
    }
    more = next_content(line);
  }
  if (!more) throw_truncated();
  first_row_ = line;
}

}  // namespace hyst::io::detail
