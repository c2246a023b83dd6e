// hyst fit-system: a dynamic multi-input multi-output model fitted to periodic experiments - the
// best linear approximation of the pooled experiments, then a state-space model of it
// (hyst/dynamics/fit_state_space.hpp).

#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "../dynamic_data.hpp"
#include "commands.hpp"
#include "hyst/dynamics/fit_state_space.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/registry/state_space_file.hpp"

namespace hyst::cli {
namespace {

struct FitSystemOptions {
  std::string model = "state_space";
  DynamicDataOptions data;
  double sample_time = 0.0;
  std::size_t order = 2;
  std::string weighting = "none";
  std::size_t max_iterations = 200;
  double excitation_threshold = BlaOptions{}.excitation_threshold;
  std::size_t transient_periods = 0;
  std::string out;
};

void run(const FitSystemOptions& options) {
  if (options.model != "state_space")
    throw Error(fmt::format("--model '{}': the dynamic models are: state_space", options.model));
  auto inputs = dynamic_data_inputs(options.data);
  io::check_outputs(inputs, {{options.out, "--out"}});
  const auto experiments = read_experiments(options.data);
  for (std::size_t i = 0; i < experiments.size(); ++i)
    fmt::print("experiment {}: {}\n", i + 1, describe_experiment(options.data, i, experiments[i]));

  const auto bla = estimate_bla(experiments, options.sample_time,
                                {options.excitation_threshold, options.transient_periods});
  fmt::print(
      "best linear approximation: {} excited lines ({:g} to {:g} Hz), {} blocks of {} "
      "realisations, {} periods\n",
      bla.lines.size(), bla.frequencies().front(), bla.frequencies().back(), bla.blocks,
      bla.inputs(), bla.periods);
  StateSpaceFitOptions fit_options;
  fit_options.order = options.order;
  fit_options.weighting = bla_weighting_from_string(options.weighting);
  fit_options.max_iterations = options.max_iterations;
  const auto fit = fit_state_space(bla, fit_options);
  fmt::print("{}\n", fit.report.brief());

  nlohmann::json scores = nlohmann::json::array();
  for (std::size_t i = 0; i < experiments.size(); ++i) {
    const auto score = score_state_space(fit.model, experiments[i].input, experiments[i].output,
                                         {.periodic = true});
    fmt::print("experiment {} (periodic steady state): relative error {:.3f} % (RMSE {:.6g})\n",
               i + 1, 100.0 * score.mean_relative_error, score.mean_rmse);
    scores.push_back({{"experiment", describe_experiment(options.data, i, experiments[i])},
                      {"mean_relative_error", score.mean_relative_error},
                      {"mean_rmse", score.mean_rmse}});
  }
  const nlohmann::json info = {{"fit",
                                {{"method", fit.report.method},
                                 {"status", std::string(fit.report.status())},
                                 {"iterations", fit.report.iterations},
                                 {"parameters", fit.report.parameters},
                                 {"lines", bla.lines.size()},
                                 {"seconds", fit.report.seconds}}},
                               {"training_scores", scores}};
  save_state_space(options.out, fit.model, std::nullopt, info);
  fmt::print("wrote {}: state_space model, {} states, {} inputs, {} outputs\n", options.out,
             fit.model.order(), fit.model.inputs(), fit.model.outputs());
}

}  // namespace

void add_fit_system_command(CLI::App& app) {
  auto options = std::make_shared<FitSystemOptions>();
  auto* command = app.add_subcommand(
      "fit-system", "Fit a dynamic multi-input model (state space) to periodic experiments.");
  command->add_option("--model", options->model, "Dynamic model: state_space")
      ->capture_default_str();
  add_dynamic_data_options(*command, options->data, true);
  command->add_option("--sample-time", options->sample_time, "Sample time Ts [s]")
      ->required()
      ->check(CLI::PositiveNumber);
  command->add_option("--order", options->order, "Number of states")->capture_default_str();
  command
      ->add_option("--weighting", options->weighting,
                   "Weights of the frequency-response fit: none (the simulation error of flat "
                   "multisines), total_variance, noise_variance")
      ->capture_default_str();
  command
      ->add_option("--max-iterations", options->max_iterations,
                   "Levenberg-Marquardt iterations (0: the subspace model)")
      ->capture_default_str();
  command
      ->add_option("--excitation-threshold", options->excitation_threshold,
                   "A line is excited above this fraction of the largest line's input power")
      ->capture_default_str();
  command
      ->add_option("--transient-periods", options->transient_periods,
                   "Periods left out at the start of each realisation")
      ->capture_default_str();
  command->add_option("--out", options->out, "Model file to write (JSON)")->required();
  command->footer(R"(The experiments (e.g. several amplitude levels) are pooled into one best
linear approximation, of which a state-space model of the given order is fitted.
Example:
  hyst fit-system --order 28 --sample-time 1.5625e-4 --layout N,channel,realisation,period \
      --input-npy u_100mV.npy --output-npy y_100mV.npy \
      --input-npy u_300mV.npy --output-npy y_300mV.npy --out fsm.json)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
