#include "hyst/io/micromag_loop.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "line_reader.hpp"
#include "micromag_lines.hpp"
#include "text_encoding.hpp"
#include "text_fields.hpp"

namespace hyst::io {
namespace {

using detail::is_micromag_end_marker;
using detail::is_micromag_format_line;
using detail::location;
using detail::parse_number;
using detail::trim;

//! Segment and data rows start with a number; header lines start with a letter.
bool is_comma_row(std::string_view content) {
  if (content.empty() || content.find(',') == std::string_view::npos) return false;
  const char first = content.front();
  return (first >= '0' && first <= '9') || first == '+' || first == '-' || first == '.';
}

//! Words of a title line with the column of their centre.
struct Word {
  std::string_view text;
  double centre = 0.0;
};

std::vector<Word> words_of(std::string_view line) {
  std::vector<Word> words;
  std::size_t position = 0;
  while (true) {
    const auto start = line.find_first_not_of(detail::kBlank, position);
    if (start == std::string_view::npos) return words;
    auto end = line.find_first_of(detail::kBlank, start);
    if (end == std::string_view::npos) end = line.size();
    words.push_back({line.substr(start, end - start), 0.5 * static_cast<double>(start + end)});
    position = end;
  }
}

//! Column names from the stacked title lines: the line with one word per column gives the names,
//! words of other lines ("Raw", "Adjusted") are put before the name they stand over, and a units
//! line ("(T)  (Am2)") is skipped.
std::vector<std::string> column_names(const std::vector<std::string_view>& titles,
                                      std::size_t count) {
  std::vector<std::vector<Word>> lines;
  for (const auto title : titles) {
    auto words = words_of(title);
    if (!words.empty() && !words.front().text.starts_with('(')) lines.push_back(std::move(words));
  }
  const auto name_line = std::find_if(lines.rbegin(), lines.rend(),
                                      [&](const auto& words) { return words.size() == count; });
  std::vector<std::string> names(count);
  if (name_line == lines.rend()) {
    for (std::size_t j = 0; j < count; ++j)
      names[j] = fmt::format("Column {}", j + 1);
    return names;
  }
  std::vector<std::string> qualifiers(count);
  for (const auto& words : lines) {
    if (&words == &*name_line) continue;
    for (const auto& word : words) {
      std::size_t nearest = 0;
      for (std::size_t j = 1; j < count; ++j) {
        if (std::abs((*name_line)[j].centre - word.centre) <
            std::abs((*name_line)[nearest].centre - word.centre)) {
          nearest = j;
        }
      }
      qualifiers[nearest] += std::string(word.text) + " ";
    }
  }
  for (std::size_t j = 0; j < count; ++j)
    names[j] = qualifiers[j] + std::string((*name_line)[j].text);
  // Repeated names (no qualifier line) get the column number.
  for (std::size_t j = 0; j < count; ++j) {
    if (std::count(names.begin(), names.end(), names[j]) > 1) {
      names[j] = fmt::format("{} (column {})", names[j], j + 1);
    }
  }
  return names;
}

class LoopParser {
 public:
  LoopParser(std::string_view text, std::string_view source) : lines_(text), source_(source) {
    file_.source = std::string(source);
  }

  MicromagLoopFile parse() {
    std::string_view line;
    if (!lines_.next(line) || !is_micromag_format_line(line)) {
      throw Error(fmt::format(
          "{}: not a MicroMag data file (the first line is '{}', expected 'MicroMag 2900/3900 "
          "Data File (Series ...)')",
          location(source_, 1), trim(line)));
    }
    file_.format = std::string(trim(line));
    lines_.next(line);
    file_.title = std::string(trim(line));
    if (file_.title.find("First-order reversal") != std::string::npos) {
      throw Error(fmt::format(
          "{}: a MicroMag FORC file, not a hysteresis loop (read it with read_micromag_forc)",
          location(source_, 2)));
    }
    if (file_.title.find("Hysteresis loop") == std::string::npos) {
      throw Error(fmt::format(
          "{}: the title is '{}'; this reader knows MicroMag files titled '... Hysteresis loop'",
          location(source_, 2), file_.title));
    }
    read_header();
    const auto declared_segments = file_.header_number("Number of segments");
    if (declared_segments) read_segment_table(*declared_segments);
    read_data();
    check_point_count();
    return std::move(file_);
  }

 private:
  // Header entries up to the first comma row. The text lines just above that row (after the last
  // blank line) are the titles of the table it starts, not entries.
  void read_header() {
    std::string_view line;
    std::size_t entries_since_blank = 0;
    while (next_content(line)) {
      if (line.empty()) {
        entries_since_blank = 0;
        titles_.clear();
        continue;
      }
      if (is_comma_row(line)) {
        file_.header.resize(file_.header.size() - entries_since_blank);
        pending_row_ = line;
        return;
      }
      titles_.push_back(raw_line_);
      const auto split = line.find_first_of('\t') != std::string_view::npos
                             ? line.find_first_of('\t')
                             : line.find("  ");
      if (split == std::string_view::npos) continue;  // a section name such as "INSTRUMENT"
      file_.header.emplace_back(std::string(trim(line.substr(0, split))),
                                std::string(trim(line.substr(split))));
      ++entries_since_blank;
    }
    throw Error(fmt::format("{}: the file ends in its header, before any data (truncated?)",
                            location(source_, lines_.number())));
  }

