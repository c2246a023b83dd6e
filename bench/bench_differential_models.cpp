// ns/sample of the differential hysteresis models at the sample rates of the data sets, and fit
// times. Items processed = samples, so Google Benchmark reports samples/s; ns/sample = 1e9 / rate.
//  - Bouc-Wen oscillator: benchmark input (multisine-like, RMS ~50 N) at 750 Hz with the
//    benchmark's 20 RK4 sub-steps, and at the 7.5 kHz band-limited grid with 1 sub-step;
//  - Jiles-Atherton: a B(H) loop of 129 samples per period, +-80 A/m (the Mn-Zn ferrite records),
//    fitted-ferrite-like parameters, default integration (RK4 under error control);
//  - Jiles-Atherton major loop (issue 21): 4 673 samples H = 65 kA/m cos(2 pi j / 4 672) from the
//    demagnetised state (the first sample rises 0 -> 65 kA/m), Venkataraman, M_s = 1.6e6 A/m,
//    a = 560 A/m, k = 1200 A/m, c = 0.1, alpha = 7e-4; default integration (RK4 under error
//    control), adaptive Dormand-Prince (1e-6 A/m) and fixed RK4 steps k / 50 (the former default);
//  - Bouc-Wen, Duhem, backlash-like: a random walk (rate independent: no sample rate).
// Fits: the oscillator on 2 x 8192 samples (x10 oversampled), Jiles-Atherton on one loop.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_bouc_wen_oscillator.hpp"
#include "hyst/identify/fit_jiles_atherton.hpp"
#include "hyst/models/backlash_like.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "hyst/models/duhem.hpp"
#include "hyst/signals/band_limited.hpp"

namespace {

constexpr std::size_t kSamples = 1 << 15;

std::vector<double> multisine(std::size_t n) {  // 5..150 Hz at 750 Hz, random phases
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> phase(0.0, 2 * std::numbers::pi);
  std::vector<double> u(n, 0.0);
  for (int f = 5; f <= 150; f += 5) {
    const double p = phase(rng);
    for (std::size_t k = 0; k < n; ++k)
      u[k] += 13.0 * std::sin(2 * std::numbers::pi * f * k / 750.0 + p);
  }
  return u;
}

std::vector<double> random_walk(std::size_t n, double scale) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> step(-0.2, 0.2);
  std::vector<double> v(n);
  double x = 0.0;
  for (auto& value : v) {
    x = std::clamp(x + step(rng), -2.0, 2.0);
    value = scale * x;
  }
  return v;
}

hyst::JilesAtherton::Params ferrite_like() {
  hyst::JilesAtherton::Params p;
  p.ms = 3.2e5;
  p.a = 26.0;
  p.k = 48.0;
  p.c = 0.91;
  p.alpha = 2e-4;
  return p;
}

std::vector<double> loop_field(std::size_t n, std::size_t per_period) {
  std::vector<double> h(n);
  for (std::size_t k = 0; k < n; ++k)
    h[k] = 80.0 * std::cos(2 * std::numbers::pi * k / per_period);
  return h;
}

template <class Model>
void run(benchmark::State& bench, const Model& model, const std::vector<double>& input) {
  std::vector<double> output(input.size());
  for (auto _ : bench) {
    auto state = model.initial_state();
    hyst::simulate(model, state, input, output);
    benchmark::DoNotOptimize(output.data());
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input.size()));
}

void BM_BoucWenOscillator750Hz20Substeps(benchmark::State& bench) {
  run(bench, hyst::BoucWenOscillator(hyst::BoucWenOscillator::benchmark()), multisine(kSamples));
}
BENCHMARK(BM_BoucWenOscillator750Hz20Substeps);

void BM_BoucWenOscillator750HzAdaptive(benchmark::State& bench) {
  auto p = hyst::BoucWenOscillator::benchmark();
  p.tolerance = 1e-8;
  run(bench, hyst::BoucWenOscillator(p), multisine(kSamples));
}
BENCHMARK(BM_BoucWenOscillator750HzAdaptive);

void BM_BoucWenOscillator7500Hz1Substep(benchmark::State& bench) {
  auto p = hyst::BoucWenOscillator::benchmark();
  p.sample_time /= 10.0;
  p.substeps = 1;
  run(bench, hyst::BoucWenOscillator(p), hyst::upsample_periodic(multisine(kSamples / 10), 10));
}
BENCHMARK(BM_BoucWenOscillator7500Hz1Substep);

