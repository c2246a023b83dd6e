#pragma once
// The global stage of the multistart engine: a derivative-free search of the whole bounded box
// before Levenberg-Marquardt, for costs whose valleys the data-derived starts may all miss.
//
// NLopt's controlled random search with local mutation (GN_CRS2_LM, Kaelo & Ali 2006) keeps a
// population of 10 (n + 1) points drawn in the box (one of them the given start) and replaces its
// worst point by reflections of random simplices, so it needs neither derivatives nor a smooth
// cost: the relay-like reversals of hysteresis models make the cost piecewise smooth. It stops
// after `evaluations` cost evaluations; its best point becomes one more local start. The random
// generator is seeded before every search, so a fit is reproducible bit for bit.

#include <array>
#include <cmath>
#include <cstddef>
#include <exception>
#include <limits>
#include <vector>

#include <nlopt.hpp>

namespace hyst::detail {

// Seed of NLopt's generator for every global search (any fixed value; fixed for reproducibility).
inline constexpr unsigned long kGlobalStageSeed = 20261127;

struct GlobalStageResult {
  bool improved = false;  // the search found a point with a lower cost than `start`
  double cost = 0.0;
  std::size_t evaluations = 0;
};

// Searches the free parameters (those not in `fixed`) of q within [lower, upper], starting from q
// (whose cost is `start_cost`); on return q is the best point found. `cost_of(q)` returns the
// least-squares cost, or infinity where the model cannot be simulated.
template <std::size_t N, class Cost>
GlobalStageResult global_search(const Cost& cost_of, std::array<double, N>& q, double start_cost,
                                const std::array<double, N>& lower,
                                const std::array<double, N>& upper, const std::vector<int>& fixed,
                                std::size_t evaluations) {
  std::vector<std::size_t> free;
  for (std::size_t i = 0; i < N; ++i) {
    bool held = false;
    for (int f : fixed)
      held = held || static_cast<std::size_t>(f) == i;
    if (!held) free.push_back(i);
  }
  GlobalStageResult result{false, start_cost, 0};
  if (free.empty() || evaluations == 0) return result;

  struct Search {
    const Cost& cost_of;
    std::array<double, N> point;
    const std::vector<std::size_t>& free;
    std::size_t evaluations = 0;
  } search{cost_of, q, free};
  const auto objective = [](const std::vector<double>& x, std::vector<double>& /*gradient*/,
                            void* data) -> double {
    auto& s = *static_cast<Search*>(data);
    for (std::size_t j = 0; j < s.free.size(); ++j)
      s.point[s.free[j]] = x[j];
    ++s.evaluations;
    const double cost = s.cost_of(s.point);
    // CRS compares costs; an unusable point ranks last without an infinity in its arithmetic.
    return std::isfinite(cost) ? cost : std::numeric_limits<double>::max();
  };

  nlopt::opt optimizer(nlopt::GN_CRS2_LM, static_cast<unsigned>(free.size()));
  std::vector<double> x(free.size()), low(free.size()), high(free.size());
  for (std::size_t j = 0; j < free.size(); ++j) {
    x[j] = q[free[j]];
    low[j] = lower[free[j]];
    high[j] = upper[free[j]];
  }
  optimizer.set_lower_bounds(low);
  optimizer.set_upper_bounds(high);
  optimizer.set_min_objective(objective, &search);
  optimizer.set_maxeval(static_cast<int>(evaluations));
  nlopt::srand(kGlobalStageSeed);
  double best = start_cost;
  try {
    optimizer.optimize(x, best);
  } catch (const std::exception&) {
    // NLopt ends on round-off limits and the like with an exception; x still holds a point of
    // the search, whose cost is computed again below.
  }
  result.evaluations = search.evaluations;
  std::array<double, N> candidate = q;
  for (std::size_t j = 0; j < free.size(); ++j)
    candidate[free[j]] = x[j];
  const double candidate_cost = cost_of(candidate);
  if (std::isfinite(candidate_cost) && candidate_cost < start_cost) {
    q = candidate;
    result.improved = true;
    result.cost = candidate_cost;
  }
  return result;
}

}  // namespace hyst::detail
