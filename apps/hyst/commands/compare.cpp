// hyst compare: fits several models to the same record and ranks them on the same held-out part
// (the logic is hyst::compare_models, identify/compare.hpp); writes the ranking as Markdown and
// CSV and the comparison plots.

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "../data_source.hpp"
#include "../record_time.hpp"
#include "commands.hpp"
#include "hyst/identify/compare.hpp"
#include "hyst/identify/cross_record_compare.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/io/output_set.hpp"
#include "hyst/plot/comparison_html.hpp"
#include "hyst/plot/comparison_plots.hpp"
#include "progress_display.hpp"

namespace hyst::cli {
namespace {

struct CompareCommandOptions {
  std::string data;
  std::string input;
  std::string output;
  std::string models;
  double validate_fraction = 0.25;
  double no_fit_percent = 20.0;
  std::vector<std::string> option_pairs;
  std::string out_dir = ".";
  std::optional<std::size_t> table;
  bool no_plots = false;
  std::string html;
  std::string fit_records;
  std::string validate_records;
  bool leave_one_out = false;
  std::string validation_start = "rest";
  std::string validation_align = "none";
  TimeOptions time;
  std::string input_unit;   //!< --input-unit: in place of the file's
  std::string output_unit;  //!< --output-unit
  bool strict = false;
  ProgressFlags progress;
};

//! The warning (the error with --strict, after the tables are written) when held-out samples
//! leave the domain their models were fitted on; `line` is the tables' own sentence about it.
void report_held_out_domain(const std::string& line, bool strict) {
  if (line.empty()) return;
  if (strict) throw Error(line + " (--strict)");
  warn(line);
}

//! The sample time of the records of `data` (--time, --sample-time, an aixACCT 'Time'
//! column): the models with time in them are fitted at it. Fits need a uniform time axis.
std::optional<double> records_sample_time(const DataSource& data,
                                          const std::optional<RecordTime>& time) {
  if (!time) return std::nullopt;
  if (!time->axis.uniform()) {
    throw Error(
        fmt::format("{}: the {} is not uniform (median step {:.6g} s): the models with "
                    "time in them are fitted at one sample time (resample the record; "
                    "rate-independent models need no --time)",
                    data.path().string(), time->source, time->axis.sample_time));
  }
  return time->axis.sample_time;
}

std::vector<std::string> split_list(const std::string& text, std::string_view option,
                                    std::string_view example) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = std::min(text.find(',', start), text.size());
    const auto item = text.substr(start, comma - start);
    if (item.empty()) {
      throw Error(fmt::format("{} '{}': an empty item (expected e.g. {})", option, text, example));
    }
    items.push_back(item);
    start = comma + 1;
  }
  return items;
}

//! --option MODEL.KEY=VALUE, the value JSON when it parses as JSON, else a string.
std::map<std::string, nlohmann::json> fit_options(const std::vector<std::string>& pairs) {
  std::map<std::string, nlohmann::json> options;
  for (const auto& pair : pairs) {
    const auto dot = pair.find('.');
    const auto equals = pair.find('=');
    if (dot == std::string::npos || equals == std::string::npos || dot == 0 || dot > equals ||
        equals == dot + 1) {
      throw Error(
          fmt::format("--option '{}': expected MODEL.KEY=VALUE, e.g. pi.operators=12", pair));
    }
    const auto model = pair.substr(0, dot);
    const auto key = pair.substr(dot + 1, equals - dot - 1);
    const auto text = pair.substr(equals + 1);
    io::check_json_text(text, fmt::format("--option '{}'", pair));
    auto value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    auto& object = options[model];
    if (object.is_null()) object = nlohmann::json::object();
    object[key] = value.is_discarded() ? nlohmann::json(text) : value;
  }
  return options;
}

//! The records of --fit-records / --validate-records: INPUT:OUTPUT variables of --data, named
//! so in the tables.
std::vector<NamedRecord> read_records(const DataSource& data, const std::string& list,
                                      std::string_view option) {
  std::vector<NamedRecord> records;
  for (const auto& item : split_list(list, option, "Vplus_15kv:Displacement_15kv,v2:y2")) {
    const auto colon = item.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == item.size() ||
        item.find(':', colon + 1) != std::string::npos) {
      throw Error(fmt::format("{} '{}': expected INPUT:OUTPUT, e.g. Vplus_15kv:Displacement_15kv",
                              option, item));
    }
    auto pair = read_column_pair(data, item.substr(0, colon), item.substr(colon + 1), "data");
    records.push_back({item, std::move(pair.input), std::move(pair.output)});
  }
  return records;
}

