#pragma once
// Bounded nonlinear least squares from several starting points, with Ceres (Levenberg-Marquardt,
// automatic derivatives), shared by the fitters of the differential hysteresis models.
//
// The functor computes the residuals of a fixed-size parameter vector q (the fitters scale their
// physical parameters so that q is of order 1) for any scalar type T:
//   template <class T> bool operator()(const T* q, T* residuals) const;
//   std::size_t residuals() const;
// With `global_evaluations` > 0, a global search of the bounded box (global_stage.hpp) first runs
// from the start of lowest cost, and its best point is one more start (index starts.size()).
// Every start runs `screening_iterations`; the best `refined_starts` (default 1) continue up to
// `max_iterations`, and the lowest final cost wins (multistart_driver.hpp).
// Parameters listed in `fixed` are held at their start value.
// Convergence: the tests of convergence.hpp, the same for every Ceres-based fitter.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/identify/fit_report.hpp"

#include "convergence.hpp"
#include "global_stage.hpp"
#include "multistart_driver.hpp"

namespace hyst::detail {

template <std::size_t N>
struct MultistartOptions {
  std::array<double, N> lower{};
  std::array<double, N> upper{};
  std::vector<int> fixed;              // indices held at their start value
  std::size_t global_evaluations = 0;  // cost evaluations of the global stage; 0: none
  std::size_t screening_iterations = 10;
  std::size_t refined_starts = 1;  // the best this many after screening continue
  std::size_t max_iterations = 100;
  double function_tolerance = kFunctionTolerance;
  ProgressCallback progress{};  // of the multistart driver (task "starts"); may be empty
};

template <std::size_t N>
struct MultistartResult {
  std::array<double, N> q{};
  Termination termination = Termination::failed;
  std::string message;
  std::size_t iterations = 0;
  std::size_t refining_iterations = 0;  // of the best start after screening
  std::size_t best_start = 0;
  double initial_cost = 0.0;  // cost of the best start before it was iterated
  double final_cost = 0.0;
  std::array<bool, N> at_bound{};  // free parameters within 1e-6 of a bound (held ones: false)
};

inline bool all_finite(double x) {
  return std::isfinite(x);
}
template <class T, int M>
bool all_finite(const ceres::Jet<T, M>& x) {
  return std::isfinite(x.a) && x.v.allFinite();
}

// The functor with a check that every residual and derivative is finite: a step that overflows
// is reported to Ceres as infeasible (it then shortens the step) instead of as NaN.
template <class Functor>
struct FiniteResiduals {
  Functor functor;
  template <class T>
  bool operator()(const T* q, T* residuals) const {
    if (!functor(q, residuals)) return false;
    for (std::size_t r = 0; r < functor.residuals(); ++r) {
      if (!all_finite(residuals[r])) return false;
    }
    return true;
  }
};

template <std::size_t N, class Functor>
double least_squares_cost(const Functor& functor, const std::array<double, N>& q) {
  std::vector<double> residuals(functor.residuals());
  if (!functor(q.data(), residuals.data())) return std::numeric_limits<double>::infinity();
  double cost = 0.0;
  for (double r : residuals)
    cost += 0.5 * r * r;
  return std::isfinite(cost) ? cost : std::numeric_limits<double>::infinity();
}

template <std::size_t N, class Functor>
ceres::Solver::Summary solve_bounded(const Functor& functor, std::array<double, N>& q,
                                     const MultistartOptions<N>& options, std::size_t iterations) {
  ceres::Problem problem;
  auto* cost = new ceres::AutoDiffCostFunction<FiniteResiduals<Functor>, ceres::DYNAMIC,
                                               static_cast<int>(N)>(
      new FiniteResiduals<Functor>{functor}, static_cast<int>(functor.residuals()));
  problem.AddResidualBlock(cost, nullptr, q.data());
  for (std::size_t i = 0; i < N; ++i) {
    problem.SetParameterLowerBound(q.data(), static_cast<int>(i), options.lower[i]);
    problem.SetParameterUpperBound(q.data(), static_cast<int>(i), options.upper[i]);
  }
  if (!options.fixed.empty()) {
    problem.SetManifold(q.data(), new ceres::SubsetManifold(static_cast<int>(N), options.fixed));
  }
  auto solver = levenberg_marquardt_options(iterations, options.function_tolerance);
  StagnationStop stagnation;
  solver.callbacks.push_back(&stagnation);
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (stagnation.stopped()) summary.message = stagnation.message();
  return summary;
}

// The engine's options for the bounds [lower, upper] and the engine settings that the fitter's
// options struct has (those add_multistart_options() describes to users).
template <std::size_t N, class FitOptions>
MultistartOptions<N> multistart_options(const std::array<double, N>& lower,
                                        const std::array<double, N>& upper,
                                        const FitOptions& options) {
  MultistartOptions<N> engine;
  engine.lower = lower;
  engine.upper = upper;
  if constexpr (requires { options.global_evaluations; }) {
    engine.global_evaluations = options.global_evaluations;
  }
  if constexpr (requires { options.screening_iterations; }) {
    engine.screening_iterations = options.screening_iterations;
  }
  if constexpr (requires { options.refined_starts; }) {
    engine.refined_starts = options.refined_starts;
  }
  if constexpr (requires { options.max_iterations; }) {
    engine.max_iterations = options.max_iterations;
  }
  if constexpr (requires { options.function_tolerance; }) {
    engine.function_tolerance = options.function_tolerance;
  }
  if constexpr (requires { options.progress; }) engine.progress = options.progress;
  return engine;
}

// Throws hyst::Error when a start is outside its bounds or no start gives a usable solution.
// `screening` computes the start costs, the global stage and the screening iterations; `functor`
// the continuation of the best starts, which then always runs (a cheaper screening functor, e.g. a
// coarser integration, with the final iterations at full accuracy). Both: the same residuals.
template <std::size_t N, class Screening, class Functor>
MultistartResult<N> multistart_fit(const Screening& screening, const Functor& functor,
                                   const std::vector<std::array<double, N>>& starts,
                                   const MultistartOptions<N>& options, std::string_view what,
                                   bool always_refine = true) {
  if (starts.empty()) throw Error(fmt::format("{} fit: no starting point", what), "starts");
  for (std::size_t s = 0; s < starts.size(); ++s) {
    for (std::size_t i = 0; i < N; ++i) {
      if (!(options.lower[i] < options.upper[i])) {
        throw Error(fmt::format("{} fit: bound of parameter {}: lower {} must be < upper {}", what,
                                i, options.lower[i], options.upper[i]),
                    "bounds");
      }
      if (!(starts[s][i] >= options.lower[i] && starts[s][i] <= options.upper[i])) {
        throw Error(fmt::format("{} fit: start {} parameter {} = {} is outside [{}, {}]", what, s,
                                i, starts[s][i], options.lower[i], options.upper[i]),
                    "starts");
      }
    }
  }
  std::vector<std::array<double, N>> all_starts = starts;
  std::vector<double> start_costs;
  for (const auto& start : starts)
    start_costs.push_back(least_squares_cost(screening, start));
  if (options.global_evaluations > 0) {
    std::size_t lowest = 0;
    for (std::size_t s = 1; s < starts.size(); ++s) {
      if (start_costs[s] < start_costs[lowest]) lowest = s;
    }
    std::array<double, N> q = starts[lowest];
    const auto cost_of = [&screening](const std::array<double, N>& point) {
      return least_squares_cost(screening, point);
    };
    const auto global = global_search(cost_of, q, start_costs[lowest], options.lower, options.upper,
                                      options.fixed, options.global_evaluations);
    if (global.improved) {
      all_starts.push_back(q);
      start_costs.push_back(global.cost);
    }
  }
  // One local solve: from start `index`, or from where a screening run ended.
  struct BoundedRun {
    std::array<double, N> q{};
    ceres::Solver::Summary summary;
    double start_cost = 0.0;
    double cost = 0.0;
    bool usable = false;
    bool finished = false;
    std::size_t iterations = 0;
  };
  const auto run_from = [&](const auto& residuals, std::array<double, N> q, double start_cost,
                            std::size_t iterations) {
    BoundedRun run;
    run.summary = solve_bounded(residuals, q, options, iterations);
    run.q = q;
    run.start_cost = start_cost;
    run.cost = run.summary.final_cost;
    run.usable = run.summary.IsSolutionUsable();
    run.finished = run.summary.termination_type != ceres::NO_CONVERGENCE;
    run.iterations = static_cast<std::size_t>(run.summary.num_successful_steps +
                                              run.summary.num_unsuccessful_steps);
    return run;
  };
  const auto runs = run_multistart(
      all_starts.size(),
      MultistartBudget{.screening_iterations = options.screening_iterations,
                       .refined_starts = options.refined_starts,
                       .max_iterations = options.max_iterations,
                       .always_continue = always_refine,
                       .progress = options.progress},
      [&](std::size_t s, std::size_t iterations) {
        // A start whose cost is not finite is not solved from.
        if (!std::isfinite(start_costs[s])) return BoundedRun{};
        return run_from(screening, all_starts[s], start_costs[s], iterations);
      },
      [&](const BoundedRun& best, std::size_t iterations) {
        return run_from(functor, best.q, best.start_cost, iterations);
      });
  if (!runs.found) {
    throw Error(fmt::format("{} fit: Ceres found no usable solution from any of the {} starts",
                            what, starts.size()));
  }
  MultistartResult<N> result;
  result.q = runs.best.q;
  result.best_start = runs.best_start;
  result.initial_cost = runs.best.start_cost;
  result.iterations = runs.iterations;
  result.refining_iterations = runs.refining_iterations;
  const ceres::Solver::Summary& best_summary = runs.best.summary;
  result.termination = termination_of_ceres(best_summary);
  result.message = best_summary.message;
  result.final_cost = best_summary.final_cost;
  for (std::size_t i = 0; i < N; ++i) {
    const bool held = std::find(options.fixed.begin(), options.fixed.end(), static_cast<int>(i)) !=
                      options.fixed.end();
    const double width = options.upper[i] - options.lower[i];
    result.at_bound[i] = !held && (result.q[i] - options.lower[i] <= 1e-6 * width ||
                                   options.upper[i] - result.q[i] <= 1e-6 * width);
  }
  return result;
}

// One functor for every stage.
template <std::size_t N, class Functor>
MultistartResult<N> multistart_fit(const Functor& functor,
                                   const std::vector<std::array<double, N>>& starts,
                                   const MultistartOptions<N>& options, std::string_view what) {
  return multistart_fit(functor, functor, starts, options, what, false);
}

// Starting points divided by the parameter scale (the fitters iterate q = physical / scale).
template <std::size_t N>
std::vector<std::array<double, N>> scaled_starts(const std::vector<std::array<double, N>>& physical,
                                                 const std::array<double, N>& scale) {
  std::vector<std::array<double, N>> starts;
  for (const auto& start : physical) {
    std::array<double, N> q{};
    for (std::size_t i = 0; i < N; ++i)
      q[i] = start[i] / scale[i];
    starts.push_back(q);
  }
  return starts;
}

// The common part of a FitReport: how Ceres ended and the costs, the residuals having been divided
// by `residual_scale` (output units).
template <std::size_t N>
FitReport report_of(const MultistartResult<N>& result, double residual_scale,
                    std::size_t parameters, std::string model, std::string method) {
  FitReport report;
  report.model = std::move(model);
  report.method = std::move(method);
  report.termination = result.termination;
  report.message = result.message;
  report.iterations = result.iterations;
  report.initial_cost = result.initial_cost * residual_scale * residual_scale;
  report.final_cost = result.final_cost * residual_scale * residual_scale;
  report.parameters = parameters;
  std::size_t at_bound = 0;
  for (bool b : result.at_bound)
    at_bound += b ? 1 : 0;
  if (parameters > 0 && at_bound >= parameters) {
    report.take_verdict(
        FitQuality::degenerate,
        fmt::format("every one of the {} fitted parameters ended at a bound of its range: the "
                    "data do not determine them within it",
                    parameters));
  }
  return report;
}

}  // namespace hyst::detail
