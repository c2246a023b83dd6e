#include "hyst/io/magic_table.hpp"

#include <algorithm>
#include <initializer_list>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "line_reader.hpp"
#include "text_encoding.hpp"
#include "text_fields.hpp"

namespace hyst::io {
namespace {

using detail::location;
using detail::parse_number;
using detail::trim;

std::vector<std::string_view> tab_fields(std::string_view line) {
  return detail::split_fields(line, '\t');
}

//! The first of `names` that the table has (MagIC 2.5 and 3 name columns differently).
std::size_t required_column(const MagicTable& table, std::initializer_list<std::string_view> names,
                            std::string_view meaning) {
  for (const auto name : names) {
    if (const auto index = table.find(name)) return *index;
  }
  throw Error(fmt::format("{}: no column for the {} (looked for '{}')", table.source, meaning,
                          fmt::join(names, "' or '")));
}

}  // namespace

std::optional<std::size_t> MagicTable::find(std::string_view column) const {
  const auto found = std::find(columns.begin(), columns.end(), column);
  if (found == columns.end()) return std::nullopt;
  return static_cast<std::size_t>(found - columns.begin());
}

MagicTable parse_magic_table(std::string_view text, std::string_view source_name) {
  check_text_encoding(text, source_name);
  MagicTable table;
  table.source = std::string(source_name);
  detail::LineReader lines(text);
  std::string_view line;
  const auto kind = lines.next(line) ? tab_fields(line) : std::vector<std::string_view>{};
  if (kind.size() < 2 || !kind[0].starts_with("tab") || kind[1].empty()) {
    throw Error(fmt::format(
        "{}: not a MagIC table (the first line is '{}', expected 'tab', a tab and the table "
        "name, e.g. 'tab\\tmagic_measurements')",
        location(source_name, 1), trim(line)));
  }
  table.name = std::string(kind[1]);
  if (!lines.next(line) || trim(line).empty()) {
    throw Error(fmt::format("{}: no column names after the table name",
                            location(source_name, lines.number())));
  }
  for (const auto name : tab_fields(line)) {
    if (name.empty()) {
      throw Error(fmt::format("{}: column {} has no name", location(source_name, lines.number()),
                              table.columns.size() + 1));
    }
    if (table.find(name)) {
      throw Error(fmt::format("{}: column '{}' appears twice",
                              location(source_name, lines.number()), name));
    }
    table.columns.emplace_back(name);
  }
  while (lines.next(line)) {
    if (trim(line).empty()) continue;
    if (trim(line).starts_with(">>>>>")) break;  // the next table of a multi-table file
    auto cells = tab_fields(line);
    while (cells.size() > table.columns.size() && cells.back().empty())
      cells.pop_back();
    if (cells.size() > table.columns.size()) {
      throw Error(fmt::format("{}: {} cells, but the table has {} columns",
                              location(source_name, lines.number()), cells.size(),
                              table.columns.size()));
    }
    std::vector<std::string> row(table.columns.size());
    std::copy(cells.begin(), cells.end(), row.begin());
    table.rows.push_back(std::move(row));
    table.row_lines.push_back(lines.number());
  }
  return table;
}

MagicTable read_magic_table(const std::filesystem::path& path) {
  return parse_magic_table(read_file(path), path.string());
}

std::vector<MagicHysteresisLoop> magic_hysteresis_loops(const MagicTable& table) {
  const auto methods =
      required_column(table, {"magic_method_codes", "method_codes"}, "method codes");
  const auto experiment =
      required_column(table, {"magic_experiment_name", "experiment"}, "experiment name");
  const auto specimen = required_column(table, {"er_specimen_name", "specimen"}, "specimen");
  const auto field =
      required_column(table, {"measurement_lab_field_dc", "meas_field_dc"}, "applied field");
  const auto moment =
      required_column(table, {"measurement_magn_moment", "magn_moment"}, "magnetic moment");

  std::vector<MagicHysteresisLoop> loops;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto& row = table.rows[i];
    bool is_loop = false;
    std::string_view codes = row[methods];  // "LP-HYS" or e.g. "LP-HYS:FS-FD"
    while (!codes.empty() && !is_loop) {
      const auto colon = std::min(codes.find(':'), codes.size());
      is_loop = trim(codes.substr(0, colon)) == "LP-HYS";
      codes.remove_prefix(std::min(colon + 1, codes.size()));
    }
    if (!is_loop) continue;
    const auto number = [&](std::size_t column) {
      const auto value = parse_number(row[column]);
      if (!value) {
        throw Error(fmt::format("{}: column '{}': '{}' is not a finite number",
                                location(table.source, table.row_lines[i]), table.columns[column],
                                row[column]));
      }
      return *value;
    };
    auto loop = std::find_if(loops.begin(), loops.end(),
                             [&](const auto& l) { return l.experiment == row[experiment]; });
    if (loop == loops.end()) {
      loops.push_back({row[specimen], row[experiment], {}, {}, table.row_lines[i]});
      loop = loops.end() - 1;
    }
    loop->field.push_back(number(field));
    loop->moment.push_back(number(moment));
  }
  return loops;
}

}  // namespace hyst::io
