// hyst evaluate: the score of a dynamic MIMO model file on periodic test data, as the nonlinear
// system identification benchmarks define it (hyst/dynamics/simulation_score.hpp), or of any
// single-input model on a measured record (evaluate_record.hpp).

#include <memory>
#include <optional>
#include <string>
#include <variant>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "../data_source.hpp"
#include "../dynamic_data.hpp"
#include "commands.hpp"
#include "evaluate_record.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/dynamics/free_run_check.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/registry/hysteretic_lfr_file.hpp"
#include "hyst/registry/state_space_file.hpp"

namespace hyst::cli {
namespace {

struct EvaluateOptions {
  std::string model;
  DynamicDataOptions data;
  bool periodic = false;
  std::size_t transient = 0;
  std::size_t init_samples = 0;  //!< --init-samples N: the state from the first N outputs
  bool json = false;
  bool strict = false;
  // Single-input models only:
  std::optional<std::size_t> table;
  std::string validation_start = "rest";
  std::string validation_align = "none";
  TimeOptions time;
};

//! The dynamic MIMO models that can be scored here.
using SystemModel = std::variant<StateSpace, AnyHystereticLfr>;

//! The model of a file when it is a dynamic MIMO model, else nothing (a single-input model).
std::optional<SystemModel> load_system_model(const std::string& path) {
  const auto document = io::parse_json_text(io::read_file(path), path);
  const auto kind =
      document.is_object() && document.contains("model") && document.at("model").is_string()
          ? document.at("model").get<std::string>()
          : std::string();
  if (kind == "state_space") return state_space_from_json(document, path).model;
  if (kind == "hysteretic_lfr") return hysteretic_lfr_from_json(document, path).model;
  return std::nullopt;
}

//! A single-input model scored on one record: one --data, --input and --output column each, and
//! none of the options of periodic MIMO data.
void run_single_input(const EvaluateOptions& options) {
  const auto refused = [&](bool given, std::string_view option, std::string_view instead) {
    if (given)
      throw Error(
          fmt::format("{}: {} is for dynamic multi-input models (state_space, "
                      "hysteretic_lfr); a single-input model is scored on --data with "
                      "--input and --output{}",
                      options.model, option, instead));
  };
  refused(!options.data.input_npy.empty() || !options.data.output_npy.empty(),
          "--input-npy/--output-npy", "");
  refused(options.data.samples_per_period != 0, "--samples-per-period", "");
  refused(options.periodic, "--periodic",
          ", from its periodic steady state with "
          "--validation-start periodic");
  refused(options.transient != 0, "--transient", "");
  refused(options.init_samples != 0, "--init-samples", "");
  if (options.data.data.size() != 1 || options.data.input_columns.empty() ||
      options.data.output_columns.empty())
    throw Error(
        fmt::format("{}: a single-input model is scored on one record: give --data FILE "
                    "--input COLUMN --output COLUMN",
                    options.model));
  evaluate_record({.model = options.model,
                   .data = options.data.data.front(),
                   .table = options.table,
                   .input = options.data.input_columns,
                   .output = options.data.output_columns,
                   .start = options.validation_start,
                   .align = options.validation_align,
                   .time = options.time,
                   .json = options.json,
                   .strict = options.strict});
}

//! A discrete dynamic model runs at its own sample time only: --sample-time, or the step of
//! --time COLUMN of the first --data file, must be it.
void check_system_sample_time(const EvaluateOptions& options, double own) {
  double given = options.time.sample_time;
  std::string source = fmt::format("--sample-time {:g}", given);
  if (!options.time.column.empty()) {
    if (options.data.data.empty())
      throw Error(fmt::format("--time {}: NumPy data have no time column; give --sample-time",
                              options.time.column));
    const DataSource data(options.data.data.front());
    given = data::uniform_sample_time(
        data.column(options.time.column),
        fmt::format("{}: time column '{}'", options.data.data.front(), options.time.column));
    source = fmt::format("time column '{}'", options.time.column);
  }
  if (given > 0.0 && !data::same_sample_time(given, own)) {
    throw Error(
        fmt::format("{}: the model is discrete, identified at the sample time {:.6g} s, "
                    "but the data are sampled at {:.6g} s ({}): resample the data or "
                    "fit the model at {:.6g} s",
                    options.model, own, given, source, given));
  }
}

SimulationScore score(const SystemModel& model, const PeriodicExperiment& experiment,
                      const ScoreOptions& options) {
  if (const auto* linear = std::get_if<StateSpace>(&model))
    return score_state_space(*linear, experiment.input, experiment.output, options);
  return score_hysteretic_lfr(std::get<AnyHystereticLfr>(model), experiment.input,
                              experiment.output, options);
}

const StateSpace& linear_block(const SystemModel& model) {
  if (const auto* linear = std::get_if<StateSpace>(&model)) return *linear;
  return std::get<AnyHystereticLfr>(model).linear();
}

std::string describe(const SystemModel& model) {
  if (const auto* linear = std::get_if<StateSpace>(&model))
    return fmt::format("state_space: {} states, {} inputs, {} outputs", linear->order(),
                       linear->inputs(), linear->outputs());
  const auto& lfr = std::get<AnyHystereticLfr>(model);
  return fmt::format("hysteretic_lfr: {} states, {} inputs, {} outputs, {} '{}' feedback channels",
                     lfr.order(), lfr.inputs(), lfr.outputs(), lfr.feedback_channels(),
                     lfr.feedback_model());
}

nlohmann::json score_json(const SimulationScore& score) {
  nlohmann::json channels = nlohmann::json::array();
  for (const auto& c : score.channels)
    channels.push_back(
        {{"rmse", c.rmse}, {"relative_error", c.relative_error}, {"output_std", c.output_std}});
  return {{"channels", channels},
          {"mean_rmse", score.mean_rmse},
          {"mean_relative_error", score.mean_relative_error},
          {"scored_samples", score.scored_samples}};
}

void run(const EvaluateOptions& options) {
  const auto system = load_system_model(options.model);
  if (!system) return run_single_input(options);
  if (options.table || options.validation_start != "rest" || options.validation_align != "none")
    throw Error(
        fmt::format("{}: --table, --validation-start and --validation-align are for "
                    "single-input models; a dynamic model is scored with --periodic or "
                    "--transient",
                    options.model));
  const auto& model = *system;
  check_system_sample_time(options, linear_block(model).sample_time());
  const auto experiments = read_experiments(options.data);
  const auto& experiment = experiments.at(0);
  const auto result = [&] {
    try {
      return score(model, experiment, {options.periodic, options.transient, options.init_samples});
    } catch (const Error& error) {
      throw Error(fmt::format("{} on {}: {}", options.model,
                              describe_experiment(options.data, 0, experiment), error.what()));
    }
  }();
  const auto warnings = free_run_warnings(linear_block(model), result.runaway);
  if (options.strict && !warnings.empty())
    throw Error(fmt::format("{}: {} (--strict)", options.model, warnings.front()));
  for (const auto& warning : warnings)
    warn(fmt::format("{}: {}", options.model, warning));
  if (options.json) {
    auto out = score_json(result);
    out["warnings"] = warnings;
    out["model"] = options.model;
    out["periodic"] = options.periodic;
    out["transient_samples"] =
        scored_transient({options.periodic, options.transient, options.init_samples});
    out["init_samples"] = options.init_samples;
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("model: {} ({})\n", options.model, describe(model));
  fmt::print("data:  {}\n", describe_experiment(options.data, 0, experiment));
  const std::string start =
      options.periodic ? std::string("periodic steady state")
      : options.init_samples > 0
          ? fmt::format(
                "the state estimated from the input and the first {} measured outputs of "
                "each realisation, which are left out",
                options.init_samples)
          : fmt::format("rest, first {} samples of each realisation left out", options.transient);
  fmt::print("start: {}\n\n", start);
  fmt::print("{:<8} {:>14} {:>15}\n", "output", "RMSE", "relative error");
  for (std::size_t c = 0; c < result.channels.size(); ++c)
    fmt::print("{:<8} {:>14.6g} {:>14.3f} %\n", c + 1, result.channels[c].rmse,
               100.0 * result.channels[c].relative_error);
  fmt::print("{:<8} {:>14.6g} {:>14.3f} %\n", "mean", result.mean_rmse,
             100.0 * result.mean_relative_error);
}

}  // namespace

void add_evaluate_command(CLI::App& app) {
  auto options = std::make_shared<EvaluateOptions>();
  auto* command = app.add_subcommand(
      "evaluate",
      "Score a model file on a measured record: any single-input model (the validation rule of "
      "'hyst fit'), or a dynamic multi-input model on periodic test data (benchmark error).");
  command->add_option("--model", options->model, "Model file (JSON)")->required();
  add_dynamic_data_options(*command, options->data, false);
  auto* periodic =
      command->add_flag("--periodic", options->periodic,
                        "Start each realisation in periodic steady state (the data are periodic)");
  command
      ->add_option("--transient", options->transient,
                   "Without --periodic: samples left out at the start of each realisation")
      ->capture_default_str()
      ->excludes(periodic);
  command
      ->add_option("--init-samples", options->init_samples,
                   "Dynamic models: start each realisation from the state estimated from its "
                   "input and its first N measured outputs (the benchmarks' n_init rule), and "
                   "score the rest")
      ->excludes(periodic)
      ->excludes("--transient");
  command->add_option("--table", options->table,
                      "Single-input models: the table of a multi-table data file (1-based)");
  command
      ->add_option("--validation-start", options->validation_start,
                   "Single-input models: where the prediction starts: rest (the model's "
                   "initial state), periodic (the record's own periodic steady state) or file "
                   "(the state the model file holds)")
      ->capture_default_str();
  command
      ->add_option("--validation-align", options->validation_align,
                   "Single-input models: none, or first-sample (the prediction shifted to the "
                   "measured first sample)")
      ->capture_default_str();
  add_time_options(*command, options->time, "--data");
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command->add_flag("--strict", options->strict,
                    "Exit with an error instead of a warning when the model is unstable in free "
                    "run (a pole outside the unit circle, outputs that ran away) or, for a "
                    "single-input model, when the record's inputs leave its fitted domain");
  command->footer(R"(A single-input model (pi, preisach, ...) is scored on one record exactly as
'hyst fit --validation-data' scores its validation record (same --validation-start and
--validation-align, defaults rest and none): RMSE (in the output's unit where the file names
it), NRMSE by the output's range and by its standard deviation, and the largest error, beside
yardsticks fitted on this record itself (its mean, a static cubic y(v)): the floor that a model
without memory reaches there.
A dynamic multi-input model (state_space, hysteretic_lfr), per output channel: RMSE of the simulated output (free run) averaged over
realisations and periods, and that RMSE relative to the channel's standard deviation; then their
mean over the channels. A warning (an error with --strict) says when the free run cannot be
trusted: a pole of the linear block outside the unit circle, or simulated samples more than 10
times their channel's measured range beyond it.
Examples:
  hyst evaluate --model m.json --data v.csv --input Vplus_1kv --output Displacement_1kv \
      --validation-start periodic --validation-align first-sample
  hyst evaluate --model fsm.json --input-npy u_200mV_test.npy --output-npy y_200mV_test.npy \
      --layout N,channel,realisation,period --periodic)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
