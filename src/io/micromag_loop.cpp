#include "hyst/io/micromag_loop.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "line_reader.hpp"
#include "micromag_columns.hpp"
#include "micromag_lines.hpp"
#include "micromag_sections.hpp"
#include "text_encoding.hpp"
#include "text_fields.hpp"

namespace hyst::io {
namespace {

using detail::is_micromag_end_marker;
using detail::is_micromag_format_line;
using detail::location;
using detail::parse_number;
using detail::trim;

class LoopParser {
 public:
  LoopParser(std::string_view text, std::string_view source)
      : lines_(text), sections_(lines_, source), source_(source) {
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
    file_.title = utf8_from_latin1(trim(line));
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
    file_.segments = sections_.read_head(file_.header);
    read_data();
    check_point_count();
    file_.units = detail::column_units(sections_.titles(), file_.columns.size());
    fill_units_from_header();
    file_.initial_curve_points = initial_curve_points();
    return std::move(file_);
  }

 private:
  void read_data() {
    std::string_view line = sections_.first_row();
    file_.first_data_line = lines_.number();
    std::size_t columns = 0;
    bool segment_break = true;
    while (true) {
      if (line.empty()) {
        segment_break = true;
      } else if (is_micromag_end_marker(line)) {
        break;
      } else {
        if (!detail::is_comma_row(line)) {
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
          file_.columns = detail::column_names(sections_.titles(), columns);
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
      if (!sections_.next_content(line)) sections_.throw_truncated();
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

  // Files without a units line (Series 0015) state the system only: "Hybrid SI" (T, A m^2) or
  // cgs (Oe, emu); a column gets the unit its name implies.
  void fill_units_from_header() {
    const auto system = file_.header_text("Units of measure").value_or("");
    const bool si = system.find("SI") != std::string::npos;
    const bool cgs = system.find("cgs") != std::string::npos ||
                     system.find("CGS") != std::string::npos ||
                     system.find("Cgs") != std::string::npos;
    if (!si && !cgs) return;
    const auto temperature = file_.header_text("Temperature in").value_or("");
    for (std::size_t j = 0; j < file_.columns.size(); ++j) {
      if (!file_.units[j].empty()) continue;
      const auto& name = file_.columns[j];
      if (name.find("Field") != std::string::npos) {
        file_.units[j] = si ? "T" : "Oe";
      } else if (name.find("Moment") != std::string::npos &&
                 name.find("Normalized") == std::string::npos) {
        file_.units[j] = si ? "A m²" : "emu";
      } else if (name.find("Temperature") != std::string::npos) {
        file_.units[j] = temperature == "Kelvin" ? "K" : temperature == "Celsius" ? "°C" : "";
      }
    }
  }

  // "Initial magnetization? Yes": the data start with the initial (virgin) curve from the
  // demagnetised state up to the first turning field, which belongs to no loop cycle. It is the
  // first data block when the branches are apart by blank lines, else the points before the
  // field first turns back.
  std::size_t initial_curve_points() const {
    const auto initial = file_.header_text("Initial magnetization?");
    if (!initial || *initial != "Yes" || file_.points() == 0) return 0;
    if (file_.segment_starts.size() >= 2) return file_.segment_starts[1];
    const auto& field = file_.field();
    const double direction = field.size() >= 2 && field[1] < field[0] ? -1.0 : 1.0;
    std::size_t k = 1;
    while (k < field.size() && direction * (field[k] - field[k - 1]) >= 0.0)
      ++k;
    return k == field.size() ? 0 : k - 1;
  }

  detail::LineReader lines_;
  detail::MicromagSectionReader sections_;
  std::string_view source_;
  MicromagLoopFile file_;
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
