#pragma once
// Inputs shared by the operator and model tests: reversals at many amplitudes (internal loops),
// with the seed reported by the caller through SCOPED_TRACE.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
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

// A seeded random walk with reversals of all sizes in [low, high] (widened by `overshoot` of the
// span on both sides, for inputs a little beyond a model's range), some samples repeated
// (no-change steps).
inline std::vector<double> seeded_input(unsigned seed, double low, double high, std::size_t count,
                                        double overshoot = 0.0) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> input(count);
  const double span = high - low;
  double v = low + 0.5 * span;
  double direction = 1.0;
  for (auto& x : input) {
    if (unit(random) < 0.08) direction = -direction;
    if (unit(random) > 0.05) v += direction * span * 0.04 * unit(random);
    v = std::clamp(v, low - overshoot * span, high + overshoot * span);
    x = v;
  }
  return input;
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
