#include "simulation_error_fit.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "../../identify/detail/convergence.hpp"
#include "compressed_least_squares.hpp"
#include "hyst/core/error.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/identify/error_metrics.hpp"
#include "lfr_sensitivity.hpp"

namespace hyst::detail {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;

// What one worker thread adds up over the realisations it simulates.
struct NormalEquations {
  MatrixXd normal;  // J^T J, lower triangle
  Eigen::VectorXd gradient;
  double squares = 0.0;
  std::vector<double> jacobian;  // one realisation's rows, reused
};

// The input of period `scored` of those after the first.
auto scored_input(const Realisation& data, Index scored) {
  return data.input.middleRows((scored + 1) * data.period, data.period);
}

// The simulation error of every realisation (simulated minus measured, weighted) as one Ceres
// cost: the realisations are simulated with their forward sensitivities on `threads` threads,
// each adding its rows to J^T J and J^T r, and Ceres sees the compressed problem
// (compressed_least_squares.hpp) instead of a Jacobian of a row per measured value. False (a step
// Ceres refuses) for parameters that make no model, leave the loop without a periodic steady state
// for a realisation's input (unstable or chaotic: over the two simulated periods such a loop can
// still look good) or give non-finite values.
class SimulationErrorCost final : public ceres::CostFunction {
 public:
  SimulationErrorCost(const LfrParametrisation& structure, std::span<const Realisation> data,
                      std::size_t threads)
      : structure_(structure), data_(data), threads_(std::max<std::size_t>(1, threads)) {
    set_num_residuals(int(structure.size()) + 1);
    mutable_parameter_block_sizes()->push_back(int(structure.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Index size = structure_.size();
    const bool with_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
    // Worker t takes realisations t, t + T, ...: the sums, and so the fit, do not depend on
    // which thread runs first.
    const std::size_t count = std::min(threads_, data_.size());
    std::vector<NormalEquations> sums(count);
    std::atomic<bool> refused{false};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    const auto work = [&](std::size_t worker) {
      NormalEquations& sum = sums[worker];
      try {
        const LfrPoint point = structure_.at(parameters[0]);
        if (with_jacobian) {
          sum.normal = MatrixXd::Zero(size, size);
          sum.gradient = Eigen::VectorXd::Zero(size);
        }
        for (std::size_t i = worker; i < data_.size() && !refused; i += count)
          if (!add_realisation(point, data_[i], with_jacobian, sum)) refused = true;
      } catch (const Error&) {
        refused = true;
      } catch (...) {
        const std::lock_guard lock(failure_mutex);
        failure = std::current_exception();
        refused = true;
      }
    };
    {
      std::vector<std::jthread> workers;
      for (std::size_t t = 1; t < count; ++t)
        workers.emplace_back(work, t);
      work(0);
    }
    if (failure) std::rethrow_exception(failure);
    if (refused) return false;

    double squares = 0.0;
    for (const auto& sum : sums)
      squares += sum.squares;
    if (!std::isfinite(squares)) return false;
    Eigen::Map<Eigen::VectorXd> out(residuals, size + 1);
    if (!with_jacobian) {
      out.setZero();
      out[0] = std::sqrt(squares);
      return true;
    }
    MatrixXd normal = MatrixXd::Zero(size, size);
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(size);
    for (const auto& sum : sums) {
      normal += sum.normal;
      gradient += sum.gradient;
    }
    normal = normal.selfadjointView<Eigen::Lower>();
    if (!normal.allFinite() || !gradient.allFinite()) return false;
    const auto compressed = compress_least_squares(normal, gradient, squares);
    out = compressed.residuals;
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        jacobians[0], size + 1, size) = compressed.jacobian;
    return true;
  }

 private:
  // Adds one realisation's scored periods, each simulated from the model's periodic state for its
  // own input; false when a residual is not finite.
  bool add_realisation(const LfrPoint& point, const Realisation& data, bool with_jacobian,
                       NormalEquations& sum) const {
    const Index size = structure_.size();
    const Index n = data.period, p = data.measured.cols();
    if (with_jacobian) sum.jacobian.resize(std::size_t(n * p * size));
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>
        jacobian(sum.jacobian.data(), n * p, size);
    Eigen::VectorXd r(n * p);
    for (Index scored = 0; scored * n < data.measured.rows(); ++scored) {
      const MatrixXd u = scored_input(data, scored);
      auto start = point.model.periodic_state(u);
      const MatrixXd y =
          with_jacobian ? simulate_with_sensitivities(point, size, u, std::move(start),
                                                      {0, data.weight, sum.jacobian.data(), true})
                        : point.model.simulate(u, start);
      for (Index k = 0; k < n; ++k)
        for (Index c = 0; c < p; ++c)
          r[k * p + c] = (y(k, c) - data.measured(scored * n + k, c)) * data.weight[c];
      if (!r.allFinite()) return false;
      sum.squares += r.squaredNorm();
      if (with_jacobian) {
        sum.normal.selfadjointView<Eigen::Lower>().rankUpdate(jacobian.transpose());
        sum.gradient.noalias() += jacobian.transpose() * r;
      }
    }
    return true;
  }

  const LfrParametrisation& structure_;
  std::span<const Realisation> data_;
  std::size_t threads_;
};

// Counts the accepted Levenberg-Marquardt steps (each costs one Jacobian; a rejected trial step
// costs one simulation), ends the run after `limit` of them and tells the progress callback.
class AcceptedStepLimit final : public ceres::IterationCallback {
 public:
  AcceptedStepLimit(const ProgressCallback& progress, std::string task, std::size_t limit)
      : progress_(progress), task_(std::move(task)), limit_(limit) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (summary.step_is_successful) {
      if (summary.iteration > 0) ++accepted_;
      cost_ = summary.cost;  // a rejected step's summary holds the refused trial's cost
    }
    if (accepted_ >= limit_) {
      reached_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (progress_) progress_(Progress{task_, accepted_, limit_, fmt::format("cost {:.6g}", cost_)});
    return ceres::SOLVER_CONTINUE;
  }

