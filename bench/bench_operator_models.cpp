// ns/sample of the further operator models: Ikuta's SMA model, the Krasnosel'skii-Pokrovskii grid
// (N = 6, 21), Maxwell-slip (8 and 32 elements), the modified PI and its analytic inverse, the
// rate-dependent PI, the butterfly strain model and its inverse, and, for the seed paper's
// comparison, the PI model with 8 backlash elements and the Preisach model with 231 relays (fast
// and relay by relay), on the same input. Items processed = samples, so Google Benchmark reports
// samples/s; ns/sample = 1e9 / rate.

#include <vector>

#include <benchmark/benchmark.h>

#include "hyst/inverse/inverse_butterfly_strain.hpp"
#include "hyst/inverse/inverse_butterfly_strain_creep.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii_creep.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/butterfly_strain.hpp"
#include "hyst/models/butterfly_strain_creep.hpp"
#include "hyst/models/ikuta_sma.hpp"
#include "hyst/models/krasnoselskii_pokrovskii.hpp"
#include "hyst/models/maxwell_slip.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"
#include "hyst/models/preisach.hpp"
#include "hyst/models/preisach_relay_grid.hpp"
#include "hyst/models/rate_dependent_prandtl_ishlinskii.hpp"
#include "hyst/signals/generators.hpp"

namespace {

constexpr std::size_t kSamples = 1 << 12;

// A random walk in [-1, 1]: reversals at every scale, many nested loops.
const std::vector<double>& input() {
  static const auto samples = hyst::signals::generate(
      hyst::signals::TimeGrid{kSamples, 1e-4},
      hyst::signals::RandomWalk{.max_step = 0.05, .lower = -1, .upper = 1, .start = 0, .seed = 1});
  return samples;
}

template <class Model>
void run_steps(benchmark::State& bench, const Model& model) {
  auto state = model.initial_state();
  for (auto _ : bench) {
    for (double v : input())
      benchmark::DoNotOptimize(model.step(state, v));
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * input().size()));
}

hyst::ModifiedPrandtlIshlinskii modified_pi() {
  return hyst::ModifiedPrandtlIshlinskii(
      {.pi = {.thresholds = hyst::uniform_thresholds(8, 0.1),
              .weights = {0.8, 0.5, 0.3, 0.2, 0.1, 0.1, 0.05, 0.05}},
       .dead_zone = {.thresholds = {-1.5, -0.8, -0.3, 0, 0.4, 0.9, 1.6},
                     .weights = {0.05, 0.1, 0.2, 1.0, -0.15, -0.2, -0.1}}});
}

void BM_IkutaSma(benchmark::State& bench) {
  run_steps(bench, hyst::IkutaSma({.martensite_finish = -0.8,
                                   .martensite_start = 0.2,
                                   .austenite_start = -0.2,
                                   .austenite_finish = 0.8}));
}

void BM_KrasnoselskiiPokrovskii(benchmark::State& bench) {
  const auto levels = static_cast<std::size_t>(bench.range(0));
  run_steps(bench, hyst::KrasnoselskiiPokrovskii(
                       {.levels = levels,
                        .weights = std::vector<double>(levels * (levels + 1) / 2, 1.0)}));
}

void BM_MaxwellSlip(benchmark::State& bench) {
  const auto n = static_cast<std::size_t>(bench.range(0));
  std::vector<double> k(n, 1.0), f(n);
  for (std::size_t i = 0; i < n; ++i)
    f[i] = 0.02 * static_cast<double>(i + 1);
  run_steps(bench, hyst::MaxwellSlip({.stiffness = k, .break_away = f, .linear_stiffness = 1}));
}

void BM_ModifiedPi(benchmark::State& bench) {
  run_steps(bench, modified_pi());
}

void BM_InverseModifiedPi(benchmark::State& bench) {
  run_steps(bench, hyst::InverseModifiedPrandtlIshlinskii(modified_pi()));
}

void BM_RateDependentPi(benchmark::State& bench) {
  run_steps(bench, hyst::RateDependentPrandtlIshlinskii(hyst::rate_dependent_pi_exponential(
                       0.1, 1.0, 0.5, static_cast<std::size_t>(bench.range(0)) - 1, 0.01, 1e-4)));
}

// PI with a logarithmic creep law: range(0) plays, 2 lags per decade over 5 decades (11 lags).
hyst::PrandtlIshlinskiiCreep pi_with_log_creep(std::size_t plays) {
  const auto thresholds = hyst::uniform_thresholds(plays, 1.0 / static_cast<double>(plays));
  return hyst::PrandtlIshlinskiiCreep(hyst::pi_logarithmic_creep(
      {thresholds, std::vector<double>(plays, 1.0 / static_cast<double>(plays))}, 0.02, 0.01, 5, 2,
      1e-3));
}

void BM_PiCreep(benchmark::State& bench) {
  run_steps(bench, pi_with_log_creep(static_cast<std::size_t>(bench.range(0))));
}

void BM_InversePiCreep(benchmark::State& bench) {
  run_steps(bench, hyst::InversePrandtlIshlinskiiCreep(
                       pi_with_log_creep(static_cast<std::size_t>(bench.range(0)))));
}

