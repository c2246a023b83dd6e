// hyst fit: identifies a registered model from measured input/output data and saves the model file
// with the fit report in its "info" object.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "../data_source.hpp"
#include "commands.hpp"
#include "fit_forc.hpp"
#include "fitted_model_output.hpp"
#include "hyst/data/preprocessing.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/io/limits.hpp"
#include "hyst/registry/forc_fit.hpp"
#include "hyst/registry/model_registry.hpp"
#include "progress_display.hpp"

namespace hyst::cli {
namespace {

struct FitOptions {
  std::string model;
  std::string data;
  std::string input;
  std::string output;
  std::string out;
  std::optional<double> validate_fraction;
  std::string validation_data;
  std::string validation_input;
  std::string validation_output;
  std::string options_json;
  std::vector<std::string> option_pairs;
  std::string report;
  std::optional<std::size_t> table;
  std::optional<std::size_t> validation_table;
  std::string validation_start = "rest";
  std::string validation_align = "none";
  std::string cycles;
  bool detrend = false;
  std::string resample;
  double band = 0.0;
  std::string forc;  //!< --forc FILE: the FORC route (fit_forc.hpp)
  std::string drift = "none";
  std::size_t hold_out_every = 0;
  std::string time;          //!< --time COLUMN: the record's sample time from its time column
  double sample_time = 0.0;  //!< --sample-time SECONDS (0: not given)
  std::string tables;        //!< --tables 6,1: several tables of an aixACCT export fitted together
  bool units_intended = false;  //!< --units-intended: fit despite units unlike the model's
  ProgressFlags progress;
};

//! A unit as files write it, for comparison: blanks and '^' left out, "²" as 2 ("A m²" = "Am2").
std::string unit_key(std::string_view unit) {
  std::string key;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    if (unit.substr(i).starts_with("\u00b2")) {
      key += '2';
      ++i;  // the two bytes of "²" in UTF-8
    } else if (unit[i] != ' ' && unit[i] != '^') {
      key += unit[i];
    }
  }
  return key;
}

//! How to bring a column in `from` to the model's `to`, for the message; "" without a rule.
std::string unit_conversion(const std::string& from, const std::string& to) {
  const auto f = unit_key(from);
  const auto t = unit_key(to);
  if (t == "A/m") {
    if (f == "T") return "H = B / mu_0: multiply by 1 / mu_0 = 795774.7 A/m per T";
    if (f == "mT") return "H = B / mu_0: multiply by 795.7747 A/m per mT";
    if (f == "Oe") return "multiply by 1000 / (4 pi) = 79.57747 A/m per Oe";
    if (f == "kA/m") return "multiply by 1000";
  }
  if (t == "T") {
    if (f == "Am2" || f == "emu" || f == "Am2/kg" || f == "emu/g") {
      return "a magnetic moment is no flux density: B = mu_0 (H + m / V) needs the sample's "
             "volume V [m^3] (1 emu = 1e-3 A m^2)";
    }
    if (f == "A/m") return "B = mu_0 (H + M) for a magnetisation M [A/m]";
    if (f == "mT") return "multiply by 1e-3";
    if (f == "G") return "multiply by 1e-4 T per G";
  }
  return "";
}

//! The unit the file states for an input or output column, checked against the model's:
//! hyst::Error naming the column, both units and the conversion, unless --units-intended. The
//! stated unit goes into `units` (the model file's info.data.units).
void check_column_unit(const FitOptions& options, const ModelEntry& entry, const DataSource& data,
                       std::string_view role, const std::string& column, const std::string& wanted,
                       nlohmann::json& units) {
  const auto stated = data.unit(column);
  if (stated.empty()) return;
  units[std::string(role)] = stated;
  if (wanted.empty() || unit_key(stated) == unit_key(wanted) || options.units_intended) return;
  const auto how = unit_conversion(stated, wanted);
  throw Error(fmt::format(
      "--{} '{}' of {} is in {}, but model '{}' takes its {} in {}: convert the column{}, or "
      "pass --units-intended to fit the values as they are",
      role, column, data.path().string(), stated, entry.name, role, wanted,
      how.empty() ? "" : fmt::format(" ({})", how)));
}

//! Every column's unit checked (check_column_unit); the units the file states in `data_info`.
void check_units(const FitOptions& options, const ModelEntry& entry, const DataSource& data,
                 const std::string& input, const std::string& output, nlohmann::json& data_info) {
  nlohmann::json units = nlohmann::json::object();
  check_column_unit(options, entry, data, "input", input, entry.input_unit, units);
  check_column_unit(options, entry, data, "output", output, entry.output_unit, units);
  if (units.empty()) return;
  if (options.units_intended) units["intended"] = true;
  data_info["units"] = std::move(units);
}

//! --cycles, --detrend, --resample METHOD[:STEP], --band as data::Preprocessing.
data::Preprocessing preprocessing(const FitOptions& options) {
  data::Preprocessing result;
  if (!(options.band >= 0.0)) {
    throw Error(fmt::format("--band {} must be >= 0 (0: 2 % of the input range)", options.band));
  }
  result.band = options.band;
  result.detrend = options.detrend;
  if (!options.cycles.empty()) {
    try {
      result.cycles = data::cycle_range_from_string(options.cycles);
    } catch (const Error& error) {
      throw Error(fmt::format("--{}", error.what()));  // "--cycles 'x': expected ..."
    }
  }
  if (!options.resample.empty()) {
    const auto colon = options.resample.find(':');
    try {
      result.resample = data::resample_method_from_string(options.resample.substr(0, colon));
    } catch (const Error& error) {
      throw Error(fmt::format("--resample: {}", error.what()));
    }
    if (colon != std::string::npos) {
      const auto text = options.resample.substr(colon + 1);
      std::size_t used = 0;
      try {
        result.resample_step = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != text.size() || !(result.resample_step > 0.0)) {
        throw Error(fmt::format("--resample '{}': the step after ':' must be a number > 0",
                                options.resample));
      }
    }
  }
  return result;
}

//! The fit options: --options (a JSON object), then every --option key=value on top of it. A
//! value is JSON when it parses as JSON (numbers, true, [0, 0.5], "text"), else a plain string.
nlohmann::json fit_options(const FitOptions& options) {
  nlohmann::json json = nlohmann::json::object();
  if (!options.options_json.empty()) {
    json = io::parse_json_text(options.options_json, "--options");
    if (!json.is_object()) {
      throw Error(
          fmt::format("--options: expected a JSON object such as {{\"operators\": 12}}, "
                      "got {}",
                      json.type_name()));
    }
  }
  for (const auto& pair : options.option_pairs) {
    const auto equals = pair.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw Error(fmt::format("--option '{}': expected key=value, e.g. operators=12", pair));
    }
    const auto key = pair.substr(0, equals);
    const auto text = pair.substr(equals + 1);
    io::check_json_text(text, fmt::format("--option '{}'", pair));
    auto value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    json[key] = value.is_discarded() ? nlohmann::json(text) : value;
  }
  return json;
}