  std::size_t accepted() const { return accepted_; }
  bool reached() const { return reached_; }

 private:
  const ProgressCallback& progress_;
  std::string task_;
  std::size_t limit_;
  std::size_t accepted_ = 0;
  double cost_ = 0.0;  // at the last accepted point
  bool reached_ = false;
};

}  // namespace

void check_experiments(const StateSpace& linear, std::span<const PeriodicExperiment> experiments,
                       const std::string& fit) {
  if (experiments.empty()) throw Error(fit + ": no experiment");
  if (linear.order() > kMaxLfrOrder)
    throw Error(
        fmt::format("{}: the linear model has {} states, more than the limit of {} of a "
                    "hysteretic LFR's linear block",
                    fit, linear.order(), kMaxLfrOrder));
  for (std::size_t e = 0; e < experiments.size(); ++e) {
    const auto& x = experiments[e];
    if (x.input.channels != linear.inputs() || x.output.channels != linear.outputs())
      throw Error(fmt::format(
          "{}: experiment {} has {} inputs and {} outputs; the linear model "
          "has {} and {}",
          fit, e, x.input.channels, x.output.channels, linear.inputs(), linear.outputs()));
    if (x.input.periods < 2)
      throw Error(fmt::format(
          "{}: experiment {} has {} period per realisation; the fit needs 2 "
          "or more (the first, which may hold the experiment's transient, is not scored)",
          fit, e, x.input.periods));
    // Every sample, the unscored first period too: it drives the simulation and enters the
    // outputs' scales and deviations.
    require_finite_signals(x.input, fmt::format("{}: experiment {} input", fit, e));
    require_finite_signals(x.output, fmt::format("{}: experiment {} output", fit, e));
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
      data.period = n;
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
  problem.AddResidualBlock(new SimulationErrorCost(structure, data, options.threads), nullptr,
                           parameters.data());
  structure.bound(problem, parameters.data());
  // Ceres's own limit counts rejected trial steps too; it only bounds them here (Ceres ends a run
  // anyway after about a dozen rejections in a row, when the trust region has shrunk to nothing).
  constexpr auto kMaxCeresIterations = std::size_t(std::numeric_limits<int>::max());
  ceres::Solver::Options solver = levenberg_marquardt_options(
      std::min(options.max_iterations, kMaxCeresIterations / kTrialStepsPerAcceptedStep) *
          kTrialStepsPerAcceptedStep,
      kFunctionTolerance);
  solver.linear_solver_type = ceres::DENSE_QR;  // P + 1 rows: the compressed problem
  // With bounds, Ceres follows each step by a projected line search that evaluates the Jacobian
  // at its trial points (three Jacobians per step instead of one) and, on these fits, slows the
  // descent down (FSM, 6 channels, first stage: cost 0.0310 after 4 accepted steps with it, 0.0164
  // after 7 without it, in 62 s and 36 s). Without it a step that leaves the bounds is projected
  // onto them and judged like any other.
  solver.max_num_line_search_step_size_iterations = 0;
  AcceptedStepLimit limit(options.progress, task, options.max_iterations);
  solver.callbacks.push_back(&limit);
  ceres::Solver::Summary summary;
  if (options.max_iterations > 0) ceres::Solve(solver, &problem, &summary);
  if (options.progress)
    options.progress(Progress{task, options.max_iterations, options.max_iterations, {}});

  auto model = structure.at(parameters.data()).model;
  std::vector<double> measured, predicted;
  for (const auto& realisation : data) {
    const Index n = realisation.period;
    for (Index scored = 0; scored * n < realisation.measured.rows(); ++scored) {
      const MatrixXd y = model.simulate_periodic(scored_input(realisation, scored));
      for (Index k = 0; k < n; ++k)
        for (Index c = 0; c < realisation.measured.cols(); ++c) {
          measured.push_back(realisation.measured(scored * n + k, c));
          predicted.push_back(y(k, c));
        }
    }
  }
  FitReport report;
  report.model = options.name;
  report.method = fmt::format(
      "Levenberg-Marquardt (Ceres, Jacobian by forward sensitivities) on the simulation error, "
      "of {}",
      structure.description());
  if (options.max_iterations == 0) {
    report.termination = Termination::converged;
    report.message = "not refined";
  } else if (limit.reached()) {
    report.termination = Termination::max_iterations;
    report.message = fmt::format("Limit of {} accepted steps reached ({} trial steps in all).",
                                 options.max_iterations, summary.iterations.size() - 1);
  } else {
    report.termination = termination_of_ceres(summary);
    report.message = summary.message;
  }
  report.iterations = limit.accepted();
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  report.parameters = parameters.size();
  report.fit = error_metrics(measured, predicted);
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return {std::move(model), std::move(report)};
}

}  // namespace hyst::detail
