#pragma once
// Inputs shared by the operator and model tests: reversals at many amplitudes (internal loops),
// with the seed reported by the caller through SCOPED_TRACE.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "hyst/signals/generators.hpp"

namespace hyst::test {

// Seeded random walk in [-bound, bound]: reversals at every scale.
inline std::vector<double> random_walk(std::size_t samples, std::uint64_t seed, double bound = 2.0,
                                       double max_step = 0.2) {
  return signals::generate(
      signals::TimeGrid{samples, 1.0},
      signals::RandomWalk{
          .max_step = max_step, .lower = -bound, .upper = bound, .start = 0.0, .seed = seed});
}

// Linear up-sampling: `factor - 1` points inserted on each straight segment.
inline std::vector<double> upsample_linear(const std::vector<double>& v, int factor) {
  std::vector<double> out;
  out.reserve(v.size() * static_cast<std::size_t>(factor));
  out.push_back(v.front());
  for (std::size_t k = 1; k < v.size(); ++k) {
    for (int j = 1; j < factor; ++j)
      out.push_back(v[k - 1] + (v[k] - v[k - 1]) * j / factor);
    out.push_back(v[k]);
  }
  return out;
}

// The pi_check.py signal: 3 sin(2 pi k/1000) e^{-k/3000} + 0.5 sin(2 pi k/137), k < 4000.
inline std::vector<double> pi_check_signal() {
  std::vector<double> v(4000);
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double t = static_cast<double>(k);
    v[k] = 3.0 * std::sin(2 * std::numbers::pi * t / 1000) * std::exp(-t / 3000) +
           0.5 * std::sin(2 * std::numbers::pi * t / 137);
  }
  return v;
}

// Two periods of a 0 -> 1 -> -1 -> 0 triangle at `frequency` [Hz], sampled every `sample_time`
// [s] from the first sample after 0.
inline std::vector<double> triangle_periods(double frequency, double sample_time) {
  const auto samples = static_cast<std::size_t>(2.0 / (frequency * sample_time));
  std::vector<double> v(samples);
  for (std::size_t k = 0; k < samples; ++k) {
    const double phase = std::fmod(static_cast<double>(k + 1) * sample_time * frequency, 1.0);
    v[k] = phase < 0.25 ? 4 * phase : phase < 0.75 ? 2 - 4 * phase : 4 * phase - 4;
  }
  return v;
}

}  // namespace hyst::test
