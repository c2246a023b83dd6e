// ns/sample of the PI model (step and simulate) and of its analytic inverse, for m operators.
// Items processed = samples, so Google Benchmark reports samples/s; ns/sample = 1e9 / rate.

#include <vector>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/signals/generators.hpp"

namespace {

constexpr std::size_t kSamples = 1 << 16;

hyst::PrandtlIshlinskii make_model(std::size_t operators) {
  std::vector<double> weights(operators);
  for (std::size_t j = 0; j < operators; ++j)
    weights[j] = 1.0 / static_cast<double>(j + 1);
  return hyst::PrandtlIshlinskii(
      {.thresholds = hyst::uniform_thresholds(operators, 2.0 / static_cast<double>(operators)),
       .weights = weights});
}

std::vector<double> make_input() {
  return hyst::signals::generate(
      hyst::signals::TimeGrid{kSamples, 1e-4},
      hyst::signals::RandomWalk{.max_step = 0.05, .lower = -2, .upper = 2, .start = 0, .seed = 1});
}

void BM_PiStep(benchmark::State& bench) {
  const auto model = make_model(static_cast<std::size_t>(bench.range(0)));
  auto state = model.initial_state();
  const auto input = make_input();
  for (auto _ : bench) {
    for (double v : input)
      benchmark::DoNotOptimize(model.step(state, v));
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input.size()));
}

void BM_PiSimulate(benchmark::State& bench) {
  const auto model = make_model(static_cast<std::size_t>(bench.range(0)));
  auto state = model.initial_state();
  const auto input = make_input();
  std::vector<double> output(input.size());
  for (auto _ : bench) {
    hyst::simulate(model, state, input, output);
    benchmark::DoNotOptimize(output.data());
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input.size()));
}

void BM_InversePiInvert(benchmark::State& bench) {
  const auto model = make_model(static_cast<std::size_t>(bench.range(0)));
  const hyst::InversePrandtlIshlinskii inverse(model);
  auto state = inverse.initial_state();
  const auto targets = make_input();
  std::vector<double> inputs(targets.size());
  for (auto _ : bench) {
    benchmark::DoNotOptimize(hyst::invert(inverse, state, targets, inputs));
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * targets.size()));
}

// The registry's inverse (the path of `hyst invert` and Python's Inverse.invert) on the same
// targets: the step inverse below kPiBatchInverseMinOperators plays, the O(log m) batch inverse
// from there on.
void BM_RegistryPiInvert(benchmark::State& bench) {
  const auto model = make_model(static_cast<std::size_t>(bench.range(0)));
  const auto dynamic = hyst::ModelRegistry::builtin().find("pi").create(
      nlohmann::json{{"thresholds", model.params().thresholds},
                     {"weights", model.params().weights}},
      nullptr);
  auto inverse = dynamic->inverse({});
  const auto targets = make_input();
  std::vector<double> inputs(targets.size());
  for (auto _ : bench) {
    benchmark::DoNotOptimize(inverse->invert(targets, inputs));
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * targets.size()));
}

}  // namespace

BENCHMARK(BM_PiStep)->Arg(8)->Arg(16)->Arg(64);
BENCHMARK(BM_PiSimulate)->Arg(8)->Arg(16)->Arg(64);
BENCHMARK(BM_InversePiInvert)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Arg(256)->Arg(1024);
BENCHMARK(BM_RegistryPiInvert)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Arg(256)->Arg(1024);