std::string models_with_a_sample_time(const ModelRegistry& registry) {
  std::string list;
  for (const auto& entry : registry.entries()) {
    if (fits_sample_time(entry)) list += (list.empty() ? "" : ", ") + entry.name;
  }
  return list;
}

// The columns of `data` whose name says time ("Time", "t", "time [s]", ...), for a hint.
std::string time_like_columns(const DataSource& data) {
  std::string list;
  for (const auto& name : data.columns()) {
    std::string lower;
    for (char c : name.substr(0, name.find(' ')))
      lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "t" || lower == "time" || lower == "t_s" || lower == "time_s")
      list += (list.empty() ? "'" : ", '") + name + "'";
  }
  return list;
}

// The fit option's default sample time as its schema states it.
std::string default_sample_time(const ModelEntry& entry) {
  for (const auto& option : entry.fit_options) {
    if (option.name == "sample_time")
      return option.default_value.empty() ? "1" : option.default_value;
  }
  return "1";
}

//! The fit option sample_time of a model whose fit has one: --sample-time, --time COLUMN, or else
//! the "Time" column of an aixACCT export when the option is not given. Its source goes into
//! `data_info`. Returns the warning for a model fitted without any of them (its time constants
//! then count samples of the default step), said once the fit shows the model depends on time
//! (untimed_fit_warning()); empty otherwise. Throws hyst::Error for a time column that is not
//! uniform, a model without a sample time, or a sample time given twice.
std::string take_sample_time(const FitOptions& options, const ModelEntry& entry,
                             const DataSource& data, nlohmann::json& fit_json,
                             nlohmann::json& data_info) {
  const bool timed = fits_sample_time(entry);
  const bool given = fit_json.contains("sample_time");
  const bool from_option = options.sample_time > 0.0;
  if ((from_option || !options.time.empty()) && !timed) {
    throw Error(
        fmt::format("{}: model '{}' has no sample time (its output depends on the order of the "
                    "samples only); models with one: {}",
                    from_option ? "--sample-time" : "--time", entry.name,
                    models_with_a_sample_time(ModelRegistry::builtin())));
  }
  if (int(given) + int(from_option) + int(!options.time.empty()) > 1) {
    std::vector<std::string> sources;
    if (!options.time.empty()) sources.push_back("--time");
    if (from_option) sources.push_back("--sample-time");
    if (given) sources.push_back("--option sample_time");
    throw Error(
        fmt::format("{} and {} both give the sample time: give one", sources[0], sources[1]));
  }
  if (!timed) return {};
  if (given) {
    data_info["sample_time"] = {{"seconds", fit_json["sample_time"]}, {"source", "--option"}};
    return {};
  }
  if (from_option) {
    fit_json["sample_time"] = options.sample_time;
    data_info["sample_time"] = {{"seconds", options.sample_time}, {"source", "--sample-time"}};
    return {};
  }
  const bool aixacct_time = data.aixacct() != nullptr && data.has_column("Time");
  if (options.time.empty() && (!aixacct_time || !options.resample.empty())) {
    const std::string hint = time_like_columns(data);
    data_info["sample_time"] = {{"seconds", default_sample_time(entry)},
                                {"source", "none given: the fit option's default"}};
    return fmt::format(
        "model '{}' depends on time but {} gives no time axis (--time COLUMN or --sample-time "
        "SECONDS): the sample time is taken as {} s, so its time constants count samples{}",
        entry.name, options.data, default_sample_time(entry),
        hint.empty() ? "" : fmt::format(" (columns that look like time: {})", hint));
  }
  if (!options.resample.empty()) {
    throw Error(
        "--time with --resample: resampling along the input makes the samples "
        "non-uniform in time, so the record has no sample time");
  }
  const std::string column = options.time.empty() ? "Time" : options.time;
  const double sample_time = data::uniform_sample_time(
      data.column(column), fmt::format("{}: time column '{}'", options.data, column));
  fit_json["sample_time"] = sample_time;
  data_info["sample_time"] = {{"seconds", sample_time}, {"column", column}};
  return {};
}

