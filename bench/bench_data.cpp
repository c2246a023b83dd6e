// Measured-record processing on long records: reversal points, cycles, drift removal, resampling
// per branch, and parsing the 772 KB aixACCT export. Input: 64 periods of a 1024-sample sine
// with seeded noise of 1 % of its amplitude (band 2 % of the range).

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "hyst/data/corrections.hpp"
#include "hyst/data/cycles.hpp"
#include "hyst/data/resampling.hpp"
#include "hyst/data/reversal_points.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/io/atomic_file.hpp"

namespace {

constexpr std::size_t kSamples = 65536;

struct Record {
  std::vector<double> input, output;
};

const Record& record() {
  static const Record r = [] {
    Record out;
    std::mt19937_64 generator(1);
    std::uniform_real_distribution<double> noise(-0.01, 0.01);
    for (std::size_t k = 0; k < kSamples; ++k) {
      const double t = 2.0 * std::numbers::pi * static_cast<double>(k) / 1024.0;
      out.input.push_back(std::sin(t) + noise(generator));
      out.output.push_back(std::sin(t - 0.5) + 1e-5 * static_cast<double>(k));
    }
    return out;
  }();
  return r;
}

constexpr double kBand = 0.04;

void BM_ReversalPoints(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(hyst::data::reversal_points(record().input, kBand));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kSamples));
}
BENCHMARK(BM_ReversalPoints);

void BM_Cycles(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(hyst::data::cycles(record().input, kBand));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kSamples));
}
BENCHMARK(BM_Cycles);

void BM_RemoveDrift(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(hyst::data::remove_drift(record().input, record().output, kBand));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kSamples));
}
BENCHMARK(BM_RemoveDrift);

void BM_ResampleOnInputGrid(benchmark::State& state) {
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        hyst::data::resample_on_input_grid(record().input, record().output, kBand, 0.02));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kSamples));
}
BENCHMARK(BM_ResampleOnInputGrid);

void BM_ParseAixacct(benchmark::State& state) {
  const auto text =
      hyst::io::read_file(HYST_SHARED_DATA_DIR "/piezo_pzt_aixacct_butterfly/RMN_TRAP_SLOW.dat");
  for (auto _ : state)
    benchmark::DoNotOptimize(hyst::io::parse_aixacct(text, "RMN_TRAP_SLOW.dat"));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
}
BENCHMARK(BM_ParseAixacct);

}  // namespace
