// ns per closed-loop sample of the MSMA actuator under PID + inverse feedforward: per sample one
// PID step, one IGPI step (the compensator), the current drive, and the actuator (coil, GPI force,
// mechanics, delay, noise). GPI m = 10 (the [ASSUMED] set of examples/config/msma_assumed.json,
// built here so that the benchmark does not depend on the working folder). Also the actuator
// alone and each strategy. Items processed = samples; ns/sample = 1e9 / rate.

#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include "hyst/actuator/control_loop.hpp"
#include "hyst/control/references.hpp"

namespace {

using Gpi = hyst::GeneralizedPrandtlIshlinskii<hyst::TanhEnvelope>;

Gpi msma_force() {
  return Gpi({.ascending = {40.0, 0.8, -3.2, 40.0},
              .descending = {40.0, 0.8, -2.8, 40.0},
              .rho = 0.143,
              .tau = 0.1,
              .alpha = 1.0,
              .m = 10,
              .input_min = 0.0,
              .input_max = 8.0});
}

hyst::ActuatorParams msma_params(double noise) {
  hyst::ActuatorParams params;
  params.sample_time = 1e-4;
  params.coil = {2.0, 0.015, 0.0, 8.0};
  params.mechanics = {0.05, 40.0, 7.6e4};
  params.delay = 1e-3;
  params.noise = {noise, 1};
  return params;
}

hyst::ControlLoop<Gpi> msma_loop(double noise = 0.0) {
  hyst::LoopParams loop;
  loop.force_gain = 9.5;
  loop.model_stiffness = 7.6e4;
  loop.model_resistance = 2.0;
  loop.model_inductance = 0.015;
  loop.voltage_min = -48.0;
  loop.voltage_max = 48.0;
  loop.pid = {.kp = 500.0, .ki = 6e5, .kd = 1.0, .derivative_filter = 3e-4};
  return hyst::ControlLoop<Gpi>(hyst::Actuator<Gpi>(msma_force(), msma_params(noise)), msma_force(),
                                loop);
}

// A 10 Hz sine and a triangle with internal loops, 0.15 .. 0.85 mm.
std::vector<double> make_reference() {
  auto reference = hyst::control::triangle_reference(1.5e-4, 8.5e-4, 6, 0.01, 1e-4).values;
  const auto sine = hyst::control::sine_reference(5e-4, 3.5e-4, 10.0, 0.5, 1e-4).values;
  reference.insert(reference.end(), sine.begin(), sine.end());
  return reference;
}

void run_strategy(benchmark::State& bench, hyst::ControlStrategy strategy, double noise) {
  const auto loop = msma_loop(noise);
  const auto reference = make_reference();
  for (auto _ : bench) {
    auto state = loop.initial_state();
    double current_reference = 0.0;
    double voltage = 0.0;
    double sum = 0.0;
    for (double r : reference)
      sum += loop.step(state, strategy, r, current_reference, voltage).measured;
    benchmark::DoNotOptimize(sum);
  }
  bench.SetItemsProcessed(bench.iterations() * static_cast<int64_t>(reference.size()));
}

void BM_ClosedLoopPidFeedforward(benchmark::State& bench) {
  run_strategy(bench, hyst::ControlStrategy::pid_feedforward, 0.0);
}
void BM_ClosedLoopPidFeedforwardWithNoise(benchmark::State& bench) {
  run_strategy(bench, hyst::ControlStrategy::pid_feedforward, 1e-7);
}
void BM_ClosedLoopPid(benchmark::State& bench) {
  run_strategy(bench, hyst::ControlStrategy::pid, 0.0);
}
void BM_OpenLoopFeedforward(benchmark::State& bench) {
  run_strategy(bench, hyst::ControlStrategy::feedforward, 0.0);
}

void BM_ActuatorStep(benchmark::State& bench) {
  const hyst::Actuator<Gpi> actuator(msma_force(), msma_params(0.0));
  const auto reference = make_reference();
  for (auto _ : bench) {
    auto state = actuator.initial_state();
    double sum = 0.0;
    for (double r : reference)
      sum += actuator.step(state, 2e4 * r).measured;  // voltage proportional to the reference
    benchmark::DoNotOptimize(sum);
  }
  bench.SetItemsProcessed(bench.iterations() * static_cast<int64_t>(reference.size()));
}

BENCHMARK(BM_ClosedLoopPidFeedforward);
BENCHMARK(BM_ClosedLoopPidFeedforwardWithNoise);
BENCHMARK(BM_ClosedLoopPid);
BENCHMARK(BM_OpenLoopFeedforward);
BENCHMARK(BM_ActuatorStep);

}  // namespace
