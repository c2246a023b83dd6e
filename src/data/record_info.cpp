#include "hyst/data/record_info.hpp"

#include <algorithm>
#include <string_view>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/data/cycles.hpp"
#include "hyst/data/reversal_points.hpp"
#include "hyst/io/data_file.hpp"

namespace hyst::data {
namespace {

// Metadata keys shown for aixACCT measurement tables.
constexpr std::string_view kHighlights[] = {"SampleName", "Waveform", "Hysteresis Frequency [Hz]",
                                            "Hysteresis Amplitude [V]"};

//! A table with its columns' values, before they are summarised.
struct ReadTable {
  TableInfo info;
  std::vector<std::vector<double>> values;  //!< values[j] belongs to info.columns[j]
};

ReadTable read_table(const io::AixacctTable& table, std::string title) {
  ReadTable read{{std::move(title), {}, {}, table.rows(), {}}, {}};
  for (const auto key : kHighlights) {
    if (const auto value = table.metadata_text(key)) read.info.metadata.emplace_back(key, *value);
  }
  for (const auto& column : table.columns) {
    read.info.columns.push_back(
        {column.name, column.unit, column.values.size(), {}, 0.0, 0.0, {}, {}});
    read.values.push_back(column.values);
  }
  return read;
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
  ReadTable table{{source.is_mat() ? "variables" : "table", {}, {}, 0, {}}, {}};
  for (const auto& name : source.columns()) {
    ColumnInfo column{name, {}, 0, {}, 0.0, 0.0, {}, {}};
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

void summarise(ColumnInfo& column, const std::vector<double>& values, double band_fraction) {
  if (values.empty()) return;
  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  column.min = *lowest;
  column.max = *highest;
  if (values.size() >= 2 && *highest > *lowest) {
    const double band = band_fraction * (*highest - *lowest);
    column.reversals = reversal_points(values, band).size();
    column.cycles = cycles(values, band).size();
  }
}

//! The column named `name` or headed "name [unit]", or nullptr.
const std::vector<double>* find_values(const ReadTable& table, std::string_view name) {
  for (std::size_t j = 0; j < table.info.columns.size(); ++j) {
    const auto& column = table.info.columns[j];
    const auto header = column.unit.empty() ? column.name : column.name + " [" + column.unit + "]";
    if (column.name == name || header == name) return &table.values[j];
  }
  return nullptr;
}

//! The figures of every cycle of the (input, output) loop, or none when the table lacks one of
//! the columns or the input has no cycle.
std::vector<LoopMetrics> loop_figures(const ReadTable& table, const RecordInfoOptions& options) {
  if (!options.loop) return {};
  const auto* input = find_values(table, options.loop->first);
  const auto* output = find_values(table, options.loop->second);
  if (!input || !output || input->size() != output->size() || input->size() < 3) return {};
  ColumnInfo figures;
  summarise(figures, *input, options.band_fraction);
  if (!figures.cycles) return {};
  return cycle_metrics(*input, *output, options.band_fraction * (figures.max - figures.min));
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
  RecordInfo info{path.string(), {}, options.band_fraction, {}};
  for (auto& table : read_tables(path, options, info.format)) {
    for (std::size_t j = 0; j < table.info.columns.size(); ++j)
      summarise(table.info.columns[j], table.values[j], options.band_fraction);
    table.info.loops = loop_figures(table, options);
    info.tables.push_back(std::move(table.info));
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
      }
      entry["columns"].push_back(std::move(c));
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
  return out;
}

}  // namespace hyst::data
