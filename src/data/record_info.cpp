#include "hyst/data/record_info.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/data/cycles.hpp"
#include "hyst/data/reversal_points.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/data_file.hpp"
#include "hyst/io/micromag_forc.hpp"
#include "hyst/io/micromag_loop.hpp"

namespace hyst::data {
namespace {

// Metadata keys shown for aixACCT measurement tables.
constexpr std::string_view kHighlights[] = {"SampleName", "Waveform", "Hysteresis Frequency [Hz]",
                                            "Hysteresis Amplitude [V]"};

//! A table with its columns' values, before they are summarised.
struct ReadTable {
  TableInfo info;
  std::vector<std::vector<double>> values;  //!< values[j] belongs to info.columns[j]
  std::size_t loop_start = 0;  //!< first row of the loop cycles (after an initial curve)
  bool aixacct = false;        //!< an aixACCT table: its 'Time' column is the default time axis
};

ReadTable read_table(const io::AixacctTable& table, std::string title) {
  ReadTable read{{std::move(title), {}, {}, table.rows(), {}, {}}, {}, 0, true};
  for (const auto key : kHighlights) {
    if (const auto value = table.metadata_text(key)) read.info.metadata.emplace_back(key, *value);
  }
  for (const auto& column : table.columns) {
    read.info.columns.push_back(
        {column.name, column.unit, column.values.size(), {}, 0.0, 0.0, {}, {}, {}, {}});
    read.values.push_back(column.values);
  }
  return read;
}

//! "Series 0016.002" of "MicroMag 2900/3900 Data File (Series 0016.002)".
std::string series_of(std::string_view format) {
  const auto open = format.find('(');
  const auto close = format.rfind(')');
  if (open == std::string_view::npos || close == std::string_view::npos || close < open) {
    return std::string(format);
  }
  return std::string(format.substr(open + 1, close - open - 1));
}

//! A MicroMag loop file's table: units per column, the segments and the initial curve.
ReadTable read_loop_table(const io::MicromagLoopFile& file) {
  ReadTable read{
      {"table", {}, {}, file.points(), {}, {}}, file.values, file.initial_curve_points, false};
  if (const auto system = file.header_text("Units of measure")) {
    read.info.metadata.emplace_back("units of measure", *system);
  }
  read.info.metadata.emplace_back("segments", fmt::format("{}", file.segment_starts.size()));
  if (file.initial_curve_points > 0) {
    read.info.metadata.emplace_back(
        "initial curve",
        fmt::format("rows 0..{} (not part of the loop cycles)", file.initial_curve_points - 1));
  }
  for (std::size_t j = 0; j < file.columns.size(); ++j) {
    read.info.columns.push_back(
        {file.columns[j], file.units[j], file.values[j].size(), {}, 0.0, 0.0, {}, {}, {}, {}});
  }
  return read;
}

ForcInfo forc_info(const io::MicromagForcFile& file) {
  ForcInfo info;
  info.layout = file.layout == io::MicromagForcLayout::series_0015   ? "Series 0015"
                : file.layout == io::MicromagForcLayout::series_0016 ? "Series 0016"
                                                                     : "no header";
  info.curves = file.curves.size();
  info.points = file.points();
  info.calibration_points = file.calibration_points();
  info.field_unit = file.units.size() > 0 ? file.units[0] : "";
  info.moment_unit = file.units.size() > 1 ? file.units[1] : "";
  info.calibration_field = file.header_number("HCal");
  const auto& first = file.curves.front();
  info.fewest_points = info.most_points = first.field.size();
  info.field_min = info.field_max = first.field.front();
  info.reversal_min = info.reversal_max = first.field.front();
  info.calibration_field_min = info.calibration_field_max = first.calibration_field;
  for (const auto& curve : file.curves) {
    info.fewest_points = std::min(info.fewest_points, curve.field.size());
    info.most_points = std::max(info.most_points, curve.field.size());
    const auto [low, high] = std::minmax_element(curve.field.begin(), curve.field.end());
    info.field_min = std::min(info.field_min, *low);
    info.field_max = std::max(info.field_max, *high);
    info.reversal_min = std::min(info.reversal_min, curve.field.front());
    info.reversal_max = std::max(info.reversal_max, curve.field.front());
    info.calibration_field_min = std::min(info.calibration_field_min, curve.calibration_field);
    info.calibration_field_max = std::max(info.calibration_field_max, curve.calibration_field);
  }
  const double last = file.final_calibration ? file.final_calibration->second
                                             : file.curves.back().calibration_moment;
  if (first.calibration_moment != 0.0) {
    info.calibration_drift_percent = 100.0 * (last / first.calibration_moment - 1.0);
  }
  return info;
}

//! Every table of the file: aixACCT summary and measurements, the one CSV table, or the MAT
//! file's variables as one table.
std::vector<ReadTable> read_tables(const std::filesystem::path& path,
                                   const RecordInfoOptions& options, std::string& format) {
  std::vector<ReadTable> tables;
  if (const auto file = io::read_if_aixacct(path)) {
    if (options.table) static_cast<void>(file->measurement(*options.table));  // throws if absent
    format = fmt::format("aixACCT export ({}), {}{} measurement tables", file->kind,
                         file->summary ? "a summary table and " : "", file->measurements.size());
    if (file->summary && !options.table) tables.push_back(read_table(*file->summary, "summary"));
    for (const auto& table : file->measurements) {
      if (options.table && table.number != *options.table) continue;
      tables.push_back(read_table(table, fmt::format("table {}", table.number)));
    }
    return tables;
  }
  const io::DataFile source(path, options.table);
  ReadTable table{{source.is_mat() ? "variables" : "table", {}, {}, 0, {}, {}}, {}, 0, false};
  for (const auto& name : source.columns()) {
    ColumnInfo column{name, {}, 0, {}, 0.0, 0.0, {}, {}, {}, {}};
    std::vector<double> values;
    try {
      values = source.column(name);
    } catch (const Error& error) {
      if (!source.is_mat()) throw;
      column.problem = error.what();  // a matrix, a string ...: listed, not used
    }
    column.samples = values.size();
    table.info.columns.push_back(std::move(column));
    table.values.push_back(std::move(values));
  }
  table.info.rows = table.values.empty() ? 0 : table.values.front().size();
  const auto columns = table.info.columns.size();
  if (source.is_mat()) {
    format = fmt::format("MATLAB .mat file, {} variables", columns);
  } else if (source.is_micromag_loop()) {
    format = fmt::format("MicroMag hysteresis loop file, {} columns", columns);
  } else {
    format = fmt::format("CSV, {} columns", columns);
  }
  tables.push_back(std::move(table));
  return tables;
}

//! Range, reversals and cycles of a column; with `times` (one per value) also its largest rate
//! and its longest run between the same reversal points.
void summarise(ColumnInfo& column, std::span<const double> values, double band_fraction,
               const std::vector<double>* times = nullptr) {
  if (values.empty()) return;
  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  column.min = *lowest;
  column.max = *highest;
  if (values.size() < 2 || !(*highest > *lowest)) return;
  const double band = band_fraction * (*highest - *lowest);
  const auto reversals = reversal_points(values, band);
  column.reversals = reversals.size();
  column.cycles = cycles(values, band).size();
  if (times == nullptr || times->size() != values.size()) return;
  const auto& t = *times;
  double rate = 0.0;
  for (std::size_t k = 1; k < values.size(); ++k)
    rate = std::max(rate, std::abs(values[k] - values[k - 1]) / (t[k] - t[k - 1]));
  column.largest_rate = rate;
  // Runs between the reversal points, and from the start and to the end of the record.
  double run = 0.0;
  std::size_t begin = 0;
  for (const auto& point : reversals) {
    run = std::max(run, t[point.index] - t[begin]);
    begin = point.index;
  }
  column.longest_run = std::max(run, t.back() - t[begin]);
}

//! The index of the column named `name` or headed "name [unit]", or none.
std::optional<std::size_t> column_index(const ReadTable& table, std::string_view name) {
  for (std::size_t j = 0; j < table.info.columns.size(); ++j) {
    const auto& column = table.info.columns[j];
    const auto header = column.unit.empty() ? column.name : column.name + " [" + column.unit + "]";
    if (column.name == name || header == name) return j;
  }
  return std::nullopt;
}

//! The column named `name` or headed "name [unit]", or nullptr.
const std::vector<double>* find_values(const ReadTable& table, std::string_view name) {
  const auto j = column_index(table, name);
  return j ? &table.values[*j] : nullptr;
}

//! The index of the table's time column (options.time, else an aixACCT table's 'Time') with its
//! axis, or none when the table has no such column.
std::optional<std::pair<std::size_t, TimeAxisInfo>> time_axis_of(const ReadTable& table,
                                                                 const RecordInfoOptions& options,
                                                                 const std::string& file) {
  if (options.time.empty() && !table.aixacct) return std::nullopt;
  const std::string name = options.time.empty() ? "Time" : options.time;
  const auto t = column_index(table, name);
  if (!t || !table.info.columns[*t].problem.empty()) return std::nullopt;
  const auto& times = table.values[*t];
  const auto axis =
      time_axis(times, fmt::format("{}: {} time column '{}'", file, table.info.title, name));
  TimeAxisInfo info{name,
                    axis.uniform(),
                    axis.sample_time,
                    axis.sample_time,
                    axis.sample_time,
                    times.back() - times.front()};
  for (std::size_t k = 1; k < times.size(); ++k) {
    info.min_step = std::min(info.min_step, times[k] - times[k - 1]);
    info.max_step = std::max(info.max_step, times[k] - times[k - 1]);
  }
  return std::pair{*t, info};
}

//! The figures of every cycle of the (input, output) loop, or none when the table lacks one of
//! the columns or the input has no cycle.
std::vector<LoopMetrics> loop_figures(const ReadTable& table, const RecordInfoOptions& options) {
  if (!options.loop) return {};
  const auto* input = find_values(table, options.loop->first);
  const auto* output = find_values(table, options.loop->second);
  if (!input || !output || input->size() != output->size()) return {};
  // The cycles start after an initial (virgin) curve: it starts from the demagnetised state and
  // would make the first cycle a mix of it and the loop.
  const std::size_t start = std::min(table.loop_start, input->size());
  const std::span<const double> loop_input(input->data() + start, input->size() - start);
  const std::span<const double> loop_output(output->data() + start, output->size() - start);
  if (loop_input.size() < 3) return {};
  ColumnInfo figures;
  summarise(figures, loop_input, options.band_fraction);
  if (!figures.cycles) return {};
  auto metrics =
      cycle_metrics(loop_input, loop_output, options.band_fraction * (figures.max - figures.min));
  for (auto& m : metrics) {  // rows of the file
    m.first += start;
    m.last += start;
    for (auto& crossing : m.coercive)
      crossing.index += start;
    for (auto& crossing : m.remanent)
      crossing.index += start;
  }
  return metrics;
}

nlohmann::json crossings_json(const std::vector<LevelCrossing>& crossings) {
  auto array = nlohmann::json::array();
  for (const auto& c : crossings) {
    array.push_back({{"value", c.value},
                     {"index", c.index},
                     {"direction", std::string(to_string(c.direction))}});
  }
  return array;
}

nlohmann::json count_json(const std::optional<std::size_t>& count) {
  return count ? nlohmann::json(*count) : nlohmann::json();
}

}  // namespace

RecordInfo record_info(const std::filesystem::path& path, const RecordInfoOptions& options) {
  if (!(options.band_fraction > 0.0 && options.band_fraction < 1.0)) {
    throw Error(fmt::format("band fraction {} must be > 0 and < 1", options.band_fraction),
                "band_fraction");
  }
  RecordInfo info{path.string(), {}, options.band_fraction, {}, {}};
  std::vector<ReadTable> tables;
  if (!io::has_mat_extension(path)) {
    const auto text = io::read_file(path);
    if (io::looks_like_micromag_forc(text)) {
      if (options.table) {
        throw Error(fmt::format(
            "{}: --table (Python: table=) chooses a table of an aixACCT export; this file is a "
            "MicroMag FORC file",
            path.string()));
      }
      const auto file = io::parse_micromag_forc(text, path.string());
      info.format = fmt::format("MicroMag FORC file, {} curves ({})", file.curves.size(),
                                series_of(file.format));
      info.forc = forc_info(file);
      return info;
    }
    if (io::looks_like_micromag_loop(text)) {
      if (options.table) {
        throw Error(fmt::format(
            "{}: --table (Python: table=) chooses a table of an aixACCT export; this file is a "
            "MicroMag loop file",
            path.string()));
      }
      const auto file = io::parse_micromag_loop(text, path.string());
      info.format = fmt::format("MicroMag hysteresis loop file, {} columns ({})",
                                file.columns.size(), series_of(file.format));
      tables.push_back(read_loop_table(file));
    }
  }
  if (tables.empty()) tables = read_tables(path, options, info.format);
  bool timed = false;
  for (auto& table : tables) {
    const auto time = time_axis_of(table, options, path.string());
    if (time) table.info.time = time->second;
    for (std::size_t j = 0; j < table.info.columns.size(); ++j) {
      const bool timed_column = time && j != time->first;
      summarise(table.info.columns[j], table.values[j], options.band_fraction,
                timed_column ? &table.values[time->first] : nullptr);
    }
    table.info.loops = loop_figures(table, options);
    timed = timed || time.has_value();
    info.tables.push_back(std::move(table.info));
  }
  if (!options.time.empty() && !timed) {
    throw Error(fmt::format("{}: no table has the time column '{}'", path.string(), options.time),
                "time");
  }
  return info;
}

nlohmann::json record_info_json(const RecordInfo& info) {
  nlohmann::json out = {{"file", info.file},
                        {"format", info.format},
                        {"band_fraction", info.band_fraction},
                        {"tables", nlohmann::json::array()}};
  for (const auto& table : info.tables) {
    nlohmann::json entry = {{"table", table.title}, {"columns", nlohmann::json::array()}};
    for (const auto& [key, value] : table.metadata)
      entry["metadata"][key] = value;
    for (const auto& column : table.columns) {
      nlohmann::json c = {
          {"name", column.name}, {"unit", column.unit}, {"samples", column.samples}};
      if (!column.problem.empty()) {
        c["problem"] = column.problem;
      } else if (column.samples > 0) {
        c["min"] = column.min;
        c["max"] = column.max;
        c["reversals"] = count_json(column.reversals);
        c["cycles"] = count_json(column.cycles);
        if (column.largest_rate) c["largest_rate"] = *column.largest_rate;
        if (column.longest_run) c["longest_run"] = *column.longest_run;
      }
      entry["columns"].push_back(std::move(c));
    }
    if (const auto& t = table.time) {
      entry["time"] = {{"column", t->column},           {"uniform", t->uniform},
                       {"sample_time", t->sample_time}, {"min_step", t->min_step},
                       {"max_step", t->max_step},       {"duration", t->duration}};
    }
    for (const auto& m : table.loops) {
      entry["loops"].push_back({{"first", m.first},
                                {"last", m.last},
                                {"area", m.area},
                                {"closure_error", m.closure_error},
                                {"input_mismatch", m.input_mismatch},
                                {"coercive_inputs", crossings_json(m.coercive)},
                                {"remanent_outputs", crossings_json(m.remanent)}});
    }
    out["tables"].push_back(std::move(entry));
  }
  if (info.forc) {
    const auto& f = *info.forc;
    out["forc"] = {{"layout", f.layout},
                   {"curves", f.curves},
                   {"points", f.points},
                   {"calibration_points", f.calibration_points},
                   {"fewest_points", f.fewest_points},
                   {"most_points", f.most_points},
                   {"field_min", f.field_min},
                   {"field_max", f.field_max},
                   {"reversal_min", f.reversal_min},
                   {"reversal_max", f.reversal_max},
                   {"calibration_field",
                    f.calibration_field ? nlohmann::json(*f.calibration_field) : nlohmann::json()},
                   {"calibration_field_min", f.calibration_field_min},
                   {"calibration_field_max", f.calibration_field_max},
                   {"calibration_drift_percent", f.calibration_drift_percent},
                   {"field_unit", f.field_unit},
                   {"moment_unit", f.moment_unit}};
  }
  return out;
}

}  // namespace hyst::data
