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
// `max_iterations`, and the lowest final cost wins.
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

// Throws hyst::Error when a start is outside its bounds or no start gives a usable solution.
// `screening` computes the start costs, the global stage and the screening iterations; `functor`
// the refinement of the best start, which then always runs (a cheaper screening functor, e.g. a
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
  struct Screened {
    double cost;
    std::size_t start;
    std::array<double, N> q;
    ceres::Solver::Summary summary;
  };
  MultistartResult<N> result;
  std::vector<Screened> screened;
  for (std::size_t s = 0; s < all_starts.size(); ++s) {
    std::array<double, N> q = all_starts[s];
    if (!std::isfinite(start_costs[s])) continue;
    const auto summary = solve_bounded(screening, q, options, options.screening_iterations);
    result.iterations +=
        static_cast<std::size_t>(summary.num_successful_steps + summary.num_unsuccessful_steps);
    if (summary.IsSolutionUsable()) screened.push_back({summary.final_cost, s, q, summary});
  }
  if (screened.empty()) {
    throw Error(fmt::format("{} fit: Ceres found no usable solution from any of the {} starts",
                            what, starts.size()));
  }
  std::stable_sort(screened.begin(), screened.end(),
                   [](const Screened& x, const Screened& y) { return x.cost < y.cost; });
  // The best `refined_starts` continue; the lowest final cost wins.
  double best_cost = std::numeric_limits<double>::infinity();
  ceres::Solver::Summary best_summary;
  const std::size_t refined =
      std::min(std::max<std::size_t>(options.refined_starts, 1), screened.size());
  for (std::size_t i = 0; i < refined; ++i) {
    Screened candidate = screened[i];
    auto summary = candidate.summary;
    if (options.max_iterations > 0 &&
        (always_refine || summary.termination_type == ceres::NO_CONVERGENCE)) {
      summary = solve_bounded(functor, candidate.q, options, options.max_iterations);
      const auto steps =
          static_cast<std::size_t>(summary.num_successful_steps + summary.num_unsuccessful_steps);
      result.iterations += steps;
      if (!summary.IsSolutionUsable()) continue;
      if (summary.final_cost < best_cost) result.refining_iterations = steps;
    } else if (always_refine) {  // no refinement: the cost of the functor itself
      summary.final_cost = least_squares_cost(functor, candidate.q);
    }
    if (summary.final_cost < best_cost) {
      best_cost = summary.final_cost;
      best_summary = summary;
      result.best_start = candidate.start;
      result.initial_cost = start_costs[candidate.start];
      result.q = candidate.q;
    }
  }
  if (!std::isfinite(best_cost)) {
    throw Error(fmt::format("{} fit: Ceres found no usable solution from any of the {} starts",
                            what, starts.size()));
  }
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