std::string models_that_can_fit(const ModelRegistry& registry) {
  std::string list;
  for (const auto& entry : registry.entries()) {
    if (entry.can_fit()) list += (list.empty() ? "" : ", ") + entry.name;
  }
  return list.empty() ? "none" : list;
}

//! "6,1" as table numbers: at most limits::kMaxFitRecords, none twice.
std::vector<std::size_t> table_list(const std::string& text) {
  const auto count = std::size_t(std::count(text.begin(), text.end(), ',')) + 1;
  if (count > io::limits::kMaxFitRecords) {
    throw Error(fmt::format("--tables: {} tables, more than the limit of {} records of one fit",
                            count, io::limits::kMaxFitRecords));
  }
  std::vector<std::size_t> tables;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const auto comma = std::min(text.find(',', begin), text.size());
    const auto item = text.substr(begin, comma - begin);
    std::size_t used = 0;
    unsigned long value = 0;
    try {
      value = std::stoul(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size() || !std::isdigit(static_cast<unsigned char>(item[0]))) {
      throw Error(
          fmt::format("--tables '{}': expected table numbers separated by commas, e.g. 6,1", text));
    }
    if (std::find(tables.begin(), tables.end(), value) != tables.end()) {
      throw Error(fmt::format("--tables: table {} is given twice", value));
    }
    tables.push_back(value);
    begin = comma + 1;
  }
  return tables;
}

