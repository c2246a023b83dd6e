// ns/sample of the discrete Preisach model: the brute-force relay grid (every relay updated and
// summed) against the fast Everett form (staircase memory + running sums), for N = 21, 101 and
// 1001 levels, on the same input; and of the continuous forms and the numerical inverse.
// Items processed = samples, so Google Benchmark reports samples/s; ns/sample = 1e9 / rate.

#include <random>
#include <vector>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "hyst/core/invert.hpp"
#include "hyst/inverse/inverse_preisach.hpp"
#include "hyst/models/preisach.hpp"
#include "hyst/models/preisach_relay_grid.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/signals/generators.hpp"

namespace {

constexpr std::size_t kSamples = 1 << 12;

hyst::Preisach::Params grid_params(std::size_t levels) {
  std::mt19937_64 rng(levels);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> mu(hyst::preisach_relay_count(levels));
  for (double& m : mu)
    m = unit(rng);
  return {.everett = {.levels = levels, .lower = -1, .upper = 1, .weights = mu}};
}

// A random walk inside the grid's range: reversals at every scale, many nested loops.
std::vector<double> make_input() {
  return hyst::signals::generate(
      hyst::signals::TimeGrid{kSamples, 1e-4},
      hyst::signals::RandomWalk{.max_step = 0.05, .lower = -1, .upper = 1, .start = 0, .seed = 1});
}

template <class Model>
void run_steps(benchmark::State& bench, const Model& model) {
  auto state = model.initial_state();
  const auto input = make_input();
  for (auto _ : bench) {
    for (double v : input)
      benchmark::DoNotOptimize(model.step(state, v));
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input.size()));
}

void BM_PreisachBruteForce(benchmark::State& bench) {
  run_steps(bench, hyst::PreisachRelayGrid(grid_params(static_cast<std::size_t>(bench.range(0)))));
}

void BM_PreisachFast(benchmark::State& bench) {
  run_steps(bench, hyst::Preisach(grid_params(static_cast<std::size_t>(bench.range(0)))));
}

void BM_GaussianPreisach(benchmark::State& bench) {
  run_steps(bench, hyst::GaussianPreisach({.everett = {.lower = -1,
                                                       .upper = 1,
                                                       .saturation = 1,
                                                       .alpha_centre = 0.2,
                                                       .alpha_width = 0.2,
                                                       .beta_centre = -0.2,
                                                       .beta_width = 0.2}}));
}

hyst::TabulatedPreisach tabulated(std::size_t intervals) {
  const hyst::Preisach grid(grid_params(intervals));
  hyst::TabulatedEverett::Params table;
  for (std::size_t k = 0; k <= intervals; ++k)
    table.levels.push_back(-1.0 + 2.0 * static_cast<double>(k) / static_cast<double>(intervals));
  for (std::size_t a = 1; a <= intervals; ++a) {
    for (std::size_t c = 0; c < a; ++c)
      table.values.push_back(grid.everett()(table.levels[a], table.levels[c]));
  }
  return hyst::TabulatedPreisach({.everett = table});
}

void BM_TabulatedPreisach(benchmark::State& bench) {
  run_steps(bench, tabulated(static_cast<std::size_t>(bench.range(0))));
}

template <class Inverse>
void run_inverse(benchmark::State& bench, const Inverse& inverse) {
  auto state = inverse.initial_state();
  // Targets: the model's own output, so that every one is reachable.
  auto forward_state = inverse.forward().initial_state();
  std::vector<double> targets;
  for (double v : make_input())
    targets.push_back(inverse.forward().step(forward_state, v));
  std::vector<double> inputs(targets.size());
  for (auto _ : bench) {
    benchmark::DoNotOptimize(hyst::invert(inverse, state, targets, inputs));
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * targets.size()));
}

void BM_InversePreisach(benchmark::State& bench) {
  run_inverse(bench, hyst::InversePreisach(
                         hyst::Preisach(grid_params(static_cast<std::size_t>(bench.range(0))))));
}

void BM_InverseGaussianPreisach(benchmark::State& bench) {
  run_inverse(bench, hyst::InverseGaussianPreisach(
                         hyst::GaussianPreisach({.everett = {.lower = -1,
                                                             .upper = 1,
                                                             .saturation = 1,
                                                             .alpha_centre = 0.2,
                                                             .alpha_width = 0.2,
                                                             .beta_centre = -0.2,
                                                             .beta_width = 0.2}})));
}

}  // namespace

// One run of a registry model from its start state, as Python's Model.simulate makes it: on a
// copy of the whole model (arg 0: clone(), then simulate) or on a copy of its state alone (arg 1:
// simulate_from_state()), for a grid of 1001 levels (501 501 relay weights).
void BM_RegistryPreisachRunFromStart(benchmark::State& bench) {
  const auto params = grid_params(1001);
  const auto model = hyst::ModelRegistry::builtin()
                         .find("preisach")
                         .create(nlohmann::json{{"levels", params.everett.levels},
                                                {"lower", -1.0},
                                                {"upper", 1.0},
                                                {"weights", params.everett.weights}},
                                 nullptr);
  const auto input = make_input();
  std::vector<double> output(input.size());
  for (auto _ : bench) {
    if (bench.range(0) == 0) {
      model->clone()->simulate(input, output);
    } else {
      model->simulate_from_state(input, output);
    }
    benchmark::DoNotOptimize(output.data());
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input.size()));
}

BENCHMARK(BM_PreisachBruteForce)->Arg(21)->Arg(101)->Arg(1001);
BENCHMARK(BM_PreisachFast)->Arg(21)->Arg(101)->Arg(1001);
BENCHMARK(BM_GaussianPreisach);
BENCHMARK(BM_TabulatedPreisach)->Arg(40)->Arg(200);
BENCHMARK(BM_InversePreisach)->Arg(21)->Arg(101)->Arg(1001);
BENCHMARK(BM_InverseGaussianPreisach);
BENCHMARK(BM_RegistryPreisachRunFromStart)->Arg(0)->Arg(1);