//! --fit-records with --validate-records or --leave-one-out: the cross-record ranking, tables
//! only.
void run_cross_record(const CompareCommandOptions& options, CrossRecordOptions compare) {
  if (!options.input.empty() || !options.output.empty()) {
    throw Error(
        "--input/--output and --fit-records exclude each other: give the records as "
        "INPUT:OUTPUT in --fit-records");
  }
  if (options.leave_one_out == !options.validate_records.empty()) {
    throw Error("--fit-records needs either --validate-records or --leave-one-out");
  }
  compare.validation.start = validation_start_from_string(options.validation_start);
  compare.validation.align = validation_alignment_from_string(options.validation_align);
  const std::filesystem::path folder = options.out_dir;
  create_output_folder(folder, "--out-dir");
  const std::vector<std::string> names{"ranking.md", "ranking.csv"};
  io::check_outputs({{options.data, "--data"}},
                    {{folder / names[0], "--out-dir"}, {folder / names[1], "--out-dir"}});
  io::OutputSet set(folder, names);
  const DataSource data(options.data, options.table);
  const auto fit = read_records(data, options.fit_records, "--fit-records");
  compare.sample_time =
      records_sample_time(data, record_time(data, options.time, fit.front().input.size()));
  ProgressDisplay display("hyst compare", options.progress.mode());
  compare.progress = display.callback();
  const auto comparison =
      options.leave_one_out
          ? compare_leave_one_out(fit, compare)
          : compare_across_records(
                fit, read_records(data, options.validate_records, "--validate-records"), compare);
  const auto markdown = cross_record_markdown(comparison);
  io::write_file_atomically(set.staged("ranking.md"), markdown);
  io::write_file_atomically(set.staged("ranking.csv"), cross_record_csv(comparison));
  set.publish();
  fmt::print("{}wrote {} and {}\n", markdown, (folder / "ranking.md").string(),
             (folder / "ranking.csv").string());
  bool any_fitted = false;
  for (const auto& row : comparison.ranking) {
    if (!row.ok) warn(fmt::format("model '{}' was not fitted: {}", row.model, row.error));
    any_fitted = any_fitted || row.ok;
  }
  if (!any_fitted) throw Error("no model could be fitted to the records (see the table)");
  report_held_out_domain(held_out_domain_lines(comparison), options.strict);
}

//! Does `file` lie directly in `folder` (the same folder, also through links)?
bool in_folder(const std::filesystem::path& file, const std::filesystem::path& folder) {
  const auto parent = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
  std::error_code error;
  return std::filesystem::equivalent(parent, folder, error) && !error;
}

