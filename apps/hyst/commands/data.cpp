// hyst data info FILE: the tables of a measured data file (CSV, MATLAB .mat, aixACCT export),
// their columns with units, lengths and ranges, and the reversal points and cycles of each column.
// hyst data extract FILE: chosen columns of one table as CSV, ready for 'hyst fit'.

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "../data_source.hpp"
#include "commands.hpp"
#include "hyst/data/cycles.hpp"
#include "hyst/data/reversal_points.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/io/mat_file.hpp"

namespace hyst::cli {
namespace {

struct InfoOptions {
  std::string file;
  std::optional<std::size_t> table;
  double band_fraction = 0.02;
  bool json = false;
};

struct ExtractOptions {
  std::string file;
  std::optional<std::size_t> table;
  std::vector<std::string> columns;
  std::string out;
};

struct InfoColumn {
  std::string name;
  std::string unit;
  std::vector<double> values;
  std::string problem;  //!< why the column has no values (a MAT variable that is no vector)
};

struct InfoTable {
  std::string title;  //!< "table 3", "summary", "variables"
  //! A few metadata entries worth a glance (aixACCT: sample, waveform, frequency, amplitude).
  std::vector<std::pair<std::string, std::string>> highlights;
  std::vector<InfoColumn> columns;
};

// Metadata keys shown for aixACCT measurement tables.
constexpr std::string_view kHighlights[] = {"SampleName", "Waveform", "Hysteresis Frequency [Hz]",
                                            "Hysteresis Amplitude [V]"};

InfoTable info_table(const io::AixacctTable& table, std::string title) {
  InfoTable info{std::move(title), {}, {}};
  for (const auto key : kHighlights) {
    if (const auto value = table.metadata_text(key)) info.highlights.emplace_back(key, *value);
  }
  for (const auto& column : table.columns)
    info.columns.push_back({column.name, column.unit, column.values, {}});
  return info;
}

//! Every table of the file: aixACCT summary and measurements, the one CSV table, or the MAT
//! file's variables as one table.
std::vector<InfoTable> read_tables(const InfoOptions& options, std::string& format) {
  std::vector<InfoTable> tables;
  if (const auto file = read_if_aixacct(options.file)) {
    if (options.table) static_cast<void>(file->measurement(*options.table));  // throws if absent
    format = fmt::format("aixACCT export ({}), {}{} measurement tables", file->kind,
                         file->summary ? "a summary table and " : "", file->measurements.size());
    if (file->summary && !options.table) tables.push_back(info_table(*file->summary, "summary"));
    for (const auto& table : file->measurements) {
      if (options.table && table.number != *options.table) continue;
      tables.push_back(info_table(table, fmt::format("table {}", table.number)));
    }
    return tables;
  }
  const DataSource source(options.file, options.table);
  InfoTable table{source.is_mat() ? "variables" : "table", {}, {}};
  for (const auto& name : source.columns()) {
    InfoColumn column{name, {}, {}, {}};
    try {
      column.values = source.column(name);
    } catch (const Error& error) {
      if (!source.is_mat()) throw;
      column.problem = error.what();  // a matrix, a string ...: listed, not used
    }
    table.columns.push_back(std::move(column));
  }
  format = source.is_mat() ? fmt::format("MATLAB .mat file, {} variables", table.columns.size())
                           : fmt::format("CSV, {} columns", table.columns.size());
  tables.push_back(std::move(table));
  return tables;
}

struct ColumnFigures {
  double min = 0.0, max = 0.0;
  std::optional<std::size_t> reversals, cycles;  //!< none for constant or too short columns
};

ColumnFigures figures(const std::vector<double>& values, double band_fraction) {
  ColumnFigures result;
  if (values.empty()) return result;
  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  result.min = *lowest;
  result.max = *highest;
  if (values.size() >= 2 && *highest > *lowest) {
    const double band = band_fraction * (*highest - *lowest);
    result.reversals = data::reversal_points(values, band).size();
    result.cycles = data::cycles(values, band).size();
  }
  return result;
}

std::string count_text(const std::optional<std::size_t>& count) {
  return count ? fmt::format("{}", *count) : std::string("-");
}

void run_info(const InfoOptions& options) {
  if (!(options.band_fraction > 0.0 && options.band_fraction < 1.0)) {
    throw Error(fmt::format("--band-fraction {} must be > 0 and < 1", options.band_fraction));
  }
  std::string format;
  const auto tables = read_tables(options, format);

  if (options.json) {
    nlohmann::json out = {{"file", options.file},
                          {"format", format},
                          {"band_fraction", options.band_fraction},
                          {"tables", nlohmann::json::array()}};
    for (const auto& table : tables) {
      nlohmann::json entry = {{"table", table.title}, {"columns", nlohmann::json::array()}};
      for (const auto& [key, value] : table.highlights)
        entry["metadata"][key] = value;
      for (const auto& column : table.columns) {
        const auto f = figures(column.values, options.band_fraction);
        nlohmann::json c = {
            {"name", column.name}, {"unit", column.unit}, {"samples", column.values.size()}};
        if (!column.problem.empty()) {
          c["problem"] = column.problem;
        } else if (!column.values.empty()) {
          c["min"] = f.min;
          c["max"] = f.max;
          c["reversals"] = f.reversals ? nlohmann::json(*f.reversals) : nlohmann::json();
          c["cycles"] = f.cycles ? nlohmann::json(*f.cycles) : nlohmann::json();
        }
        entry["columns"].push_back(std::move(c));
      }
      out["tables"].push_back(std::move(entry));
    }
    fmt::print("{}\n", out.dump(2));
    return;
  }

  fmt::print("{}: {}\n", options.file, format);
  fmt::print("reversals and cycles with a hysteresis band of {:.3g} % of each column's range\n",
             100.0 * options.band_fraction);
  for (const auto& table : tables) {
    const std::size_t rows = table.columns.empty() ? 0 : table.columns.front().values.size();
    std::string highlights;
    for (const auto& [key, value] : table.highlights)
      highlights += fmt::format("{}{} {}", highlights.empty() ? "; " : ", ", key, value);
    fmt::print("\n{}: {} columns{}{}\n", table.title, table.columns.size(),
               table.title == "variables" ? "" : fmt::format(", {} rows", rows), highlights);
    fmt::print("  {:<22}{:<9}{:>8}{:>14}{:>14}{:>11}{:>8}\n", "column", "unit", "samples", "min",
               "max", "reversals", "cycles");
    for (const auto& column : table.columns) {
      if (!column.problem.empty()) {
        fmt::print("  {:<22}{}\n", column.name, one_line(column.problem));
        continue;
      }
      const auto f = figures(column.values, options.band_fraction);
      fmt::print("  {:<22}{:<9}{:>8}{:>14.6g}{:>14.6g}{:>11}{:>8}\n", column.name, column.unit,
                 column.values.size(), f.min, f.max, count_text(f.reversals), count_text(f.cycles));
    }
  }
}

void run_extract(const ExtractOptions& options) {
  check_output_folder(options.out, "--out");
  const DataSource source(options.file, options.table);
  const auto names = options.columns.empty() ? source.columns() : options.columns;
  io::Table table;
  table.source = options.out;
  std::size_t rows = 0;
  for (const auto& name : names) {
    auto values = source.column(name);
    if (!table.columns.empty() && values.size() != table.rows()) {
      throw Error(
          fmt::format("{}: column '{}' has {} samples but '{}' has {}; extract columns of "
                      "equal length",
                      options.file, name, values.size(), table.names.front(), table.rows()));
    }
    rows = values.size();
    table.add_column(name, std::move(values));
  }
  io::write_csv(options.out, table);
  fmt::print("wrote {}: {} columns ({}), {} rows\n", options.out, table.cols(),
             fmt::join(table.names, ", "), rows);
}

}  // namespace

void add_data_command(CLI::App& app) {
  auto* command = app.add_subcommand(
      "data", "Inspect measured data files (CSV, .mat, aixACCT) and extract columns as CSV.");
  command->require_subcommand(1);

  auto info = std::make_shared<InfoOptions>();
  auto* info_command = command->add_subcommand(
      "info", "Tables, columns, units, lengths, ranges, reversal points and cycles of a file.");
  info_command->add_option("file", info->file, "CSV, MATLAB .mat or aixACCT export")->required();
  info_command->add_option("--table", info->table, "Only measurement table N of an aixACCT export");
  info_command->add_option("--band-fraction", info->band_fraction,
                           "Hysteresis band for reversals and cycles, as a fraction of each "
                           "column's range (default 0.02)");
  info_command->add_flag("--json", info->json, "Print JSON instead of text");
  info_command->footer(R"(Example:
  hyst data info RMN_TRAP_SLOW.dat --table 6
A column's reversals are its turning points that it leaves by more than the band; a cycle is
one period: back to the first value, moving in the first direction.)");
  info_command->callback([info] { run_info(*info); });

  auto extract = std::make_shared<ExtractOptions>();
  auto* extract_command =
      command->add_subcommand("extract", "Write chosen columns of one table as CSV.");
  extract_command->add_option("file", extract->file, "CSV, MATLAB .mat or aixACCT export")
      ->required();
  extract_command->add_option("--table", extract->table,
                              "Measurement table N of an aixACCT export");
  extract_command
      ->add_option("--columns", extract->columns,
                   "Columns (variables) to write, comma separated (default: all); aixACCT "
                   "columns by name (V+) or header (V+ [V])")
      ->delimiter(',');
  extract_command->add_option("--out", extract->out, "CSV file to write")->required();
  extract_command->footer(R"(Example:
  hyst data extract RMN_TRAP_SLOW.dat --table 6 --columns V+,D1 --out pzt.csv
  hyst fit pi --data pzt.csv --input V+ --output D1 --out pzt.json)");
  extract_command->callback([extract] { run_extract(*extract); });
}

}  // namespace hyst::cli
