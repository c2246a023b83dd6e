#pragma once
// The multistart rule of every Ceres-based fitter: each start runs a short local solve (the
// screening); the run of lowest cost continues up to the full iteration budget unless it already
// ended by its own rule. Without screening (`screen` false), every start runs the full budget and
// the lowest cost is kept (what suits a neural network's random initialisations, where a short run
// says little).
//
// The fitter supplies the local solve and the continuation; its run type has the members
//   double cost;             what the starts are ranked by (lower is better)
//   bool usable;             the solve gave a solution that can be kept
//   bool finished;           converged or stopped by its own rule: no continuation
//   std::size_t iterations;  iterations the solve took
// multistart_fit.hpp drives bounded fixed-size problems with it, fit_narx.cpp NARX's two-stage
// training.

#include <cstddef>
#include <limits>
#include <utility>

namespace hyst::detail {

struct MultistartBudget {
  bool screen = true;                     // false: every start runs max_iterations, none continues
  std::size_t screening_iterations = 10;  // per start
  std::size_t max_iterations = 100;       // of the best start's continuation (0: none)
};

template <class Run>
struct MultistartRuns {
  Run best{};
  std::size_t best_start = 0;
  std::size_t iterations = 0;           // of every solve and the continuation
  std::size_t refining_iterations = 0;  // of the continuation of the best start
  bool found = false;                   // some start gave a usable run
};

// solve(start index, iterations) -> Run; continue_run(const Run&, iterations) -> Run.
template <class Solve, class Continue>
auto run_multistart(std::size_t starts, const MultistartBudget& budget, Solve&& solve,
                    Continue&& continue_run) {
  using Run = decltype(solve(std::size_t{0}, std::size_t{0}));
  MultistartRuns<Run> runs;
  double best_cost = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < starts; ++s) {
    Run run = solve(s, budget.screen ? budget.screening_iterations : budget.max_iterations);
    runs.iterations += run.iterations;
    if (run.usable && run.cost < best_cost) {
      best_cost = run.cost;
      runs.best = std::move(run);
      runs.best_start = s;
      runs.found = true;
    }
  }
  if (runs.found && budget.screen && budget.max_iterations > 0 && !runs.best.finished) {
    runs.best = continue_run(runs.best, budget.max_iterations);
    runs.refining_iterations = runs.best.iterations;
    runs.iterations += runs.refining_iterations;
  }
  return runs;
}

}  // namespace hyst::detail