  void read_segment_table(double declared) {
    std::size_t rows = 0;
    std::string_view line = *pending_row_;
    pending_row_.reset();
    titles_.clear();
    for (bool more = true; more && is_comma_row(line); more = next_content(line)) {
      const auto fields = detail::split_fields(line, ',');
      for (std::size_t j = 0; j < fields.size(); ++j) {
        if (!parse_number(fields[j])) {
          throw Error(fmt::format("{}: segment table, field {}: '{}' is not a finite number",
                                  location(source_, lines_.number()), j + 1, fields[j]));
        }
      }
      ++rows;
    }
    if (static_cast<double>(rows) != declared) {
      throw Error(fmt::format(
          "{}: the header says 'Number of segments {}' but the segment table has {} rows",
          location(source_, lines_.number()), declared, rows));
    }
    file_.segments = rows;
    // Column titles: the text lines after the last blank line before the data.
    while (!lines_ended_ && !is_comma_row(line)) {
      if (is_micromag_end_marker(line)) {
        throw Error(fmt::format("{}: the file has a segment table but no data rows",
                                location(source_, lines_.number())));
      }
      if (line.empty()) {
        titles_.clear();
      } else {
        titles_.push_back(raw_line_);
      }
      if (!next_content(line)) break;
    }
    if (lines_ended_) throw_truncated();
    pending_row_ = line;
  }

  void read_data() {
    std::string_view line = *pending_row_;
    file_.first_data_line = lines_.number();
    std::size_t columns = 0;
    bool segment_break = true;
    while (true) {
      if (line.empty()) {
        segment_break = true;
      } else if (is_micromag_end_marker(line)) {
        break;
      } else {
        if (!is_comma_row(line)) {
          throw Error(fmt::format(
              "{}: '{}' is not a data row ({} comma-separated numbers) nor the end marker "
              "'MicroMag 2900/3900 Data File ends'",
              location(source_, lines_.number()), line, columns));
        }
        const auto fields = detail::split_fields(line, ',');
        if (columns == 0) {
          columns = fields.size();
          if (columns < 2) {
            throw Error(fmt::format("{}: a data row needs at least field and moment, got '{}'",
                                    location(source_, lines_.number()), line));
          }
          file_.columns = column_names(titles_, columns);
          file_.values.resize(columns);
        }
        if (fields.size() != columns) {
          throw Error(fmt::format("{}: {} fields, but the first data row (line {}) has {}",
                                  location(source_, lines_.number()), fields.size(),
                                  file_.first_data_line, columns));
        }
        if (segment_break) file_.segment_starts.push_back(file_.values[0].size());
        segment_break = false;
        for (std::size_t j = 0; j < columns; ++j) {
          const auto value = parse_number(fields[j]);
          if (!value) {
            throw Error(fmt::format("{}: column {} ('{}'): '{}' is not a finite number",
                                    location(source_, lines_.number()), j + 1, file_.columns[j],
                                    fields[j]));
          }
          file_.values[j].push_back(*value);
        }
      }
      if (!next_content(line)) throw_truncated();
    }
  }

  void check_point_count() const {
    const auto declared = file_.header_number("Number of data");
    if (declared && *declared != static_cast<double>(file_.points())) {
      throw Error(
          fmt::format("{}: the header says 'Number of data {}' but the file has {} data rows",
                      source_, *declared, file_.points()));
    }
  }

  [[noreturn]] void throw_truncated() const {
    throw Error(fmt::format(
        "{}: the file ends without the line 'MicroMag 2900/3900 Data File ends' (truncated?)",
        location(source_, lines_.number())));
  }

  //! The next line, trimmed (raw_line_ keeps it untrimmed for the title alignment).
  bool next_content(std::string_view& line) {
    if (!lines_.next(raw_line_)) {
      lines_ended_ = true;
      return false;
    }
    line = trim(raw_line_);
    return true;
  }

  detail::LineReader lines_;
  std::string_view source_;
  MicromagLoopFile file_;
  std::string_view raw_line_;
  bool lines_ended_ = false;
  std::optional<std::string_view> pending_row_;  //!< a comma row read ahead
  std::vector<std::string_view> titles_;         //!< title lines above the table being read
};

}  // namespace

std::optional<std::string> MicromagLoopFile::header_text(std::string_view key) const {
  return detail::entry_text(header, key);
}

std::optional<double> MicromagLoopFile::header_number(std::string_view key) const {
  return detail::entry_number(header, key);
}

const std::vector<double>& MicromagLoopFile::column(std::string_view name) const {
  const auto found = std::find(columns.begin(), columns.end(), name);
  if (found == columns.end()) {
    throw Error(
        fmt::format("{}: no column '{}' (columns: {})", source, name, fmt::join(columns, ", ")));
  }
  return values[static_cast<std::size_t>(found - columns.begin())];
}

Table MicromagLoopFile::to_table() const {
  Table table;
  table.source = source;
  for (std::size_t j = 0; j < columns.size(); ++j)
    table.add_column(columns[j], values[j]);
  return table;
}

bool looks_like_micromag_loop(std::string_view text) {
  detail::LineReader lines(text);
  std::string_view first;
  std::string_view second;
  return lines.next(first) && is_micromag_format_line(first) && lines.next(second) &&
         second.find("Hysteresis loop") != std::string_view::npos;
}

MicromagLoopFile parse_micromag_loop(std::string_view text, std::string_view source_name) {
  check_text_encoding(text, source_name);
  return LoopParser(text, source_name).parse();
}

MicromagLoopFile read_micromag_loop(const std::filesystem::path& path) {
  return parse_micromag_loop(read_file(path), path.string());
}

}  // namespace hyst::io
