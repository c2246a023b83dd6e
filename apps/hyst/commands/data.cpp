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
#include "hyst/data/loop_metrics.hpp"
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
  std::vector<std::string> loop;  //!< {input, output}: also the loop figures of every cycle
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

const InfoColumn* find_column(const InfoTable& table, std::string_view name) {
  for (const auto& column : table.columns) {
    const auto header = column.unit.empty() ? column.name : column.name + " [" + column.unit + "]";
    if (column.name == name || header == name) return &column;
  }
  return nullptr;
}

//! The figures of every cycle of the (input, output) loop of a table, or none when the table
//! lacks one of the columns.
std::vector<data::LoopMetrics> loop_figures(const InfoTable& table, const InfoOptions& options) {
  if (options.loop.empty()) return {};
  const auto* input = find_column(table, options.loop[0]);
  const auto* output = find_column(table, options.loop[1]);
  if (!input || !output || input->values.size() != output->values.size() ||
      input->values.size() < 3) {
    return {};
  }
  const auto f = figures(input->values, options.band_fraction);
  if (!f.cycles) return {};
  return data::cycle_metrics(input->values, output->values,
                             options.band_fraction * (f.max - f.min));
}

std::string crossings_text(const std::vector<data::LevelCrossing>& crossings) {
  std::string text;
  for (const auto& crossing : crossings) {
    text += fmt::format("{}{:.6g} ({})", text.empty() ? "" : ", ", crossing.value,
                        crossing.direction == data::Direction::ascending ? "up" : "down");
  }
  return text.empty() ? std::string("none") : text;
}

void run_info(const InfoOptions& options) {
  if (!(options.band_fraction > 0.0 && options.band_fraction < 1.0)) {
    throw Error(fmt::format("--band-fraction {} must be > 0 and < 1", options.band_fraction));
  }
  if (!options.loop.empty() && options.loop.size() != 2) {
    throw Error(
        fmt::format("--loop expects two columns INPUT,OUTPUT, got {}", options.loop.size()));
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
      for (const auto& m : loop_figures(table, options)) {
        auto crossings = [](const std::vector<data::LevelCrossing>& list) {
          auto array = nlohmann::json::array();
          for (const auto& c : list) {
            array.push_back({{"value", c.value},
                             {"index", c.index},
                             {"direction", std::string(data::to_string(c.direction))}});
          }
          return array;
        };
        entry["loops"].push_back({{"first", m.first},
                                  {"last", m.last},
                                  {"area", m.area},
                                  {"closure_error", m.closure_error},
                                  {"input_mismatch", m.input_mismatch},
                                  {"coercive_inputs", crossings(m.coercive)},
                                  {"remanent_outputs", crossings(m.remanent)}});
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
    for (const auto& m : loop_figures(table, options)) {
      fmt::print(
          "  loop {} -> {}, samples {}..{}: area {:.6g}, closure error {:.4g} (input mismatch "
          "{:.4g}); coercive inputs {}; remanent outputs {}\n",
          options.loop[0], options.loop[1], m.first, m.last, m.area, m.closure_error,
          m.input_mismatch, crossings_text(m.coercive), crossings_text(m.remanent));
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
  command->footer(R"(Examples:
  hyst data info RMN_TRAP_SLOW.dat --table 6 --loop V+,P1
  hyst data extract RMN_TRAP_SLOW.dat --table 6 --columns V+,P1 --out p.csv
Run 'hyst data info --help' or 'hyst data extract --help' for their options.)");

  auto info = std::make_shared<InfoOptions>();
  auto* info_command = command->add_subcommand(
      "info", "Tables, columns, units, lengths, ranges, reversal points and cycles of a file.");
  info_command->add_option("file", info->file, "CSV, MATLAB .mat or aixACCT export")->required();
  info_command->add_option("--table", info->table, "Only measurement table N of an aixACCT export");
  info_command->add_option("--band-fraction", info->band_fraction,
                           "Hysteresis band for reversals and cycles, as a fraction of each "
                           "column's range (default 0.02)");
  info_command
      ->add_option("--loop", info->loop,
                   "INPUT,OUTPUT: also the loop figures of every cycle (area, closure error, "
                   "coercive inputs at output 0, remanent outputs at input 0)")
      ->delimiter(',');
  info_command->add_flag("--json", info->json, "Print JSON instead of text");
  info_command->footer(R"(Example:
  hyst data info RMN_TRAP_SLOW.dat --table 6
  hyst data info RMN_TRAP_SLOW.dat --loop V+,P1     loop area, coercive and remanent values
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
  hyst data extract RMN_TRAP_SLOW.dat --table 6 --columns V+,P1 --out p.csv
  hyst fit pi --data p.csv --input V+ --output P1 --out p.json)");
  extract_command->callback([extract] { run_extract(*extract); });
}

}  // namespace hyst::cli
