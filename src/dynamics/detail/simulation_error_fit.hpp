#pragma once
// The fit shared by the dynamic models with hysteresis (hysteretic LFR, Hammerstein): Levenberg-
// Marquardt (Ceres) on the free-run simulation error of every realisation of periodic
// experiments, with the Jacobian from the simulation's forward sensitivities. The periods after
// the first are scored (the first may hold the experiment's transient), each simulated over one
// period from the model's own periodic steady state for that period's input (HystereticLfr::
// periodic_state, at every parameter vector tried: what the periodic score sees), with the
// derivatives of that periodic steady state; parameters whose loop has no periodic steady state
// are refused as a failed step. Each experiment's channels are weighted by 1 / their standard
// deviation (the benchmark's relative error).

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hyst/core/progress.hpp"
#include "hyst/dynamics/best_linear_approximation.hpp"
#include "hyst/dynamics/state_space.hpp"
#include "hyst/identify/fit_report.hpp"
#include "lfr_parametrisation.hpp"

namespace hyst::detail {

// One realisation: its whole input record (periods of `period` samples), the measured outputs
// of the periods after the first and their weights.
struct Realisation {
  Eigen::MatrixXd input;
  Eigen::MatrixXd measured;   // the input's rows from `period` on
  Eigen::RowVectorXd weight;  // per channel
  Eigen::Index period = 0;
};

// Throws hyst::Error (the message starting with `fit`) for no experiment, experiments whose
// channel counts differ from the linear model's, or fewer than 2 periods in a realisation.
void check_experiments(const StateSpace& linear, std::span<const PeriodicExperiment> experiments,
                       const std::string& fit);

// Each experiment's channels weighted by 1 / (std * sqrt(scored values of the experiment)), so
// that the cost is half the sum over experiments of the mean squared relative error. Throws
// hyst::Error for a constant output.
std::vector<Realisation> realisations(std::span<const PeriodicExperiment> experiments,
                                      const std::string& fit);

// The largest |value| of each input and each output channel over every experiment; throws
// hyst::Error when one is zero throughout.
struct SignalScales {
  Eigen::VectorXd input, output;
};
SignalScales signal_scales(std::span<const PeriodicExperiment> experiments, const std::string& fit);

// Bound on the Levenberg-Marquardt trial steps of a fit, per accepted step allowed.
inline constexpr std::size_t kTrialStepsPerAcceptedStep = 20;

struct SimulationErrorFitOptions {
  std::string name;  // the Progress task and the report's model, e.g. "hysteretic_lfr"
  // Accepted Levenberg-Marquardt steps (one Jacobian each); rejected trial steps, one simulation
  // each, are not counted (at most kTrialStepsPerAcceptedStep trial steps per accepted one).
  std::size_t max_iterations = 30;
  std::size_t threads = 2;
  ProgressCallback progress{};
};

struct SimulationErrorFit {
  HystereticLfr<PrandtlIshlinskii> model;
  FitReport report;  // fit: relative to the measured outputs of the scored periods
};

SimulationErrorFit fit_simulation_error(const LfrParametrisation& structure,
                                        std::span<const Realisation> data,
                                        const SimulationErrorFitOptions& options);

// A whole fit of a Structure (an LfrParametrisation made from the linear model, the signal scales,
// the options and the fit's name, e.g. FeedbackLfrParametrisation): the checks, the data,
// Levenberg-Marquardt. `model` names the report's model.
template <typename Structure, typename Options>
SimulationErrorFit fit_structure(const StateSpace& linear,
                                 std::span<const PeriodicExperiment> experiments,
                                 const Options& options, const std::string& fit,
                                 const std::string& model) {
  check_experiments(linear, experiments, fit);
  check_threshold_fractions(options.threshold_fractions, fit);
  const Structure structure(linear, signal_scales(experiments, fit), options, fit);
  return fit_simulation_error(structure, realisations(experiments, fit),
                              {model, options.max_iterations, options.threads, options.progress});
}

}  // namespace hyst::detail
