#pragma once
// When a Ceres-based fit has converged: one set of tests for every fitter (the shared multistart
// engine, GPI, NARX).
//
// Ceres stops with "converged" when one step lowers the cost by less than `function_tolerance`
// relative to it (default 1e-9), when the step is below 1e-9 relative to the parameters, or when
// the projected gradient is below 1e-10 relative to its start. The costs of hysteresis models are
// piecewise smooth (every reversal is a max/min), and Levenberg-Marquardt then often creeps along
// a kinked valley in thousands of tiny steps, each above those tolerances (GPI on one period of
// the 1.5 kV piezo loop: fit NRMSE 1.385 % after 1000 iterations, 1.377 % after 1237). Such a
// run ends at the iteration limit without a meaningful gain. StagnationStop ends it as converged:
// over the last 50 iterations (successful or not) the cost fell by less than 0.1 % of it, so the
// RMSE by less than 0.05 %. Its message says that this rule stopped the run.

#include <cstddef>
#include <deque>
#include <string>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "hyst/identify/fit_report.hpp"

namespace hyst::detail {

// The relative cost decrease of one step below which Ceres reports convergence.
inline constexpr double kFunctionTolerance = 1e-9;

// Levenberg-Marquardt with dense QR, silent, one thread, and the convergence tests above;
// `iterations` is the limit.
inline ceres::Solver::Options levenberg_marquardt_options(std::size_t iterations,
                                                          double function_tolerance) {
  ceres::Solver::Options solver;
  solver.minimizer_type = ceres::TRUST_REGION;
  solver.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = static_cast<int>(iterations);
  solver.function_tolerance = function_tolerance;
  solver.gradient_tolerance = 1e-10;
  solver.parameter_tolerance = 1e-9;
  solver.logging_type = ceres::SILENT;
  solver.minimizer_progress_to_stdout = false;
  solver.num_threads = 1;
  return solver;
}

// How a Ceres run ended, in hyst's words (StagnationStop's USER_SUCCESS is "converged").
inline Termination termination_of_ceres(const ceres::Solver::Summary& summary) {
  switch (summary.termination_type) {
    case ceres::CONVERGENCE:
    case ceres::USER_SUCCESS:
      return Termination::converged;
    case ceres::NO_CONVERGENCE:
      return Termination::max_iterations;
    case ceres::FAILURE:
    case ceres::USER_FAILURE:
      return Termination::failed;
  }
  return Termination::failed;
}

// Ends a run whose cost fell by less than kRelative (relative) over the last kWindow iterations;
// Ceres then reports USER_SUCCESS, which termination_of_ceres() maps to "converged".
class StagnationStop : public ceres::IterationCallback {
 public:
  static constexpr std::size_t kWindow = 50;
  static constexpr double kRelative = 1e-3;

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    costs_.push_back(summary.cost);
    if (costs_.size() <= kWindow) return ceres::SOLVER_CONTINUE;
    const double before = costs_.front();
    costs_.pop_front();
    if (!(before - summary.cost <= kRelative * summary.cost)) return ceres::SOLVER_CONTINUE;
    stopped_ = true;
    last_cost_ = summary.cost;
    iteration_ = static_cast<std::size_t>(summary.iteration);
    return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
  }

  bool stopped() const { return stopped_; }
  // The reason in the words of a Ceres summary message.
  std::string message() const {
    return fmt::format(
        "Converged: the cost {:.6g} fell by less than {:g} (relative) over the {} iterations "
        "up to iteration {}.",
        last_cost_, kRelative, kWindow, iteration_);
  }

 private:
  std::deque<double> costs_;
  bool stopped_ = false;
  double last_cost_ = 0.0;
  std::size_t iteration_ = 0;
};

}  // namespace hyst::detail
