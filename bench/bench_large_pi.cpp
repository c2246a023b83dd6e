// PI models with many operators (10^4, 10^5, 10^6): building the analytic inverse, generating the
// C code of model and inverse (`hyst export --lang c` without the file write), and inverting
// 10^4 target samples through the registry (the path of `hyst invert`). Building and exporting
// are linear in the number of operators m, so each tenfold m costs about tenfold time; the
// inversion costs m per sample (every play operator is updated).

#include <cmath>
#include <cstddef>
#include <vector>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "hyst/export/export_c.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/registry/model_file.hpp"

namespace {

// Thresholds r_j = j / m, weights p_0 = 1 and a decaying tail (every partial sum > 0).
hyst::PrandtlIshlinskii::Params params(std::size_t m) {
  hyst::PrandtlIshlinskii::Params p;
  p.thresholds.resize(m);
  p.weights.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    const double x = static_cast<double>(j) / static_cast<double>(m);
    p.thresholds[j] = x;
    p.weights[j] = j == 0 ? 1.0 : 0.5 / static_cast<double>(m) * std::exp(-3.0 * x);
  }
  return p;
}

std::unique_ptr<hyst::DynamicModel> dynamic_model(std::size_t m) {
  const auto p = params(m);
  const nlohmann::json document = {
      {"model", "pi"},
      {"version", 1},
      {"params", {{"thresholds", p.thresholds}, {"weights", p.weights}, {"offset", 0.0}}}};
  return hyst::model_from_json(document, "bench");
}

void set_complexity(benchmark::State& state) {
  state.SetComplexityN(state.range(0));
  state.counters["operators"] = static_cast<double>(state.range(0));
}

void BM_PiBuildInverse(benchmark::State& state) {
  const hyst::PrandtlIshlinskii model(params(static_cast<std::size_t>(state.range(0))));
  for (auto _ : state) {
    const hyst::InversePrandtlIshlinskii inverse(model);
    benchmark::DoNotOptimize(inverse.inverse_operator().params().weights.data());
  }
  set_complexity(state);
}
BENCHMARK(BM_PiBuildInverse)
    ->RangeMultiplier(10)
    ->Range(10000, 1000000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN);

void BM_PiGenerateC(benchmark::State& state) {
  const auto model = dynamic_model(static_cast<std::size_t>(state.range(0)));
  hyst::CExportOptions options;
  options.prefix = "big";
  for (auto _ : state) {
    const auto code = hyst::generate_c(*model, options);
    benchmark::DoNotOptimize(code.source.data());
  }
  set_complexity(state);
}
BENCHMARK(BM_PiGenerateC)
    ->RangeMultiplier(10)
    ->Range(10000, 1000000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN);

// 10^4 targets (a growing sine within the reachable range) from the model's initial state.
void BM_PiInvert10kSamples(benchmark::State& state) {
  const auto model = dynamic_model(static_cast<std::size_t>(state.range(0)));
  constexpr std::size_t samples = 10000;
  std::vector<double> targets(samples);
  for (std::size_t k = 0; k < samples; ++k) {
    const double t = static_cast<double>(k);
    targets[k] = 1.2 * std::sin(2.0 * 3.141592653589793 * t / 1000.0) * (1.0 + t / samples);
  }
  std::vector<double> inputs(samples);
  for (auto _ : state) {
    auto inverse = model->inverse({});
    benchmark::DoNotOptimize(inverse->invert(targets, inputs));
  }
  set_complexity(state);
}
BENCHMARK(BM_PiInvert10kSamples)
    ->RangeMultiplier(10)
    ->Range(10000, 1000000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN);

}  // namespace