void run(const CompareCommandOptions& options) {
  if (!options.fit_records.empty()) {
    CrossRecordOptions cross;
    if (!options.models.empty()) cross.models = split_list(options.models, "--models", "pi,narx");
    cross.fit_options = fit_options(options.option_pairs);
    cross.no_fit_percent = options.no_fit_percent;
    run_cross_record(options, std::move(cross));
    return;
  }
  if (options.input.empty() || options.output.empty()) {
    throw Error("give --input and --output (one record, split in time) or --fit-records");
  }
  CompareOptions compare;
  if (!options.models.empty()) compare.models = split_list(options.models, "--models", "pi,narx");
  compare.validate_fraction = options.validate_fraction;
  compare.no_fit_percent = options.no_fit_percent;
  compare.fit_options = fit_options(options.option_pairs);
  const std::filesystem::path folder = options.out_dir;
  create_output_folder(folder, "--out-dir");
  // The files in --out-dir (and --html when it lies there too) are published as one set
  // (hyst/io/output_set.hpp): a reader never sees new rankings beside old plots.
  std::vector<std::string> names{"ranking.md", "ranking.csv"};
  if (!options.no_plots) names.insert(names.end(), {"loops.png", "errors.png"});
  std::vector<io::NamedPath> outputs;
  for (const auto& name : names)
    outputs.push_back({folder / name, "--out-dir"});
  const bool html_on_stdout = is_stdout(options.html);
  const bool html_in_set =
      !options.html.empty() && !html_on_stdout && in_folder(options.html, folder);
  if (html_in_set) names.push_back(std::filesystem::path(options.html).filename().string());
  if (!options.html.empty()) outputs.push_back({options.html, "--html"});
  io::check_outputs({{options.data, "--data"}}, outputs);
  io::OutputSet set(folder, names);

  const DataSource data(options.data, options.table);
  const auto record = read_column_pair(data, options.input, options.output, "data");
  const auto time = record_time(data, options.time, record.input.size());
  compare.sample_time = records_sample_time(data, time);
  ProgressDisplay display("hyst compare", options.progress.mode());
  compare.progress = display.callback();
  const auto comparison = compare_models(record.input, record.output, compare);

  const auto markdown = model_comparison_markdown(comparison);
  io::write_file_atomically(set.staged("ranking.md"), markdown);
  io::write_file_atomically(set.staged("ranking.csv"), model_comparison_csv(comparison));
  auto* messages = message_stream(html_on_stdout);
  fmt::print(messages, "{}", markdown);
  std::string written =
      fmt::format("{} and {}", (folder / "ranking.md").string(), (folder / "ranking.csv").string());
  const bool any_fitted = std::any_of(comparison.ranking.begin(), comparison.ranking.end(),
                                      [](const ComparedModel& row) { return row.ok; });
  if (!options.no_plots && any_fitted) {
    plot::write_model_comparison_plots(comparison, record.input, record.output,
                                       set.staged("loops.png"), set.staged("errors.png"));
    written = fmt::format("{}, {}, {} and {}", (folder / "ranking.md").string(),
                          (folder / "ranking.csv").string(), (folder / "loops.png").string(),
                          (folder / "errors.png").string());
  }
  const auto html_title =
      fmt::format("Model comparison: {} -> {} ({})", options.input, options.output,
                  std::filesystem::path(options.data).filename().string());
  const auto unit_of = [&](const std::string& column, const std::string& given) {
    return given.empty() ? data.unit(column) : given;
  };
  const auto labelled = [&](const std::string& column, const std::string& unit) {
    return unit.empty() ? column : fmt::format("{} [{}]", column, unit);
  };
  const auto output_unit = unit_of(options.output, options.output_unit);
  plot::ComparisonPageLabels labels{
      labelled(options.input, unit_of(options.input, options.input_unit)),
      labelled(options.output, output_unit),
      output_unit,
      {}};
  // The figures over time in seconds when the record has a time axis.
  if (time) {
    labels.time = time->times;
    if (labels.time.empty()) {
      for (std::size_t k = 0; k < record.input.size(); ++k)
        labels.time.push_back(static_cast<double>(k) * time->axis.sample_time);
    }
  }
  if (html_in_set) {
    plot::write_model_comparison_html(set.staged(names.back()), comparison, record.input,
                                      record.output, html_title, labels);
  }
  set.publish();
  if (html_on_stdout) {
    write_text_output(options.html, plot::model_comparison_html(comparison, record.input,
                                                                record.output, html_title, labels));
  } else if (!options.html.empty() && !html_in_set) {
    plot::write_model_comparison_html(options.html, comparison, record.input, record.output,
                                      html_title, labels);
  }
  if (!options.html.empty()) {
    written += fmt::format("; {}", options.html);
  }
  fmt::print(messages, "wrote {}\n", written);
  for (const auto& row : comparison.ranking) {
    if (!row.ok) warn(fmt::format("model '{}' was not fitted: {}", row.model, row.error));
  }
  if (!any_fitted) throw Error("no model could be fitted to the data (see the table)");
  report_held_out_domain(held_out_domain_line(comparison), options.strict);
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareCommandOptions>();
  auto* command = app.add_subcommand(
      "compare", "Fit several models to the same data and rank them on the same held-out part.");
  command
      ->add_option("--data", options->data,
                   "Measured data: CSV, MATLAB .mat, aixACCT export or MicroMag loop file")
      ->required();
  command->add_option("--input", options->input,
                      "Input column (variable) of --data (the time-split ranking)");
  command->add_option("--output", options->output,
                      "Output column (variable) of --data (the time-split ranking)");
  auto* fit_records = command->add_option(
      "--fit-records", options->fit_records,
      "Rank on separate records: the records the models are fitted on, INPUT:OUTPUT variables of "
      "--data, comma-separated (joined in this order)");
  auto* validate_records =
      command
          ->add_option("--validate-records", options->validate_records,
                       "The held-out records the models are ranked on, INPUT:OUTPUT, "
                       "comma-separated")
          ->needs(fit_records);
  command
      ->add_flag("--leave-one-out", options->leave_one_out,
                 "Each record of --fit-records held out in turn, the models fitted on the others; "
                 "the table gives the mean and worst held-out NRMSE")
      ->needs(fit_records)
      ->excludes(validate_records);
  command
      ->add_option("--validation-start", options->validation_start,
                   "State each held-out record's prediction starts from: rest (the model's "
                   "initial state), periodic (the record's own periodic steady state) or "
                   "continue (where the fit records ended)")
      ->capture_default_str()
      ->needs(fit_records);
  command
      ->add_option("--validation-align", options->validation_align,
                   "none, or first-sample: shift each held-out prediction to the measured first "
                   "sample (records zeroed separately)")
      ->capture_default_str()
      ->needs(fit_records);
  command->add_option("--out-dir", options->out_dir,
                      "Folder for ranking.md, ranking.csv, loops.png and errors.png (default: the "
                      "current folder)");
  command->add_option("--models", options->models,
                      "Comma-separated model names (default: every model with a fitter)");
  command
      ->add_option("--validate-fraction", options->validate_fraction,
                   "Last fraction of the record held out for the ranking (default 0.25)")
      ->excludes(fit_records);
  command->add_option("--no-fit-threshold", options->no_fit_percent,
                      "Held-out NRMSE [%] of the best model above which the table says that no "
                      "model describes the record (default 20)");
  command
      ->add_option("--option", options->option_pairs,
                   "A fit option of one model, MODEL.KEY=VALUE (repeatable), e.g. "
                   "pi.operators=12")
      ->allow_extra_args(false);
  command->add_option("--table", options->table,
                      "Measurement table N of an aixACCT export (see 'hyst data info FILE')");
  add_time_options(*command, options->time, "--data");
  command->add_flag("--strict", options->strict,
                    "Exit with status 1 when held-out samples leave the domain a model was "
                    "fitted on (the tables are written; without it, a warning line)");
  command->add_option("--input-unit", options->input_unit,
                      "Unit of the input for the --html page's axes (default: the file's)");
  command->add_option("--output-unit", options->output_unit,
                      "Unit of the output for the --html page's axes and error columns "
                      "(default: the file's)");
  command->add_flag("--no-plots", options->no_plots, "Write the tables only");
  add_progress_flags(*command, options->progress);
  command
      ->add_option("--html", options->html,
                   "Also write one self-contained HTML page with the table and SVG plots ('-': "
                   "standard output; time split only)")
      ->excludes(fit_records);
  command->footer(R"(Examples:
  hyst compare --data d.csv --input v --output y
  hyst compare --data d.csv --input v --output y --out-dir cmp --html cmp/report.html
  hyst compare --data d.csv --input v --output y --models pi,gpi,narx \
      --option narx.hidden_sizes=[6] --out-dir cmp
  hyst compare --data MeasurementData.mat --fit-records Vplus_15kv:Displacement_15kv \
      --validate-records Vplus_1kv:Displacement_1kv,Vplus_11kv:Displacement_11kv \
      --validation-start periodic --validation-align first-sample --out-dir cmp
  hyst compare --data MeasurementData.mat --leave-one-out \
      --fit-records Vplus_08kv:Displacement_08kv,Vplus_1kv:Displacement_1kv,Vplus_15kv:Displacement_15kv
Time split (--input/--output): every model is fitted on the first part of the record and run
in free run over the whole record; the ranking is by the NRMSE [%] on the held-out last part,
which measures extrapolation (the table says so). A model whose fit fails gets a row with the
reason; the others still run. Reference predictors (mean, last value held, cubic y(v),
ARX(2,2)) fitted and scored the same way are the yardstick: the table marks every model that
does not beat the best of them.
Separate records (--fit-records): the fit records are joined in the order given (the model
state runs on across each junction) and every model is fitted once on them; each record of
--validate-records is predicted by the rule of --validation-start/--validation-align (as in
'hyst fit --validation-data'). --leave-one-out holds each record of --fit-records out in turn.
The table ranks by the mean held-out NRMSE [%] and gives the worst and every record's; tables
only (ranking.md, ranking.csv), no plots.
Time: the models with time in them (creep, rate dependence, the Bouc-Wen oscillator; 'hyst
models NAME' lists the fit option sample_time) are fitted at the sample time of --time COLUMN
or --sample-time SECONDS (an aixACCT export's 'Time' column by default), unless --option
MODEL.sample_time=... says otherwise; without any, their time constants count samples.)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
