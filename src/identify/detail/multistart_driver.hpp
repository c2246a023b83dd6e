#pragma once
// The multistart rule of every Ceres-based fitter: each start runs a short local solve (the
// screening); the `refined_starts` runs of lowest cost (usually 1) continue up to the full
// iteration budget unless they already ended by their own rule (`always_continue`: even then, for a
// screening at a lower accuracy than the continuation), and the lowest final cost is kept. Without
// screening (`screen` false), every start runs the full budget and the lowest cost is kept (what
// suits a neural network's random initialisations, where a short run says little).
//
// The fitter supplies the local solve and the continuation; its run type has the members
//   double cost;             what the starts are ranked by (lower is better)
//   bool usable;             the solve gave a solution that can be kept
//   bool finished;           converged or stopped by its own rule: no continuation
//   std::size_t iterations;  iterations the solve took
// multistart_fit.hpp drives bounded fixed-size problems with it, fit_narx.cpp NARX's two-stage
// training.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "hyst/core/progress.hpp"

namespace hyst::detail {

struct MultistartBudget {
  bool screen = true;                     // false: every start runs max_iterations, none continues
  std::size_t screening_iterations = 10;  // per start
  std::size_t refined_starts = 1;         // screened runs that continue (at least 1)
  std::size_t max_iterations = 100;       // of each continuation (0: none)
  bool always_continue = false;           // continue runs that ended in the screening too
  ProgressCallback progress{};  // told before each start and the continuation (task "starts")
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
  struct Screened {
    Run run;
    std::size_t start;
  };
  MultistartRuns<Run> runs;
  std::vector<Screened> usable;
  // The steps: every start, then the continuations (counted as one per refined start).
  const std::size_t steps =
      starts + (budget.screen ? std::max<std::size_t>(budget.refined_starts, 1) : 0);
  std::size_t done = 0;
  const auto tell = [&](const char* what) {
    if (budget.progress) budget.progress({"starts", done, steps, what});
  };
  for (std::size_t s = 0; s < starts; ++s) {
    tell(budget.screen ? "screening" : "start");
    ++done;
    Run run = solve(s, budget.screen ? budget.screening_iterations : budget.max_iterations);
    runs.iterations += run.iterations;
    if (run.usable && run.cost < std::numeric_limits<double>::infinity()) {
      usable.push_back({std::move(run), s});
    }
  }
  if (usable.empty()) {
    done = steps;
    tell("");
    return runs;
  }
  std::stable_sort(usable.begin(), usable.end(),
                   [](const Screened& x, const Screened& y) { return x.run.cost < y.run.cost; });
  const std::size_t refined =
      budget.screen ? std::clamp<std::size_t>(budget.refined_starts, 1, usable.size()) : 1;
  for (std::size_t i = 0; i < refined; ++i) {
    Run run = std::move(usable[i].run);
    std::size_t continued = 0;
    if (budget.screen && (budget.always_continue || (budget.max_iterations > 0 && !run.finished))) {
      tell("refining");
      ++done;
      run = continue_run(run, budget.max_iterations);
      continued = run.iterations;
      runs.iterations += continued;
    }
    // The first candidate is kept whatever its continuation gave (one refined start: as it
    // ended); a later one replaces it when usable and lower.
    if (!runs.found || (run.usable && (!runs.best.usable || run.cost < runs.best.cost))) {
      runs.best = std::move(run);
      runs.best_start = usable[i].start;
      runs.refining_iterations = continued;
      runs.found = true;
    }
  }
  done = steps;
  tell("");
  return runs;
}

}  // namespace hyst::detail
