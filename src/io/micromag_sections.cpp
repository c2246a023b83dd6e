#include "micromag_sections.hpp"

#include <algorithm>
#include <cstddef>

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

namespace {

//! Where a header line splits into key and value: at the first '=', ':', tab or run of two
//! blanks, whichever comes first ("HCal           = +2.35E-01", "Units of measure:  Hybrid SI",
//! "Configuration                   VSM"); npos for a line without one (a section name).
std::size_t entry_split(std::string_view line) {
  const auto mark = line.find_first_of("=:\t");
  const auto gap = line.find("  ");
  return std::min(mark, gap);
}

//! A segment table row opens with the segment's number written with leading zeros
//! ("0000001,+100.0000E-03,..."); a data row opens with a signed field ("+5.0E-01") or a plain
//! number ("0.5", "2"), never with "0" and another digit.
bool opens_with_segment_number(std::string_view row) {
  const auto number = row.substr(0, row.find(','));
  return number.size() >= 2 && number.front() == '0' &&
         number.find_first_not_of("0123456789") == std::string_view::npos;
}

}  // namespace

std::size_t MicromagSectionReader::read_head(HeaderEntries& header) {
  // Header entries up to the first comma row. The text lines just above that row (after the last
  // blank line) that split at blanks, not at '=' or ':', are the titles of the table it starts,
  // not entries.
  std::string_view line;
  std::vector<std::size_t> title_entries;  // indices into header of the lines in titles_
  bool found = false;
  bool ended = false;
  while (!found && next_content(line)) {
    if (line.empty()) {
      title_entries.clear();
      titles_.clear();
      continue;
    }
    if (is_micromag_end_marker(line)) {
      ended = true;
      break;
    }
    if (is_comma_row(line)) {
      for (auto k = title_entries.rbegin(); k != title_entries.rend(); ++k)
        header.erase(header.begin() + static_cast<std::ptrdiff_t>(*k));
      first_row_ = line;
      found = true;
      break;
    }
    const auto split = entry_split(line);
    if (split == std::string_view::npos) {  // a section name such as "INSTRUMENT", a title word
      titles_.push_back(raw_line_);
      continue;
    }
    const auto key = trim(line.substr(0, split));
    auto value = trim(line.substr(split));
    const bool marked = value.starts_with('=') || value.starts_with(':');
    if (marked) value = trim(value.substr(1));
    if (key.empty()) continue;
    if (!marked) {
      titles_.push_back(raw_line_);
      title_entries.push_back(header.size());
    }
    header.emplace_back(utf8_from_latin1(key), utf8_from_latin1(value));
  }
  if (ended) {
    throw Error(fmt::format("{}: the end marker follows the header: the file has no data rows",
                            location(source_, lines_.number())));
  }
  if (!found) {
    throw Error(fmt::format("{}: the file ends in its header, before any data (truncated?)",
                            location(source_, lines_.number())));
  }
  // A segment table (loop files) has its own titles ("Segment  Averaging ..." over " Number
  // Time ...") and numbered rows. Without one, "Number of segments" is the script's count of
  // field sweeps (a FORC file writes it too), not a count of rows to check.
  bool titled = false;
  for (const auto title : titles_)
    titled = titled || title.find("Segment") != std::string_view::npos;
  if (!titled && !opens_with_segment_number(first_row_)) return 0;
  std::size_t rows = 0;
  read_segment_table(entry_number(header, "Number of segments"), rows);
  return rows;
}

void MicromagSectionReader::read_segment_table(std::optional<double> declared, std::size_t& rows) {
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
  if (declared && static_cast<double>(rows) != *declared) {
    throw Error(
        fmt::format("{}: the header says 'Number of segments {}' but the segment table has {} rows",
                    location(source_, lines_.number()), *declared, rows));
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
