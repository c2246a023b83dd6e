// ns/sample of the generalized PI model (step and simulate) and of its inverse (IGPI), for m = 10
// and m = 50 (m + 1 operators), and the wall time of one Ceres fit on 10 000 samples.
// Items processed = samples, so Google Benchmark reports samples/s; ns/sample = 1e9 / rate.

#include <cmath>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_generalized_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_generalized_prandtl_ishlinskii.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"
#include "hyst/signals/generators.hpp"

namespace {

constexpr std::size_t kSamples = 1 << 16;

// The ASSUMED MSMA-like set of msma_synth.py (0..8 A -> N), with m operators spread over the same
// threshold span (alpha = 10 / m) and the weight sum kept near 1.
hyst::GpiParams make_params(std::size_t m, hyst::EnvelopeKind kind = hyst::EnvelopeKind::tanh) {
  const double scale = 10.0 / static_cast<double>(m);
  hyst::GpiParams params{.envelope = kind,
                         .ascending = {40.0, 0.8, -3.2, 40.0},
                         .descending = {40.0, 0.8, -2.8, 40.0},
                         .rho = 0.143 * scale,
                         .tau = 0.1,
                         .alpha = scale,
                         .m = m,
                         .input_min = 0.0,
                         .input_max = 8.0};
  if (kind == hyst::EnvelopeKind::arctan) {
    params.ascending[0] = params.descending[0] = 25.0;
  } else if (kind == hyst::EnvelopeKind::linear) {
    params.ascending = {10.0, 0.0};
    params.descending = {10.0, 5.0};
  }
  return params;
}

// A seeded random walk over 0.5 .. 7.5 A: reversals at every scale.
std::vector<double> make_current() {
  return hyst::signals::generate(
      hyst::signals::TimeGrid{kSamples, 1e-4},
      hyst::signals::RandomWalk{
          .max_step = 0.1, .lower = 0.5, .upper = 7.5, .start = 4.0, .seed = 1});
}

template <class E>
void BM_GpiStep(benchmark::State& bench) {
  const hyst::GeneralizedPrandtlIshlinskii<E> model(
      make_params(static_cast<std::size_t>(bench.range(0)), E::kind));
  auto state = model.initial_state();
  const auto input = make_current();
  for (auto _ : bench) {
    for (double v : input)
      benchmark::DoNotOptimize(model.step(state, v));
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input.size()));
}

// For comparison: the tanh envelope evaluated with the C library's std::tanh instead of
// tanh_by_exp() (the kernel accepts any envelope type; this one is not part of the library).
struct LibmTanhEnvelope : hyst::TanhEnvelope {
  template <class T, class V>
  static T value(const T* c, const V& v) {
    return c[0] * std::tanh(c[1] * v + c[2]) + c[3];
  }
};

void BM_GpiStepLibmTanh(benchmark::State& bench) {
  const hyst::GeneralizedPrandtlIshlinskii<> model(
      make_params(static_cast<std::size_t>(bench.range(0))));
  using Kernel = hyst::GpiKernel<LibmTanhEnvelope, double>;
  const auto& params = model.params();
  auto state = model.initial_state();
  const auto input = make_current();
  for (auto _ : bench) {
    for (double v : input) {
      benchmark::DoNotOptimize(Kernel::step(params.ascending.data(), params.descending.data(),
                                            model.thresholds().data(), model.weights().data(),
                                            model.size(), state.play.data(), v));
    }
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input.size()));
}

void BM_GpiSimulate(benchmark::State& bench) {
  const hyst::GeneralizedPrandtlIshlinskii<> model(
      make_params(static_cast<std::size_t>(bench.range(0))));
  auto state = model.initial_state();
  const auto input = make_current();
  std::vector<double> output(input.size());
  for (auto _ : bench) {
    hyst::simulate(model, state, input, output);
    benchmark::DoNotOptimize(output.data());
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input.size()));
}

void BM_IgpiInvert(benchmark::State& bench) {
  const hyst::GeneralizedPrandtlIshlinskii<> model(
      make_params(static_cast<std::size_t>(bench.range(0))));
  const hyst::InverseGeneralizedPrandtlIshlinskii<> inverse(model,
                                                            {.input_min = 0.0, .input_max = 8.0});
  // Reachable targets: the model's own output for the random-walk current.
  auto forward = model.initial_state();
  const auto targets = hyst::simulate(model, forward, make_current());
  auto state = inverse.initial_state();
  std::vector<double> inputs(targets.size());
  for (auto _ : bench) {
    benchmark::DoNotOptimize(hyst::invert(inverse, state, targets, inputs));
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * targets.size()));
}

// One complete fit (all starting points, Ceres Levenberg-Marquardt) on 10 000 samples of the
// MSMA-like model's output for a random-walk current (minor loops at every scale), plus noise.
void BM_GpiFit10k(benchmark::State& bench) {
  const hyst::GeneralizedPrandtlIshlinskii<> truth(make_params(10));
  const auto current = hyst::signals::generate(
      hyst::signals::TimeGrid{10'000, 1e-3},
      hyst::signals::RandomWalk{
          .max_step = 0.08, .lower = 0.0, .upper = 8.0, .start = 0.0, .seed = 5});
  auto state = truth.initial_state();
  auto force = hyst::simulate(truth, state, current);
  std::mt19937_64 rng(6);  // white noise, uniform in +-0.17 N (standard deviation 0.1 N)
  for (double& f : force)
    f += 0.17 * (2 * static_cast<double>(rng() >> 11) * 0x1p-53 - 1);
  hyst::GpiFitOptions options;
  options.m = 10;
  double seconds = 0;
  for (auto _ : bench) {
    const auto fit = hyst::fit_generalized_prandtl_ishlinskii(current, force, options);
    benchmark::DoNotOptimize(fit.report.final_cost);
    seconds = fit.report.seconds;
  }
  bench.counters["fit_seconds"] = seconds;
}

}  // namespace

BENCHMARK(BM_GpiStep<hyst::TanhEnvelope>)->Arg(10)->Arg(50);
BENCHMARK(BM_GpiStep<hyst::ArctanEnvelope>)->Arg(10)->Arg(50);
BENCHMARK(BM_GpiStep<hyst::LinearEnvelope>)->Arg(10)->Arg(50);
BENCHMARK(BM_GpiStepLibmTanh)->Arg(10)->Arg(50);
BENCHMARK(BM_GpiSimulate)->Arg(10)->Arg(50);
BENCHMARK(BM_IgpiInvert)->Arg(10)->Arg(50);
BENCHMARK(BM_GpiFit10k)->Unit(benchmark::kMillisecond)->Iterations(3);