void BM_JilesAthertonLoop129(benchmark::State& bench) {
  auto p = ferrite_like();
  p.variant = static_cast<hyst::JilesAthertonVariant>(bench.range(0));
  run(bench, hyst::JilesAtherton(p), loop_field(kSamples, 129));
}
BENCHMARK(BM_JilesAthertonLoop129)->Arg(0)->Arg(1);

std::vector<double> major_loop_field() {
  constexpr std::size_t kPoints = 4673;
  std::vector<double> h(kPoints);
  for (std::size_t j = 0; j < kPoints; ++j)
    h[j] = 65e3 * std::cos(2 * std::numbers::pi * static_cast<double>(j) / (kPoints - 1));
  return h;
}

// Arg: 0 = the default (RK4 under error control), 1 = adaptive Dormand-Prince, tolerance 1e-6 A/m,
// 2 = fixed RK4 steps of k / 50 (the default until 2026-11-27).
void BM_JilesAthertonMajorLoop4673(benchmark::State& bench) {
  hyst::JilesAtherton::Params p;
  p.variant = hyst::JilesAthertonVariant::venkataraman;
  p.ms = 1.6e6;
  p.a = 560.0;
  p.k = 1200.0;
  p.c = 0.1;
  p.alpha = 7e-4;
  if (bench.range(0) == 1) p.tolerance = 1e-6;
  if (bench.range(0) == 2) p.max_field_step = p.k / 50.0;
  run(bench, hyst::JilesAtherton(p), major_loop_field());
}
BENCHMARK(BM_JilesAthertonMajorLoop4673)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

// n = 1 (the default): the exact per-sample solution.
void BM_BoucWenExact(benchmark::State& bench) {
  run(bench, hyst::BoucWen(hyst::BoucWen::Params{}), random_walk(kSamples, 1.0));
}
BENCHMARK(BM_BoucWenExact);

// n = 1.5: classical RK4, 20 sub-steps per sample.
void BM_BoucWen20Substeps(benchmark::State& bench) {
  hyst::BoucWen::Params p;
  p.n = 1.5;
  run(bench, hyst::BoucWen(p), random_walk(kSamples, 1.0));
}
BENCHMARK(BM_BoucWen20Substeps);

void BM_Duhem20Substeps(benchmark::State& bench) {
  run(bench, hyst::Duhem(hyst::Duhem::Params{}), random_walk(kSamples, 1.0));
}
BENCHMARK(BM_Duhem20Substeps);

void BM_BacklashLikeExact(benchmark::State& bench) {
  run(bench, hyst::BacklashLike(hyst::BacklashLike::Params{}), random_walk(kSamples, 1.0));
}
BENCHMARK(BM_BacklashLikeExact);

void BM_FitBoucWenOscillator(benchmark::State& bench) {
  const auto period = multisine(8192);
  const auto fine_period = hyst::upsample_periodic(period, 10);
  std::vector<double> fine(fine_period);
  fine.insert(fine.end(), fine_period.begin(), fine_period.end());
  auto p = hyst::BoucWenOscillator::benchmark();
  p.sample_time /= 10.0;
  p.substeps = 1;
  const auto y = hyst::simulate_bouc_wen_oscillator(hyst::BoucWenOscillator(p), fine, 10);
  const hyst::BoucWenOscillatorRecord record{fine, y, 10, 8192};
  for (auto _ : bench) {
    const auto fit = hyst::fit_bouc_wen_oscillator(std::span(&record, 1), {});
    benchmark::DoNotOptimize(fit.report.final_cost);
  }
}
BENCHMARK(BM_FitBoucWenOscillator)->Unit(benchmark::kSecond)->Iterations(1);

void BM_FitJilesAthertonLoop(benchmark::State& bench) {
  const auto h = loop_field(129, 129);
  auto p = ferrite_like();
  p.max_field_step = 160.0 / 2000.0;
  const auto b = hyst::simulate_bh_loop(hyst::JilesAtherton(p), h);
  const hyst::BhLoop loop{h, b};
  for (auto _ : bench) {
    const auto fit = hyst::fit_jiles_atherton(std::span(&loop, 1), {}, {});
    benchmark::DoNotOptimize(fit.report.final_cost);
  }
}
BENCHMARK(BM_FitJilesAthertonLoop)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
