// The exported C code's step against the library's, per sample, on the same model files
// (bench/export_models/). The C files are generated at build time by `hyst export --lang c` and
// compiled into this program as C99 (see bench/CMakeLists.txt). Library figures: the registry's
// DynamicModel::simulate / DynamicInverse::invert on a batch (one virtual call per batch, an
// input check per sample), the path of `hyst simulate` and the Python module.

#include <cstddef>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_bouc_wen_exact.h"
#include "bench_bouc_wen_rk4.h"
#include "bench_gpi.h"
#include "bench_modified_pi.h"
#include "bench_pi16.h"
#include "bench_preisach.h"
#include "hyst/registry/model_file.hpp"

namespace {

constexpr std::size_t kSamples = 4096;

// A seeded random walk in [low, high] with reversals at every scale.
std::vector<double> walk(double low, double high) {
  std::mt19937 random(42);
  std::uniform_real_distribution<double> step(-0.05, 0.05);
  std::vector<double> input(kSamples);
  double v = 0.5 * (low + high);
  for (auto& x : input) {
    v = std::clamp(v + step(random) * (high - low), low, high);
    x = v;
  }
  return input;
}

std::unique_ptr<hyst::DynamicModel> model_file(const std::string& name) {
  return hyst::load_model(std::string(HYST_EXPORT_MODELS_DIR) + "/" + name + ".json");
}

void set_ns_per_sample(benchmark::State& state) {
  state.counters["ns/sample"] = benchmark::Counter(
      static_cast<double>(kSamples) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void library_model(benchmark::State& state, const std::string& name, double low, double high) {
  auto model = model_file(name);
  const auto input = walk(low, high);
  std::vector<double> output(kSamples);
  for (auto _ : state) {
    model->simulate(input, output);
    benchmark::DoNotOptimize(output.data());
  }
  set_ns_per_sample(state);
}

void library_inverse(benchmark::State& state, const std::string& name, double low, double high) {
  auto model = model_file(name);
  std::vector<double> target(kSamples);
  model->clone()->simulate(walk(low, high), target);
  auto inverse = model->inverse({});
  std::vector<double> input(kSamples);
  for (auto _ : state) {
    inverse->invert(target, input);
    benchmark::DoNotOptimize(input.data());
  }
  set_ns_per_sample(state);
}

template <class State, class Init, class Step>
void c_loop(benchmark::State& state, const std::vector<double>& input, Init init, Step step) {
  State c_state;
  init(&c_state);
  for (auto _ : state) {
    double sum = 0.0;
    for (const double v : input)
      sum += step(&c_state, v);
    benchmark::DoNotOptimize(sum);
  }
  set_ns_per_sample(state);
}

// The C model's and the C inverse's step for one exported prefix.
#define HYST_C_BENCHMARKS(prefix, name, low, high)                                          \
  void c_model_##prefix(benchmark::State& state) {                                          \
    c_loop<prefix##_state>(                                                                 \
        state, walk(low, high), prefix##_init,                                              \
        [](prefix##_state* s, double v) { return prefix##_step(&prefix##_PARAMS, s, v); }); \
  }                                                                                         \
  BENCHMARK_CAPTURE(library_model, name, #name, low, high);                                 \
  BENCHMARK(c_model_##prefix)

#define HYST_C_INVERSE_BENCHMARKS(prefix, name, low, high)                                         \
  void c_inverse_##prefix(benchmark::State& state) {                                               \
    std::vector<double> target(kSamples);                                                          \
    model_file(#name)->simulate(walk(low, high), target);                                          \
    c_loop<prefix##_inverse_state>(state, target, prefix##_inverse_init,                           \
                                   [](prefix##_inverse_state* s, double y) {                       \
                                     return prefix##_inverse_step(&prefix##_INVERSE_PARAMS, s, y); \
                                   });                                                             \
  }                                                                                                \
  BENCHMARK_CAPTURE(library_inverse, name, #name, low, high);                                      \
  BENCHMARK(c_inverse_##prefix)

HYST_C_BENCHMARKS(bench_pi16, pi16, -2.0, 2.0);
HYST_C_INVERSE_BENCHMARKS(bench_pi16, pi16, -2.0, 2.0);
HYST_C_BENCHMARKS(bench_modified_pi, modified_pi, -2.0, 2.0);
HYST_C_INVERSE_BENCHMARKS(bench_modified_pi, modified_pi, -2.0, 2.0);
HYST_C_BENCHMARKS(bench_gpi, gpi, -2.5, 2.5);
HYST_C_INVERSE_BENCHMARKS(bench_gpi, gpi, -2.5, 2.5);
HYST_C_BENCHMARKS(bench_preisach, preisach, -1.0, 1.0);
HYST_C_INVERSE_BENCHMARKS(bench_preisach, preisach, -1.0, 1.0);
HYST_C_BENCHMARKS(bench_bouc_wen_rk4, bouc_wen_rk4, -3.0, 3.0);
HYST_C_BENCHMARKS(bench_bouc_wen_exact, bouc_wen_exact, -3.0, 3.0);

}  // namespace