//! --tables: one model fitted to several tables of an aixACCT export together, each at the
//! sample time of its 'Time' column when the model has one (ModelEntry::fit_records).
void run_tables_fit(const FitOptions& options, const ModelEntry& entry) {
  if (options.table || options.validate_fraction || !options.validation_data.empty() ||
      !options.cycles.empty() || options.detrend || !options.resample.empty() ||
      options.band != 0.0 || !options.time.empty()) {
    throw Error(
        "--tables fits the tables as measured, from their own 'Time' columns: it takes no "
        "--table, --validate-fraction, --validation-data, --cycles, --detrend, --resample, --band "
        "or --time (compare a held-out table with 'hyst compare')");
  }
  if (!entry.can_fit_records()) {
    std::string names;
    for (const auto& other : ModelRegistry::builtin().entries()) {
      if (other.can_fit_records()) names += (names.empty() ? "" : ", ") + other.name;
    }
    throw Error(
        fmt::format("--tables: model '{}' has no fit of several records (models with one: {})",
                    entry.name, names));
  }
  const auto tables = table_list(options.tables);
  auto fit_json = fit_options(options);
  std::vector<io::NamedPath> outputs{{options.out, "--out"}};
  if (!options.report.empty()) outputs.push_back({options.report, "--report"});
  io::check_outputs({{options.data, "--data"}}, outputs);

  const bool timed = fits_sample_time(entry);
  if (timed && fit_json.contains("sample_time")) {
    throw Error(
        "--tables takes each table's sample time from its 'Time' column: give no "
        "--option sample_time");
  }
  std::vector<ColumnPair> columns;
  std::vector<double> sample_times;
  nlohmann::json table_info = nlohmann::json::array();
  for (const auto table : tables) {
    const DataSource data(options.data, table);
    columns.push_back(
        read_column_pair(data, options.input, options.output, fmt::format("table {}", table)));
    nlohmann::json info = {{"table", table}, {"samples", columns.back().input.size()}};
    check_units(options, entry, data, options.input, options.output, info);
    if (timed) {
      sample_times.push_back(data::uniform_sample_time(
          data.column("Time"), fmt::format("{}: table {} column 'Time'", options.data, table)));
      info["sample_time"] = sample_times.back();
    }
    table_info.push_back(std::move(info));
  }
  std::vector<FitRecord> records;
  for (const auto& pair : columns)
    records.push_back({pair.input, pair.output});
  ProgressDisplay display("hyst fit", options.progress.mode());
  auto outcome = [&] {
    try {
      return display.run(fmt::format("fitting {} to {} tables", entry.name, records.size()),
                         [&] { return entry.fit_records(records, sample_times, fit_json); });
    } catch (const Error& error) {
      throw Error(
          fmt::format("fitting '{}' to {} tables {} (input '{}', output '{}'): {}", entry.name,
                      options.data, options.tables, options.input, options.output, error.what()),
          error.field());
    }
  }();
  if (outcome.report.termination == Termination::failed) {
    throw Error(fmt::format("fitting '{}' to {} tables {} failed: {}", entry.name, options.data,
                            options.tables, outcome.report.message));
  }
  const nlohmann::json data_info = {{"file", options.data},
                                    {"input", options.input},
                                    {"output", options.output},
                                    {"tables", std::move(table_info)}};
  write_fitted_model(*outcome.model, fit_info_json(outcome.report, data_info, fit_json),
                     outcome.report, options.out, options.report);
}

