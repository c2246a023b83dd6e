// hyst fit-system: a dynamic multi-input multi-output model fitted to periodic experiments - the
// best linear approximation of the pooled experiments, then a state-space model of it
// (hyst/dynamics/fit_state_space.hpp).

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "../dynamic_data.hpp"
#include "commands.hpp"
#include "hyst/dynamics/fit_hammerstein.hpp"
#include "hyst/dynamics/fit_hysteretic_lfr.hpp"
#include "hyst/dynamics/fit_state_space.hpp"
#include "hyst/dynamics/free_run_check.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/registry/hysteretic_lfr_file.hpp"
#include "hyst/registry/state_space_file.hpp"
#include "progress_display.hpp"

namespace hyst::cli {
namespace {

struct FitSystemOptions {
  std::string model = "state_space";
  DynamicDataOptions data;
  std::optional<double> sample_time;  // with --linear: that model's when not given
  std::size_t order = 2;
  std::string weighting = "none";
  std::size_t max_iterations = 200;
  double excitation_threshold = BlaOptions{}.excitation_threshold;
  std::size_t transient_periods = 0;
  std::string linear;                       // hysteresis models: start from this linear model
  std::vector<double> threshold_fractions;  // empty: the model's default
  std::size_t hysteresis_iterations = HystereticLfrFitOptions{}.max_iterations;
  bool fixed_poles = false;
  bool fixed_io_matrices = false;
  std::size_t general_iterations = HystereticLfrFitOptions{}.general_iterations;
  std::size_t feedback_channels = 0;  // 0: one per output
  ProgressFlags progress;
  std::string out;
  std::vector<std::string> given;  // the options of the models with hysteresis given
};

//! The free-run score of the fitted model on every training experiment (periodic steady state),
//! with a warning line (and "warnings" in the file) for an unstable linear block or samples that
//! ran away: a fit is not trusted until its free run has been seen.
nlohmann::json scores_json(const std::vector<PeriodicExperiment>& experiments,
                           const DynamicDataOptions& data, const StateSpace& linear,
                           const std::function<SimulationScore(const PeriodicExperiment&)>& score) {
  nlohmann::json scores = nlohmann::json::array();
  for (std::size_t i = 0; i < experiments.size(); ++i) {
    const auto experiment = describe_experiment(data, i, experiments[i]);
    // A fitted model is written even when it cannot be scored: the fit may have taken minutes.
    try {
      const auto result = score(experiments[i]);
      fmt::print("experiment {} (periodic steady state): relative error {:.3f} % (RMSE {:.6g})\n",
                 i + 1, 100.0 * result.mean_relative_error, result.mean_rmse);
      const auto warnings = free_run_warnings(linear, result.runaway);
      for (const auto& warning : warnings)
        warn(fmt::format("experiment {}: unstable in free run: {}", i + 1, warning));
      scores.push_back({{"experiment", experiment},
                        {"mean_relative_error", result.mean_relative_error},
                        {"mean_rmse", result.mean_rmse},
                        {"warnings", warnings}});
    } catch (const Error& error) {
      fmt::print("experiment {} (periodic steady state): not scored: {}\n", i + 1, error.what());
      scores.push_back({{"experiment", experiment}, {"error", error.what()}});
    }
  }
  return scores;
}

nlohmann::json fit_info(const FitReport& report, nlohmann::json scores) {
  return {{"fit",
           {{"method", report.method},
            {"status", std::string(report.status())},
            {"iterations", report.iterations},
            {"parameters", report.parameters},
            {"seconds", report.seconds}}},
          {"training_scores", std::move(scores)}};
}

// A model with hysteresis (hysteretic_lfr, hammerstein) from a linear model: given (--linear) or
// fitted here first.
template <typename FitOptions, typename Fit>
void fit_hysteretic(const FitSystemOptions& options,
                    const std::vector<PeriodicExperiment>& experiments, const StateSpace& linear,
                    const Fit& fit_model) {
  FitOptions fit_options;
  if (!options.threshold_fractions.empty())
    fit_options.threshold_fractions = options.threshold_fractions;
  fit_options.max_iterations = options.hysteresis_iterations;
  fit_options.fit_poles = !options.fixed_poles;
  fit_options.fit_io_matrices = !options.fixed_io_matrices;
  if constexpr (requires { fit_options.general_iterations; }) {
    fit_options.general_iterations = options.general_iterations;
    fit_options.feedback_channels = options.feedback_channels;
  }
  ProgressDisplay display("hyst fit-system", options.progress.mode());
  fit_options.progress = display.callback();
  const auto fit = display.run(fmt::format("fitting {}", options.model),
                               [&] { return fit_model(linear, experiments, fit_options); });
  fmt::print("{}\n", fit.report.brief());
  const auto model = any_hysteretic_lfr(fit.model);
  const ScoreOptions periodic{.periodic = true};
  auto scores =
      scores_json(experiments, options.data, model.linear(), [&](const PeriodicExperiment& x) {
        return score_hysteretic_lfr(model, x.input, x.output, periodic);
      });
  auto info = fit_info(fit.report, std::move(scores));
  info["fit"]["structure"] = options.model;
  save_hysteretic_lfr(options.out, model, info);
  fmt::print("wrote {}: {} model{}, {} states, {} inputs, {} outputs, {} parameters\n", options.out,
             options.model, options.model == "hysteretic_lfr" ? "" : " (a hysteretic_lfr file)",
             model.order(), model.inputs(), model.outputs(), model.parameter_count());
}

void fit_with_hysteresis(const FitSystemOptions& options,
                         const std::vector<PeriodicExperiment>& experiments,
                         const StateSpace& linear) {
  if (options.model == "hammerstein")
    return fit_hysteretic<HammersteinFitOptions>(
        options, experiments, linear,
        [](const StateSpace& l, const std::vector<PeriodicExperiment>& x,
           const HammersteinFitOptions& o) { return fit_hammerstein(l, x, o); });
  fit_hysteretic<HystereticLfrFitOptions>(
      options, experiments, linear,
      [](const StateSpace& l, const std::vector<PeriodicExperiment>& x,
         const HystereticLfrFitOptions& o) { return fit_hysteretic_lfr(l, x, o); });
}

// What the options ask for, bounded before any data is read.
void check_counts(const FitSystemOptions& options) {
  if (!options.sample_time && options.linear.empty())
    throw Error(
        "--sample-time is required (or --linear: a state_space model file, whose sample "
        "time is taken)");
  if (options.sample_time &&
      (!std::isfinite(*options.sample_time) || !(*options.sample_time > 0.0)))
    throw Error(fmt::format("--sample-time {:g}: the sample time must be finite and > 0 s",
                            *options.sample_time));
  if (options.linear.empty() && (options.order < 1 || options.order > kMaxStateSpaceFitOrder))
    throw Error(fmt::format("--order {}: the order must be in 1..{} (the limit of a fit's order)",
                            options.order, kMaxStateSpaceFitOrder));
  if (options.threshold_fractions.size() > kMaxThresholdFractions)
    throw Error(fmt::format("--thresholds: {} thresholds are above the limit of {}",
                            options.threshold_fractions.size(), kMaxThresholdFractions));
  if (options.feedback_channels > kMaxFeedbackChannels)
    throw Error(fmt::format("--feedback-channels {}: above the limit of {} channels",
                            options.feedback_channels, kMaxFeedbackChannels));
}

void run(const FitSystemOptions& options) {
  check_counts(options);
  if (options.model != "state_space" && options.model != "hysteretic_lfr" &&
      options.model != "hammerstein")
    throw Error(
        fmt::format("--model '{}': the dynamic models are: state_space, hysteretic_lfr, "
                    "hammerstein",
                    options.model));
  if (!options.given.empty() && options.model == "state_space")
    throw Error(
        fmt::format("{}: only with --model hysteretic_lfr or hammerstein", options.given[0]));
  for (const auto& name : options.given)
    if ((name == "--general-iterations" || name == "--feedback-channels") &&
        options.model != "hysteretic_lfr")
      throw Error(name + ": only with --model hysteretic_lfr");
  auto inputs = dynamic_data_inputs(options.data);
  if (!options.linear.empty()) inputs.push_back({options.linear, "--linear"});
  io::check_outputs(inputs, {{options.out, "--out"}});
  const auto experiments = read_experiments(options.data);
  for (std::size_t i = 0; i < experiments.size(); ++i)
    fmt::print("experiment {}: {}\n", i + 1, describe_experiment(options.data, i, experiments[i]));
  if (!options.linear.empty()) {
    // The linear model's sample time is the fit's; --sample-time, when given, must repeat it.
    const auto linear = load_state_space(options.linear).model;
    if (options.sample_time && linear.sample_time() != *options.sample_time)
      throw Error(fmt::format("--linear {}: sample time {:g} s, but --sample-time is {:g} s",
                              options.linear, linear.sample_time(), *options.sample_time));
    return fit_with_hysteresis(options, experiments, linear);
  }

  const auto bla = estimate_bla(experiments, *options.sample_time,
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

  if (options.model != "state_space") return fit_with_hysteresis(options, experiments, fit.model);
  auto info =
      fit_info(fit.report,
               scores_json(experiments, options.data, fit.model, [&](const PeriodicExperiment& x) {
                 return score_state_space(fit.model, x.input, x.output, {.periodic = true});
               }));
  info["fit"]["lines"] = bla.lines.size();
  save_state_space(options.out, fit.model, std::nullopt, info);
  fmt::print("wrote {}: state_space model, {} states, {} inputs, {} outputs\n", options.out,
             fit.model.order(), fit.model.inputs(), fit.model.outputs());
}

}  // namespace

void add_fit_system_command(CLI::App& app) {
  auto options = std::make_shared<FitSystemOptions>();
  auto* command = app.add_subcommand(
      "fit-system", "Fit a dynamic multi-input model (state space) to periodic experiments.");
  command
      ->add_option("--model", options->model,
                   "Dynamic model: state_space; hysteretic_lfr (a PI model per output in the "
                   "feedback of the linear model); hammerstein (a PI model per input ahead of "
                   "it). Both are fitted from the linear model on the simulation error")
      ->capture_default_str();
  add_dynamic_data_options(*command, options->data, true);
  command->add_option("--sample-time", options->sample_time,
                      "Sample time Ts [s], finite and > 0; with --linear taken from that model "
                      "(given as well, it must be the same)");
  command
      ->add_option("--order", options->order,
                   fmt::format("Number of states, 1 to {}", kMaxStateSpaceFitOrder))
      ->capture_default_str();
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
  std::vector<CLI::Option*> hysteresis_options;
  hysteresis_options.push_back(
      command
          ->add_option(
              "--linear", options->linear,
              "hysteretic_lfr, hammerstein: start from this state_space model file instead "
              "of fitting one")
          ->check(CLI::ExistingFile));
  hysteresis_options.push_back(
      command
          ->add_option(
              "--thresholds", options->threshold_fractions,
              fmt::format("hysteretic_lfr, hammerstein: PI thresholds as fractions of the "
                          "largest hysteresis input, from 0 (default {} for hysteretic_lfr, "
                          "{} for hammerstein)",
                          fmt::join(HystereticLfrFitOptions{}.threshold_fractions, ","),
                          fmt::join(HammersteinFitOptions{}.threshold_fractions, ",")))
          ->delimiter(','));
  hysteresis_options.push_back(
      command
          ->add_option("--hysteresis-iterations,--lfr-iterations", options->hysteresis_iterations,
                       "hysteretic_lfr, hammerstein: accepted Levenberg-Marquardt steps on the "
                       "simulation error (one Jacobian each; rejected trial steps not counted)")
          ->capture_default_str());
  hysteresis_options.push_back(
      command
          ->add_option(
              "--general-iterations", options->general_iterations,
              "hysteretic_lfr: then accepted Levenberg-Marquardt steps with every matrix of "
              "the LFR free (0: none)")
          ->capture_default_str());
  hysteresis_options.push_back(command->add_option(
      "--feedback-channels", options->feedback_channels,
      "hysteretic_lfr: hysteresis channels in the feedback (default: one per output; channel "
      "i = k p + j starts driven by output j and, for k > 0, half of output (j + k) mod p)"));
  hysteresis_options.push_back(
      command->add_flag("--fixed-poles", options->fixed_poles,
                        "hysteretic_lfr, hammerstein: keep the linear model's poles"));
  hysteresis_options.push_back(
      command->add_flag("--fixed-io", options->fixed_io_matrices,
                        "hysteretic_lfr, hammerstein: keep the linear model's B, C and D"));
  command->add_option("--out", options->out, "Model file to write (JSON)")->required();
  add_progress_flags(*command, options->progress);
  command->footer(R"(The experiments (e.g. several amplitude levels) are pooled into one best
linear approximation, of which a state-space model of the given order is fitted.
Example:
  hyst fit-system --order 28 --sample-time 1.5625e-4 --layout N,channel,realisation,period \
      --input-npy u_100mV.npy --output-npy y_100mV.npy \
      --input-npy u_300mV.npy --output-npy y_300mV.npy --out fsm.json)");
  command->callback([options, hysteresis_options] {
    for (const auto* option : hysteresis_options)
      if (option->count() > 0) options->given.push_back(option->get_name());
    run(*options);
  });
}

}  // namespace hyst::cli