// The same with dead zones after it (saturating beyond +-0.6, the modified PI with creep).
hyst::ModifiedPrandtlIshlinskiiCreep modified_pi_with_log_creep(std::size_t plays) {
  hyst::ModifiedPrandtlIshlinskiiCreep::Params p;
  p.pi_creep = pi_with_log_creep(plays).params();
  p.dead_zone = {{-0.6, -0.3, 0.0, 0.3, 0.6}, {-0.3, -0.2, 1.0, -0.2, -0.3}};
  return hyst::ModifiedPrandtlIshlinskiiCreep(p);
}

void BM_ModifiedPiCreep(benchmark::State& bench) {
  run_steps(bench, modified_pi_with_log_creep(static_cast<std::size_t>(bench.range(0))));
}

void BM_InverseModifiedPiCreep(benchmark::State& bench) {
  run_steps(bench, hyst::InverseModifiedPrandtlIshlinskiiCreep(
                       modified_pi_with_log_creep(static_cast<std::size_t>(bench.range(0)))));
}

// Butterfly strain: range(0) levels on [-1, 1], equal weights (F0 = 1), y = 0.2 v + P + 0.3 P^2
// (monotone over the whole range, so that the inverse searches on every sample).
hyst::ButterflyStrain butterfly_strain(std::size_t levels) {
  hyst::ButterflyStrain::Params p;
  p.polarisation.everett = {
      .levels = levels,
      .lower = -1.0,
      .upper = 1.0,
      .weights = hyst::uniform_relay_weights(
          levels, 1.0 / static_cast<double>(hyst::preisach_relay_count(levels)))};
  p.field_coefficient = 0.2;
  p.polarisation_coefficients = {1.0, 0.3};
  return hyst::ButterflyStrain(p);
}

void BM_ButterflyStrain(benchmark::State& bench) {
  run_steps(bench, butterfly_strain(static_cast<std::size_t>(bench.range(0))));
}

// The branch test (2 N + 2 previews) and the bracketed search, on every sample.
void BM_InverseButterflyStrain(benchmark::State& bench) {
  run_steps(bench,
            hyst::InverseButterflyStrain(butterfly_strain(static_cast<std::size_t>(bench.range(0))),
                                         {.input_min = -1.0, .input_max = 1.0}));
}

// The same butterfly with a logarithmic creep of its polarisation: 3 plays, 14 lags (2 per
// decade from 0.01 s to 1e5 s at Ts = 1 ms), equal weights 0.01 per lag.
hyst::ButterflyStrainCreep butterfly_strain_creep(std::size_t levels) {
  hyst::ButterflyStrainCreep::Params p;
  p.butterfly = butterfly_strain(levels).params();
  p.creep_thresholds = {0.0, 0.3, 0.6};
  p.time_constants = hyst::log_spaced_time_constants(0.01, 1e5, 15);
  p.creep_weights.assign(p.time_constants.size() * p.creep_thresholds.size(), 0.01);
  p.sample_time = 1e-3;
  return hyst::ButterflyStrainCreep(p);
}

void BM_ButterflyStrainCreep(benchmark::State& bench) {
  run_steps(bench, butterfly_strain_creep(static_cast<std::size_t>(bench.range(0))));
}

void BM_InverseButterflyStrainCreep(benchmark::State& bench) {
  run_steps(bench, hyst::InverseButterflyStrainCreep(
                       butterfly_strain_creep(static_cast<std::size_t>(bench.range(0))),
                       {.input_min = -1.0, .input_max = 1.0}));
}

// The seed comparison: 8 unweighted backlash elements, 231 unweighted relays.
void BM_SeedPi8(benchmark::State& bench) {
  run_steps(bench, hyst::PrandtlIshlinskii({.thresholds = hyst::uniform_thresholds(8, 0.125),
                                            .weights = std::vector<double>(8, 0.125)}));
}

hyst::Preisach::Params relays231() {
  return {
      .everett = {
          .levels = 21, .lower = -1, .upper = 1, .weights = std::vector<double>(231, 1.0 / 231.0)}};
}

void BM_SeedPreisach231(benchmark::State& bench) {
  run_steps(bench, hyst::Preisach(relays231()));
}

void BM_SeedPreisach231RelayByRelay(benchmark::State& bench) {
  run_steps(bench, hyst::PreisachRelayGrid(relays231()));
}

}  // namespace

BENCHMARK(BM_IkutaSma);
BENCHMARK(BM_KrasnoselskiiPokrovskii)->Arg(6)->Arg(21);
BENCHMARK(BM_MaxwellSlip)->Arg(8)->Arg(32);
BENCHMARK(BM_ModifiedPi);
BENCHMARK(BM_InverseModifiedPi);
BENCHMARK(BM_RateDependentPi)->Arg(8)->Arg(16);
BENCHMARK(BM_PiCreep)->Arg(8)->Arg(16);
BENCHMARK(BM_InversePiCreep)->Arg(8)->Arg(16);
BENCHMARK(BM_ModifiedPiCreep)->Arg(8)->Arg(16);
BENCHMARK(BM_InverseModifiedPiCreep)->Arg(8)->Arg(16);
BENCHMARK(BM_ButterflyStrain)->Arg(16)->Arg(64);
BENCHMARK(BM_InverseButterflyStrain)->Arg(16)->Arg(64);
BENCHMARK(BM_ButterflyStrainCreep)->Arg(16);
BENCHMARK(BM_InverseButterflyStrainCreep)->Arg(16);
BENCHMARK(BM_SeedPi8);
BENCHMARK(BM_SeedPreisach231);
BENCHMARK(BM_SeedPreisach231RelayByRelay);