void run(const FitOptions& options) {
  if (!options.forc.empty()) {
    if (options.table || !options.cycles.empty() || options.detrend || !options.resample.empty() ||
        options.band != 0.0) {
      throw Error(
          "--forc: --table, --cycles, --detrend, --resample and --band prepare time records; a "
          "FORC file's curves are fitted as measured (--drift corrects their drift)");
    }
    run_forc_fit({options.model, options.forc, options.out, options.report, options.drift,
                  options.hold_out_every, fit_options(options)});
    return;
  }
  if (options.data.empty() || options.input.empty() || options.output.empty()) {
    throw Error(
        "hyst fit needs --data, --input and --output (or, for the Preisach model, --forc FILE: "
        "'hyst fit preisach --forc FILE --out m.json')");
  }
  const auto& registry = ModelRegistry::builtin();
  const auto& entry = registry.find(options.model);
  if (!options.tables.empty()) {
    run_tables_fit(options, entry);
    return;
  }
  if (!entry.can_fit()) {
    throw Error(fmt::format("model '{}' cannot be fitted (models that can: {})", entry.name,
                            models_that_can_fit(registry)));
  }
  auto fit_json = fit_options(options);
  std::vector<io::NamedPath> outputs{{options.out, "--out"}};
  if (!options.report.empty()) outputs.push_back({options.report, "--report"});
  std::vector<io::NamedPath> inputs{{options.data, "--data"}};
  if (!options.validation_data.empty()) {
    inputs.push_back({options.validation_data, "--validation-data"});
  }
  io::check_outputs(inputs, outputs);

  const auto prepare = preprocessing(options);
  const DataSource data(options.data, options.table);
  const auto record = read_column_pair(data, options.input, options.output, "data");

  FitRequest request;
  request.input = record.input;
  request.output = record.output;
  nlohmann::json data_info = {{"file", options.data},
                              {"input", options.input},
                              {"output", options.output},
                              {"samples", record.input.size()}};
  if (options.table) data_info["table"] = *options.table;
  check_units(options, entry, data, options.input, options.output, data_info);

  // Validation: the last part of the record, or a separate record.
  std::optional<ColumnPair> held_out;
  if (options.validate_fraction) {
    const double fraction = *options.validate_fraction;
    if (!(fraction > 0.0 && fraction < 1.0)) {
      throw Error(fmt::format("--validate-fraction {} must be > 0 and < 1", fraction));
    }
    const auto samples = record.input.size();
    const auto held = static_cast<std::size_t>(std::llround(fraction * double(samples)));
    if (held < 1 || held >= samples) {
      throw Error(fmt::format(
          "--validate-fraction {} of {} samples leaves {} for validation and {} for fitting; "
          "both need at least one",
          fraction, samples, held, samples - held));
    }
    // The fitter splits the record and predicts the held-out part by continuing the simulation
    // from the state reached at the end of the fit part.
    request.validate_fraction = fraction;
    data_info["validation"] = {{"kind", "last part of the record"}, {"fraction", fraction}};
  } else if (!options.validation_data.empty()) {
    const DataSource validation(options.validation_data, options.validation_table);
    const auto input = options.validation_input.empty() ? options.input : options.validation_input;
    const auto output =
        options.validation_output.empty() ? options.output : options.validation_output;
    held_out = read_column_pair(validation, input, output, "validation data");
    nlohmann::json validation_units;
    check_units(options, entry, validation, input, output, validation_units);
    request.validation_input = held_out->input;
    request.validation_output = held_out->output;
    data_info["validation"] = {{"kind", "separate record"},
                               {"file", options.validation_data},
                               {"input", input},
                               {"output", output},
                               {"samples", held_out->input.size()}};
    if (options.validation_table) data_info["validation"]["table"] = *options.validation_table;
    if (validation_units.contains("units")) {
      data_info["validation"]["units"] = std::move(validation_units["units"]);
    }
    request.validation.start = validation_start_from_string(options.validation_start);
    request.validation.align = validation_alignment_from_string(options.validation_align);
    data_info["validation"]["start"] = options.validation_start;
    data_info["validation"]["align"] = options.validation_align;
  }
  const std::string untimed = take_sample_time(options, entry, data, fit_json, data_info);
  request.options = fit_json;
  request.preprocessing = prepare;

  // The fitters and the preprocessing know the samples, not where they came from (constant data,
  // two samples, a resampling step asking for too many samples): name the data here.
  ProgressDisplay display("hyst fit", options.progress.mode());
  request.progress = display.callback();
  auto outcome = [&] {
    try {
      return display.run(fmt::format("fitting {}", entry.name),
                         [&] { return fit_model(entry, request); });
    } catch (const Error& error) {
      throw Error(fmt::format("fitting '{}' to {} (input '{}', output '{}'{}): {}", entry.name,
                              options.data, options.input, options.output,
                              options.resample.empty() ? "" : ", --resample " + options.resample,
                              error.what()),
                  error.field());
    }
  }();
  const auto& report = outcome.report;
  if (report.termination == Termination::failed) {
    throw Error(
        fmt::format("fitting '{}' to {} failed: {}", entry.name, options.data, report.message));
  }

  // A continuous-time model's time constants are in seconds only with a time axis (a model
  // whose fit option only serves a part, e.g. a leakage term, or a NARX, which states none).
  if (!untimed.empty() && outcome.model->time_dependence() == TimeDependence::continuous)
    warn(untimed);
  write_fitted_model(*outcome.model, fit_info_json(report, data_info, fit_json), report,
                     options.out, options.report);
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto options = std::make_shared<FitOptions>();
  auto* command = app.add_subcommand(
      "fit", "Fit a model to measured input/output data and save it as a model file.");
  command->add_option("model", options->model, "Model name (see 'hyst models')")->required();
  auto* data = command->add_option(
      "--data", options->data,
      "Measured data: CSV, MATLAB .mat, aixACCT export or MicroMag loop file (required unless "
      "--forc)");
  auto* input = command->add_option("--input", options->input, "Input column (variable) of --data");
  auto* output =
      command->add_option("--output", options->output, "Output column (variable) of --data");
  command->add_option("--out", options->out, "Model file to write (JSON; '-': standard output)")
      ->required();
  auto* fraction = command->add_option(
      "--validate-fraction", options->validate_fraction,
      "Hold out the last fraction F (0 < F < 1) of the record for validation (never shuffled)");
  auto* validation =
      command->add_option("--validation-data", options->validation_data,
                          "A separate record for validation (CSV or .mat), e.g. another amplitude");
  command
      ->add_option("--validation-input", options->validation_input,
                   "Input column of --validation-data (default: --input)")
      ->needs(validation);
  command
      ->add_option("--validation-output", options->validation_output,
                   "Output column of --validation-data (default: --output)")
      ->needs(validation);
  fraction->excludes(validation);
  command
      ->add_option("--validation-start", options->validation_start,
                   "State the --validation-data prediction starts from: rest (the model's "
                   "initial state), periodic (the record's own periodic steady state) or "
                   "continue (where the fit record ended)")
      ->capture_default_str()
      ->needs(validation);
  command
      ->add_option("--validation-align", options->validation_align,
                   "none, or first-sample: shift the prediction to the measured first sample "
                   "(records zeroed separately)")
      ->capture_default_str()
      ->needs(validation);
  command->add_option("--options", options->options_json,
                      "Fit options as a JSON object, e.g. '{\"operators\": 12}'");
  command
      ->add_option("--option", options->option_pairs,
                   "One fit option key=value (repeatable; the value is JSON if it parses, "
                   "else a string); applied on top of --options")
      ->allow_extra_args(false);
  command->add_option("--report", options->report,
                      "Also write the full fit report (text; '-': standard output)");
  command->add_option("--table", options->table,
                      "Measurement table N of an aixACCT export (see 'hyst data info FILE')");
  command->add_option("--tables", options->tables,
                      "Several measurement tables N,M,... of an aixACCT export, fitted together "
                      "as one model (one actuator at several rates), each at the sample time of "
                      "its 'Time' column; for the models with a fit of several records "
                      "(pi_creep, modified_pi_creep, butterfly_strain, butterfly_strain_creep)");
  command
      ->add_option("--sample-time", options->sample_time,
                   "Sample time of --data [s] for files without a time column (the fit option "
                   "sample_time)")
      ->check(CLI::PositiveNumber);
  command->add_option("--time", options->time,
                      "Time column of --data [s]: its uniform step is the fit option sample_time "
                      "of a model that has one (an aixACCT export's 'Time' column is used by "
                      "default)");
  command
      ->add_option("--validation-table", options->validation_table,
                   "Measurement table of an aixACCT --validation-data")
      ->needs(validation);
  command->add_option("--cycles", options->cycles,
                      "Fit only cycles N, N-M or N- (1-based periods of the input)");
  add_progress_flags(*command, options->progress);
  command->add_flag("--detrend", options->detrend,
                    "Remove linear drift between cycles so that the loop closes, in --data and in "
                    "the validation record (drift is a measurement artefact)");
  command->add_option("--resample", options->resample,
                      "Resample each branch: input-grid[:STEP] (uniform input) or "
                      "arc-length[:STEP] (uniform normalised arc length)");
  command->add_flag("--units-intended", options->units_intended,
                    "Fit even where --data states units other than the model's (Jiles-Atherton: "
                    "input H in A/m, output B in T; 'hyst models NAME'): the values are meant as "
                    "they are. Without it such data are refused with the conversion to make");
  command->add_option("--band", options->band,
                      "Hysteresis band for reversals and cycles [input units] (default: 2 % of "
                      "the input range)");
  std::string forc_options;
  for (const auto& option : forc_fit_options())
    forc_options += fmt::format("\n  {}: {}", option.name, option.description);
  auto* forc = command->add_option(
      "--forc", options->forc,
      "A MicroMag FORC file (Series 0015 or 0016): identify the Preisach model (model "
      "'tabulated_preisach', a tabulated Everett function) from its first-order reversal "
      "curves. Fit options (--option key=value):" +
          forc_options);
  command
      ->add_option("--drift", options->drift,
                   "With --forc: correct the moments for the drift of the calibration points: "
                   "none, multiplicative (sensitivity) or additive (offset)")
      ->capture_default_str()
      ->needs(forc);
  command
      ->add_option("--hold-out-every", options->hold_out_every,
                   "With --forc: hold out curves N, 2N, 3N, ... (N >= 2) and report how well "
                   "they are predicted")
      ->needs(forc);
  for (auto* excluded : {data, input, output, fraction, validation})
    forc->excludes(excluded);
  command->footer(R"(Examples:
  hyst fit pi --data d.csv --input v --output y --out m.json --validate-fraction 0.2
  hyst fit pi --data MeasurementData.mat --input Vplus_19kv --output Displacement_19kv \
      --validation-data MeasurementData.mat --validation-input Vplus_1kv \
      --validation-output Displacement_1kv --option operators=12 \
      --option initial_state=periodic --out pzt.json --report pzt.txt
  hyst fit pi --data RMN_TRAP_SLOW.dat --table 6 --input V+ --output P1 \
      --detrend --resample input-grid:20 --out pzt.json
  hyst fit pi_creep --data RMN_TRAP_SLOW.dat --table 1 --input V+ --output P1 \
      --option initial_state=periodic --out creep.json   # sample time from 'Time'
  hyst fit modified_pi_creep --data RMN_TRAP_SLOW.dat --tables 6,1 --input V+ --output P1 \
      --option initial_state=periodic --out creep.json   # 1 Hz and 0.1 Hz together
  hyst fit preisach --forc conventional_example.forc --drift multiplicative \
      --hold-out-every 4 --option intervals=32 --out forc.json --report forc.txt
Preprocessing: --detrend, then --cycles, then --resample on --data. A --validation-data
record gets the drift removal only (detrend (fit and validation); cycles and resampling are
fit-only); with --validate-fraction the held-out part is the end of the prepared record. The
fit report lists the steps applied, marked "fit record:", "validation record:" or "fit and
held-out validation part:".
The model file's "info" object holds the fit report; 'hyst info m.json' shows it.
'hyst models NAME' lists the fit options of a model.)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
