// hyst data info FILE: the tables of a measured data file (CSV, MATLAB .mat, aixACCT export,
// MicroMag loop file), their columns with units, lengths and ranges, and the reversal points and
// cycles of each column; for a MicroMag FORC file its curves.
// hyst data extract FILE: chosen columns of one table as CSV, ready for 'hyst fit'.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.hpp"
#include "hyst/core/error.hpp"
#include "hyst/data/record_info.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/io/data_file.hpp"

namespace hyst::cli {
namespace {

struct DataInfoOptions {
  std::string file;
  std::optional<std::size_t> table;
  double band_fraction = 0.02;
  std::vector<std::string> loop;  //!< {input, output}: also the loop figures of every cycle
  std::string time;               //!< --time COLUMN
  bool json = false;
};

struct ExtractOptions {
  std::string file;
  std::optional<std::size_t> table;
  std::vector<std::string> columns;
  std::string out;
};

std::string count_text(const std::optional<std::size_t>& count) {
  return count ? fmt::format("{}", *count) : std::string("-");
}

std::string crossings_text(const std::vector<data::LevelCrossing>& crossings) {
  std::string text;
  for (const auto& crossing : crossings) {
    text += fmt::format("{}{:.6g} ({})", text.empty() ? "" : ", ", crossing.value,
                        crossing.direction == data::Direction::ascending ? "up" : "down");
  }
  return text.empty() ? std::string("none") : text;
}

std::string with_unit(double value, const std::string& unit) {
  return unit.empty() ? fmt::format("{:.6g}", value) : fmt::format("{:.6g} {}", value, unit);
}

void print_forc(const data::ForcInfo& f) {
  fmt::print("layout {}; first-order reversal curves, each after a drift-calibration point\n",
             f.layout);
  fmt::print("  curves              {} ({} to {} points each)\n", f.curves, f.fewest_points,
             f.most_points);
  fmt::print("  points              {} (and {} calibration points)\n", f.points,
             f.calibration_points);
  fmt::print("  field               {} .. {}\n", with_unit(f.field_min, f.field_unit),
             with_unit(f.field_max, f.field_unit));
  fmt::print("  reversal fields     {} .. {}\n", with_unit(f.reversal_min, f.field_unit),
             with_unit(f.reversal_max, f.field_unit));
  fmt::print("  calibration field   {} (header HCal), measured at {} .. {}\n",
             f.calibration_field ? with_unit(*f.calibration_field, f.field_unit) : "-",
             with_unit(f.calibration_field_min, f.field_unit),
             with_unit(f.calibration_field_max, f.field_unit));
  fmt::print("  calibration drift   {:+.3g} % of the calibration moment over the run\n",
             f.calibration_drift_percent);
  fmt::print("  moment unit         {}\n", f.moment_unit.empty() ? "-" : f.moment_unit);
}

void run_info(const DataInfoOptions& options) {
  if (!options.loop.empty() && options.loop.size() != 2) {
    throw Error(
        fmt::format("--loop expects two columns INPUT,OUTPUT, got {}", options.loop.size()));
  }
  data::RecordInfoOptions request;
  request.table = options.table;
  request.band_fraction = options.band_fraction;
  if (!options.loop.empty()) request.loop.emplace(options.loop[0], options.loop[1]);
  request.time = options.time;
  const auto info = data::record_info(options.file, request);

  if (options.json) {
    fmt::print("{}\n", data::record_info_json(info).dump(2));
    return;
  }

  fmt::print("{}: {}\n", info.file, info.format);
  if (info.forc) {
    print_forc(*info.forc);
    return;
  }
  fmt::print("reversals and cycles with a hysteresis band of {:.3g} % of each column's range\n",
             100.0 * options.band_fraction);
  for (const auto& table : info.tables) {
    std::string highlights;
    for (const auto& [key, value] : table.metadata)
      highlights += fmt::format("{}{} {}", highlights.empty() ? "; " : ", ", key, value);
    fmt::print("\n{}: {} columns{}{}\n", table.title, table.columns.size(),
               table.title == "variables" ? "" : fmt::format(", {} rows", table.rows), highlights);
    if (const auto& t = table.time) {
      fmt::print("  time axis: column '{}', {}, duration {:.6g} s\n", t->column,
                 t->uniform ? fmt::format("uniform, sample time {:.6g} s", t->sample_time)
                            : fmt::format("not uniform: median step {:.6g} s, steps {:.6g} .. "
                                          "{:.6g} s",
                                          t->sample_time, t->min_step, t->max_step),
                 t->duration);
    }
    const std::string timing =
        table.time ? fmt::format("{:>16}{:>17}", "max rate [/s]", "longest run [s]") : "";
    fmt::print("  {:<22}{:<9}{:>8}{:>14}{:>14}{:>11}{:>8}{}\n", "column", "unit", "samples", "min",
               "max", "reversals", "cycles", timing);
    for (const auto& column : table.columns) {
      if (!column.problem.empty()) {
        fmt::print("  {:<22}{}\n", column.name, one_line(column.problem));
        continue;
      }
      const std::string rates =
          column.largest_rate
              ? fmt::format("{:>16.6g}{:>17.6g}", *column.largest_rate, *column.longest_run)
              : "";
      fmt::print("  {:<22}{:<9}{:>8}{:>14.6g}{:>14.6g}{:>11}{:>8}{}\n", column.name, column.unit,
                 column.samples, column.min, column.max, count_text(column.reversals),
                 count_text(column.cycles), rates);
    }
    for (const auto& m : table.loops) {
      fmt::print(
          "  loop {} -> {}, samples {}..{}: area {:.6g}, closure error {:.4g} (input mismatch "
          "{:.4g}); coercive inputs {}; remanent outputs {}\n",
          options.loop[0], options.loop[1], m.first, m.last, m.area, m.closure_error,
          m.input_mismatch, crossings_text(m.coercive), crossings_text(m.remanent));
    }
  }
}

void run_extract(const ExtractOptions& options) {
  io::check_outputs({{options.file, "FILE"}}, {{options.out, "--out"}});
  auto table = io::DataFile(options.file, options.table).columns_table(options.columns);
  table.source = options.out;
  write_text_output(options.out, io::format_csv(table));
  fmt::print(message_stream(is_stdout(options.out)), "wrote {}: {} columns ({}), {} rows\n",
             options.out, table.cols(), fmt::join(table.names, ", "), table.rows());
}

}  // namespace

void add_data_command(CLI::App& app) {
  auto* command = app.add_subcommand("data",
                                     "Inspect measured data files (CSV, .mat, aixACCT, MicroMag "
                                     "loop and FORC) and extract columns as CSV.");
  command->require_subcommand(1);
  command->footer(R"(Examples:
  hyst data info RMN_TRAP_SLOW.dat --table 6 --loop V+,P1
  hyst data extract RMN_TRAP_SLOW.dat --table 6 --columns V+,P1 --out p.csv
Run 'hyst data info --help' or 'hyst data extract --help' for their options.)");

  auto info = std::make_shared<DataInfoOptions>();
  auto* info_command = command->add_subcommand(
      "info", "Tables, columns, units, lengths, ranges, reversal points and cycles of a file.");
  info_command
      ->add_option("file", info->file,
                   "CSV, MATLAB .mat, aixACCT export, MicroMag loop or FORC file")
      ->required();
  info_command->add_option("--table", info->table, "Only measurement table N of an aixACCT export");
  info_command->add_option("--band-fraction", info->band_fraction,
                           "Hysteresis band for reversals and cycles, as a fraction of each "
                           "column's range (default 0.02)");
  info_command
      ->add_option("--loop", info->loop,
                   "INPUT,OUTPUT: also the loop figures of every cycle (area, closure error, "
                   "coercive inputs at output 0, remanent outputs at input 0)")
      ->delimiter(',');
  info_command->add_option("--time", info->time,
                           "Time column [s] (default: an aixACCT table's 'Time'): each table's "
                           "time axis, and each column's largest rate and longest run between "
                           "reversals");
  info_command->add_flag("--json", info->json, "Print JSON instead of text");
  info_command->footer(R"(Example:
  hyst data info RMN_TRAP_SLOW.dat --table 6
  hyst data info RMN_TRAP_SLOW.dat --loop V+,P1     loop area, coercive and remanent values
  hyst data info conventional_example.forc         FORC curves, fields, calibration points
  hyst data info record.csv --time t               sample time, rates, longest ramps and holds
A MicroMag loop file's initial (virgin) curve is left out of the loop cycles.
A column's reversals are its turning points that it leaves by more than the band; a cycle is
one period: back to the first value, moving in the first direction. With a time axis, a
column's longest run is the longest time between its reversal points (or the record's ends):
the longest ramp or hold a model fitted on it has seen; the time axis is uniform when every
step is within 0.1 % of the median step.)");
  info_command->callback([info] { run_info(*info); });

  auto extract = std::make_shared<ExtractOptions>();
  auto* extract_command =
      command->add_subcommand("extract", "Write chosen columns of one table as CSV.");
  extract_command
      ->add_option("file", extract->file, "CSV, MATLAB .mat, aixACCT export or MicroMag loop file")
      ->required();
  extract_command->add_option("--table", extract->table,
                              "Measurement table N of an aixACCT export");
  extract_command
      ->add_option("--columns", extract->columns,
                   "Columns (variables) to write, comma separated (default: all); aixACCT "
                   "columns by name (V+) or header (V+ [V])")
      ->delimiter(',');
  extract_command->add_option("--out", extract->out, "CSV file to write ('-': standard output)")
      ->required();
  extract_command->footer(R"(Example:
  hyst data extract RMN_TRAP_SLOW.dat --table 6 --columns V+,P1 --out p.csv
  hyst fit pi --data p.csv --input V+ --output P1 --out p.json)");
  extract_command->callback([extract] { run_extract(*extract); });
}

}  // namespace hyst::cli
