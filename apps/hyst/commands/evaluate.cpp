// hyst evaluate: the score of a dynamic MIMO model file on periodic test data, as the nonlinear
// system identification benchmarks define it (hyst/dynamics/simulation_score.hpp).

#include <memory>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "../dynamic_data.hpp"
#include "commands.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/registry/state_space_file.hpp"

namespace hyst::cli {
namespace {

struct EvaluateOptions {
  std::string model;
  DynamicDataOptions data;
  bool periodic = false;
  std::size_t transient = 0;
  bool json = false;
};

//! The model of a file; only dynamic MIMO models can be scored here.
StateSpace load_system_model(const std::string& path) {
  const auto document = io::parse_json_text(io::read_file(path), path);
  const auto kind =
      document.is_object() && document.contains("model") && document.at("model").is_string()
          ? document.at("model").get<std::string>()
          : std::string();
  if (kind != "state_space")
    throw Error(fmt::format(
        "{}: model '{}' is not a dynamic multi-input model (state_space); score single-input "
        "hysteresis models with 'hyst fit --validate' or 'hyst compare'",
        path, kind));
  return state_space_from_json(document, path).model;
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
  const auto model = load_system_model(options.model);
  const auto experiments = read_experiments(options.data);
  const auto& experiment = experiments.at(0);
  const auto score = score_state_space(model, experiment.input, experiment.output,
                                       {options.periodic, options.transient});
  if (options.json) {
    auto out = score_json(score);
    out["model"] = options.model;
    out["periodic"] = options.periodic;
    out["transient_samples"] = options.transient;
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("model: {} (state_space: {} states, {} inputs, {} outputs)\n", options.model,
             model.order(), model.inputs(), model.outputs());
  fmt::print("data:  {}\n", describe_experiment(options.data, 0, experiment));
  fmt::print("start: {}\n\n",
             options.periodic ? "periodic steady state"
                              : fmt::format("rest, first {} samples of each realisation left out",
                                            options.transient));
  fmt::print("{:<8} {:>14} {:>15}\n", "output", "RMSE", "relative error");
  for (std::size_t c = 0; c < score.channels.size(); ++c)
    fmt::print("{:<8} {:>14.6g} {:>14.3f} %\n", c + 1, score.channels[c].rmse,
               100.0 * score.channels[c].relative_error);
  fmt::print("{:<8} {:>14.6g} {:>14.3f} %\n", "mean", score.mean_rmse,
             100.0 * score.mean_relative_error);
}

}  // namespace

void add_evaluate_command(CLI::App& app) {
  auto options = std::make_shared<EvaluateOptions>();
  auto* command = app.add_subcommand(
      "evaluate", "Score a dynamic multi-input model on periodic test data (benchmark error).");
  command->add_option("--model", options->model, "Model file (JSON) of a dynamic model")
      ->required();
  add_dynamic_data_options(*command, options->data, false);
  auto* periodic =
      command->add_flag("--periodic", options->periodic,
                        "Start each realisation in periodic steady state (the data are periodic)");
  command
      ->add_option("--transient", options->transient,
                   "Without --periodic: samples left out at the start of each realisation")
      ->capture_default_str()
      ->excludes(periodic);
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command->footer(R"(Per output channel: RMSE of the simulated output (free run) averaged over
realisations and periods, and that RMSE relative to the channel's standard deviation; then their
mean over the channels.
Example:
  hyst evaluate --model fsm.json --input-npy u_200mV_test.npy --output-npy y_200mV_test.npy \
      --layout N,channel,realisation,period --periodic)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
