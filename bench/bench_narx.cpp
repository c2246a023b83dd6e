// ns/sample of the NARX model's step in free run, for hidden layer sizes h (one layer) with
// 6 input lags, 6 output lags and 4 plays (17 regressors, the Bouc-Wen benchmark structure), and
// for two layers [h, h]. Items processed = samples.

#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>

#include "hyst/models/narx.hpp"
#include "hyst/signals/generators.hpp"

namespace {

constexpr std::size_t kSamples = 1 << 14;

hyst::Narx make_model(std::vector<std::size_t> hidden) {
  hyst::Narx::Params p;
  p.input_lags = 6;
  p.output_lags = 6;
  p.play_thresholds = {0.2, 0.4, 0.6, 0.8};
  p.hidden_sizes = std::move(hidden);
  p.weights.resize(hyst::Narx::network_parameter_count(17, p.hidden_sizes));
  // Small weights with alternating signs: a stable model, its output stays bounded.
  for (std::size_t i = 0; i < p.weights.size(); ++i)
    p.weights[i] = (i % 2 == 0 ? 0.02 : -0.03);
  return hyst::Narx(p);
}

void run(benchmark::State& bench, const hyst::Narx& model) {
  auto state = model.initial_state();
  const auto input = hyst::signals::generate(
      hyst::signals::TimeGrid{kSamples, 1e-3},
      hyst::signals::RandomWalk{.max_step = 0.05, .lower = -1, .upper = 1, .start = 0, .seed = 1});
  for (auto _ : bench) {
    for (const double v : input)
      benchmark::DoNotOptimize(model.step(state, v));
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input.size()));
}

void BM_NarxStepOneLayer(benchmark::State& bench) {
  run(bench, make_model({static_cast<std::size_t>(bench.range(0))}));
}

void BM_NarxStepTwoLayers(benchmark::State& bench) {
  const auto h = static_cast<std::size_t>(bench.range(0));
  run(bench, make_model({h, h}));
}

}  // namespace

BENCHMARK(BM_NarxStepOneLayer)->Arg(4)->Arg(12)->Arg(32);
BENCHMARK(BM_NarxStepTwoLayers)->Arg(4)->Arg(12);
