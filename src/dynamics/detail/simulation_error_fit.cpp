#include "simulation_error_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "../../identify/detail/convergence.hpp"
#include "hyst/core/error.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/identify/error_metrics.hpp"
#include "lfr_sensitivity.hpp"

namespace hyst::detail {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;

// Simulated minus measured, weighted, with its Jacobian from the forward sensitivities; false (a
// step Ceres refuses) for parameters that make no model, leave the loop without a periodic steady
// state for this realisation's input (unstable or chaotic: over the two simulated periods such a
// loop can still look good) or give non-finite values.
class RealisationCost final : public ceres::CostFunction {
 public:
  RealisationCost(const LfrParametrisation& structure, const Realisation& data)
      : structure_(structure), data_(data) {
    set_num_residuals(int(data.measured.size()));
    mutable_parameter_block_sizes()->push_back(int(structure.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    try {
      const LfrPoint point = structure_.at(parameters[0]);
      auto start = point.model.periodic_state(data_.input.topRows(data_.warmup));
      double* jacobian = jacobians != nullptr ? jacobians[0] : nullptr;
      const MatrixXd y =
          jacobian != nullptr
              ? simulate_with_sensitivities(point, structure_.size(), data_.input, std::move(start),
                                            {data_.warmup, data_.weight, jacobian})
              : point.model.simulate(data_.input, start);
      const Index rows = data_.measured.rows(), p = data_.measured.cols();
      for (Index k = 0; k < rows; ++k)
        for (Index c = 0; c < p; ++c) {
          const double r = (y(data_.warmup + k, c) - data_.measured(k, c)) * data_.weight[c];
          if (!std::isfinite(r)) return false;
          residuals[k * p + c] = r;
        }
      // A non-finite Jacobian entry needs no scan here: Ceres checks every evaluation's residuals
      // and Jacobian (IsEvaluationValid) and treats a bad one as a failed step.
      return true;
    } catch (const Error&) {
      return false;
    }
  }

 private:
  const LfrParametrisation& structure_;
  const Realisation& data_;
};

// Tells the progress callback where Levenberg-Marquardt stands after each iteration.
class IterationProgress final : public ceres::IterationCallback {
 public:
  IterationProgress(const ProgressCallback& progress, std::string task, std::size_t iterations)
      : progress_(progress), task_(std::move(task)), iterations_(iterations) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    const auto done = std::min(std::size_t(summary.iteration), iterations_);
    const std::string current = fmt::format("cost {:.6g}", summary.cost);
    if (done < iterations_) progress_(Progress{task_, done, iterations_, current});
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const ProgressCallback& progress_;
  std::string task_;
  std::size_t iterations_;
};

}  // namespace

void check_experiments(const StateSpace& linear, std::span<const PeriodicExperiment> experiments,
                       const std::string& fit) {
  if (experiments.empty()) throw Error(fit + ": no experiment");
  for (std::size_t e = 0; e < experiments.size(); ++e) {
    const auto& x = experiments[e];
    if (x.input.channels != linear.inputs() || x.output.channels != linear.outputs())
      throw Error(fmt::format(
          "{}: experiment {} has {} inputs and {} outputs; the linear model "
          "has {} and {}",
          fit, e, x.input.channels, x.output.channels, linear.inputs(), linear.outputs()));
    if (x.input.periods < 2)
      throw Error(
          fmt::format("{}: experiment {} has {} period per realisation; the fit needs 2 "
                      "or more (the first warms the hysteresis up)",
                      fit, e, x.input.periods));
  }
}

std::vector<Realisation> realisations(std::span<const PeriodicExperiment> experiments,
                                      const std::string& fit) {
  std::vector<Realisation> result;
  for (const auto& x : experiments) {
    const auto n = Index(x.input.samples);
    const auto p = Index(x.output.channels);
    Eigen::RowVectorXd mean = Eigen::RowVectorXd::Zero(p), square = mean;
    std::vector<MatrixXd> outputs;
    for (std::size_t r = 0; r < x.output.realisations; ++r) {
      outputs.push_back(realisation_record(x.output, r));
      mean += outputs.back().colwise().sum();
      square += outputs.back().array().square().matrix().colwise().sum();
    }
    const double count = double(x.output.realisations * x.output.record_length());
    mean /= count;
    const Eigen::RowVectorXd deviation =
        (square / count - mean.array().square().matrix()).cwiseMax(0.0).cwiseSqrt();
    const double scored = double(x.output.realisations * (x.output.periods - 1) * x.output.samples);
    for (std::size_t r = 0; r < x.output.realisations; ++r) {
      Realisation data;
      data.input = realisation_record(x.input, r);
      data.warmup = n;
      data.measured = outputs[r].bottomRows(outputs[r].rows() - n);
      data.weight = (deviation * std::sqrt(scored * double(p))).cwiseInverse();
      for (Index c = 0; c < p; ++c)
        if (!std::isfinite(data.weight[c]))
          throw Error(fmt::format("{}: output {} is constant in an experiment", fit, c));
      result.push_back(std::move(data));
    }
  }
  return result;
}

SignalScales signal_scales(std::span<const PeriodicExperiment> experiments,
                           const std::string& fit) {
  SignalScales scales;
  const auto m = Index(experiments.front().input.channels);
  const auto p = Index(experiments.front().output.channels);
  scales.input = Eigen::VectorXd::Zero(m);
  scales.output = Eigen::VectorXd::Zero(p);
  for (const auto& x : experiments) {
    for (std::size_t i = 0; i < x.input.values.size(); ++i) {
      const auto c = Index(i % x.input.channels);
      scales.input[c] = std::max(scales.input[c], std::abs(x.input.values[i]));
    }
    for (std::size_t i = 0; i < x.output.values.size(); ++i) {
      const auto c = Index(i % x.output.channels);
      scales.output[c] = std::max(scales.output[c], std::abs(x.output.values[i]));
    }
  }
  if (!(scales.input.minCoeff() > 0.0) || !(scales.output.minCoeff() > 0.0))
    throw Error(fit + ": an input or output is zero throughout");
  return scales;
}

SimulationErrorFit fit_simulation_error(const LfrParametrisation& structure,
                                        std::span<const Realisation> data,
                                        const SimulationErrorFitOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const std::string task = options.name + " Levenberg-Marquardt iterations";
  std::vector<double> parameters = structure.initial();
  ceres::Problem problem;
  for (const auto& realisation : data)
    problem.AddResidualBlock(new RealisationCost(structure, realisation), nullptr,
                             parameters.data());
  structure.bound(problem, parameters.data());
  ceres::Solver::Options solver =
      levenberg_marquardt_options(options.max_iterations, kFunctionTolerance);
  // The normal equations: the Jacobian has hundreds of thousands of rows and a few hundred
  // columns, where QR costs twice as much and needs no better conditioning (LM damps it).
  solver.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  solver.num_threads = int(std::max<std::size_t>(1, options.threads));
  IterationProgress progress(options.progress, task, options.max_iterations);
  if (options.progress) solver.callbacks.push_back(&progress);
  ceres::Solver::Summary summary;
  if (options.max_iterations > 0) ceres::Solve(solver, &problem, &summary);
  if (options.progress)
    options.progress(Progress{task, options.max_iterations, options.max_iterations, {}});

  auto model = structure.at(parameters.data()).model;
  std::vector<double> measured, predicted;
  for (const auto& realisation : data) {
    auto state = model.periodic_state(realisation.input.topRows(realisation.warmup));
    const MatrixXd y = model.simulate(realisation.input, state);
    for (Index k = 0; k < realisation.measured.rows(); ++k)
      for (Index c = 0; c < realisation.measured.cols(); ++c) {
        measured.push_back(realisation.measured(k, c));
        predicted.push_back(y(realisation.warmup + k, c));
      }
  }
  FitReport report;
  report.model = options.name;
  report.method = fmt::format(
      "Levenberg-Marquardt (Ceres, Jacobian by forward sensitivities) on the simulation error, "
      "of {}",
      structure.description());
  report.termination =
      options.max_iterations == 0 ? Termination::converged : termination_of_ceres(summary);
  report.message = options.max_iterations == 0 ? "not refined" : summary.message;
  report.iterations = std::size_t(summary.iterations.size());
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  report.parameters = parameters.size();
  report.fit = error_metrics(measured, predicted);
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return {std::move(model), std::move(report)};
}

}  // namespace hyst::detail
