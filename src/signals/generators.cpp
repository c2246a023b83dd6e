#include "hyst/signals/generators.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst::signals {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void require_positive(double value, std::string_view name) {
  require_finite(value, name);
  if (!(value > 0.0)) throw Error(fmt::format("{} = {} must be > 0", name, value));
}

void require_non_negative(double value, std::string_view name) {
  require_finite(value, name);
  if (value < 0.0) throw Error(fmt::format("{} = {} must be >= 0", name, value));
}

void validate(const TimeGrid& grid) {
  if (grid.samples < 1) {
    throw Error(fmt::format("time grid samples = {} must be >= 1", grid.samples));
  }
  require_positive(grid.dt, "time grid dt");
}

double time_at(const TimeGrid& grid, std::size_t k) {
  return static_cast<double>(k) * grid.dt;
}

//! The grid and the fields every periodic signal has (amplitude, frequency >= 0, phase, offset;
//! a time constant > 0 where the envelope has one), named "<signal> <field>" in messages.
template <class Signal>
void validate_periodic(const TimeGrid& grid, const Signal& signal, std::string_view name) {
  validate(grid);
  require_finite(signal.amplitude, fmt::format("{} amplitude", name));
  require_non_negative(signal.frequency, fmt::format("{} frequency", name));
  if constexpr (requires { signal.time_constant; }) {
    require_positive(signal.time_constant, fmt::format("{} time_constant", name));
  }
  require_finite(signal.phase, fmt::format("{} phase", name));
  require_finite(signal.offset, fmt::format("{} offset", name));
}

//! sin(2 pi c + phase) with the whole cycles removed from c first, which keeps the argument small
//! (and the result accurate) for long signals.
double sin_cycles(double cycles, double phase) {
  return std::sin(kTwoPi * (cycles - std::floor(cycles)) + phase);
}

//! Throws unless every sample is finite, e.g. when amplitude + offset overflow.
std::vector<double> checked(std::vector<double> samples, std::string_view signal) {
  require_finite(samples, fmt::format("{} output", signal));
  return samples;
}

template <class Sample>
std::vector<double> sample(const TimeGrid& grid, std::string_view signal, Sample&& at_time) {
  std::vector<double> samples(grid.samples);
  for (std::size_t k = 0; k < grid.samples; ++k)
    samples[k] = at_time(time_at(grid, k));
  return checked(std::move(samples), signal);
}

}  // namespace

std::vector<double> times(const TimeGrid& grid) {
  validate(grid);
  return sample(grid, "time grid", [](double t) { return t; });
}

std::vector<double> generate(const TimeGrid& grid, const Sine& signal) {
  validate_periodic(grid, signal, "sine");
  return sample(grid, "sine", [&](double t) {
    return signal.amplitude * sin_cycles(signal.frequency * t, signal.phase) + signal.offset;
  });
}

std::vector<double> generate(const TimeGrid& grid, const Triangle& signal) {
  validate_periodic(grid, signal, "triangle");
  const double phase_cycles = signal.phase / kTwoPi;
  return sample(grid, "triangle", [&](double t) {
    const double cycles = signal.frequency * t + phase_cycles;
    const double p = cycles - std::floor(cycles);  // position in the period, [0, 1)
    double shape = 0.0;                            // in [-1, 1], rising from 0 at p = 0
    if (p < 0.25) {
      shape = 4.0 * p;
    } else if (p < 0.75) {
      shape = 2.0 - 4.0 * p;
    } else {
      shape = 4.0 * p - 4.0;
    }
    return signal.amplitude * shape + signal.offset;
  });
}

std::vector<double> generate(const TimeGrid& grid, const DecayingSine& signal) {
  validate_periodic(grid, signal, "decaying sine");
  return sample(grid, "decaying sine", [&](double t) {
    const double envelope = signal.amplitude * std::exp(-t / signal.time_constant);
    return envelope * sin_cycles(signal.frequency * t, signal.phase) + signal.offset;
  });
}

std::vector<double> generate(const TimeGrid& grid, const GrowingSine& signal) {
  validate_periodic(grid, signal, "growing sine");
  return sample(grid, "growing sine", [&](double t) {
    const double envelope = -signal.amplitude * std::expm1(-t / signal.time_constant);
    return envelope * sin_cycles(signal.frequency * t, signal.phase) + signal.offset;
  });
}

std::vector<double> generate(const TimeGrid& grid, const Multisine& signal) {
  validate(grid);
  const std::size_t count = signal.frequencies.size();
  require_not_empty(count, "multisine frequencies");
  if (signal.amplitudes.size() != count) {
    throw Error(
        fmt::format("multisine amplitudes has {} entries but frequencies has {}; they must have "
                    "the same length",
                    signal.amplitudes.size(), count));
  }
  if (!signal.phases.empty() && signal.phases.size() != count) {
    throw Error(
        fmt::format("multisine phases has {} entries but frequencies has {}; it must be empty "
                    "(Schroeder phases) or have the same length",
                    signal.phases.size(), count));
  }
  for (std::size_t i = 0; i < count; ++i) {
    require_non_negative(signal.frequencies[i], fmt::format("multisine frequencies[{}]", i));
  }
  require_finite(signal.amplitudes, "multisine amplitudes");
  require_finite(signal.phases, "multisine phases");
  require_finite(signal.offset, "multisine offset");

  std::vector<double> phases = signal.phases;
  if (phases.empty()) {
    phases.resize(count);
    const double k_total = static_cast<double>(count);
    for (std::size_t i = 0; i < count; ++i) {
      const double k = static_cast<double>(i + 1);
      phases[i] = -std::numbers::pi * k * (k - 1.0) / k_total;
    }
  }
  return sample(grid, "multisine", [&](double t) {
    double sum = signal.offset;
    for (std::size_t i = 0; i < count; ++i) {
      sum += signal.amplitudes[i] * sin_cycles(signal.frequencies[i] * t, phases[i]);
    }
    return sum;
  });
}

std::vector<double> generate(const TimeGrid& grid, const Chirp& signal) {
  validate(grid);
  require_finite(signal.amplitude, "chirp amplitude");
  require_non_negative(signal.start_frequency, "chirp start_frequency");
  require_non_negative(signal.end_frequency, "chirp end_frequency");
  require_finite(signal.phase, "chirp phase");
  require_finite(signal.offset, "chirp offset");
  const double duration = time_at(grid, grid.samples - 1);
  // Sweep rate [Hz/s]; a single sample has no sweep.
  const double rate =
      duration > 0.0 ? (signal.end_frequency - signal.start_frequency) / duration : 0.0;
  return sample(grid, "chirp", [&](double t) {
    const double cycles = signal.start_frequency * t + 0.5 * rate * t * t;
    return signal.amplitude * sin_cycles(cycles, signal.phase) + signal.offset;
  });
}

std::vector<double> generate(const TimeGrid& grid, const RandomWalk& signal) {
  validate(grid);
  require_finite(signal.max_step, "random walk max_step");
  require_finite(signal.lower, "random walk lower");
  require_finite(signal.upper, "random walk upper");
  require_finite(signal.start, "random walk start");
  const double lower = signal.lower;
  const double upper = signal.upper;
  if (!(lower < upper)) {
    throw Error(fmt::format("random walk lower = {} must be < upper = {}", lower, upper));
  }
  if (signal.start < lower || signal.start > upper) {
    throw Error(fmt::format("random walk start = {} must be in [lower, upper] = [{}, {}]",
                            signal.start, lower, upper));
  }
  require_non_negative(signal.max_step, "random walk max_step");
  if (!(signal.max_step < upper - lower)) {
    throw Error(fmt::format("random walk max_step = {} must be < upper - lower = {}",
                            signal.max_step, upper - lower));
  }

  // Fully specified arithmetic (no std::uniform_real_distribution, whose algorithm differs
  // between standard libraries): the top 53 bits of each draw give a double in [0, 1).
  std::mt19937_64 engine(signal.seed);
  std::vector<double> samples(grid.samples);
  double x = signal.start;
  samples[0] = x;
  for (std::size_t k = 1; k < grid.samples; ++k) {
    const double u = static_cast<double>(engine() >> 11) * 0x1.0p-53;
    const double step = signal.max_step * (2.0 * u - 1.0);
    // Reflect at the bounds. The distances are formed first so that nothing overflows; one
    // reflection suffices because max_step < upper - lower.
    if (step > upper - x) {
      x = upper - (step - (upper - x));
    } else if (-step > x - lower) {
      x = lower + (-step - (x - lower));
    } else {
      x += step;
    }
    x = std::clamp(x, lower, upper);  // guards against rounding at the bounds
    samples[k] = x;
  }
  return checked(std::move(samples), "random walk");
}

}  // namespace hyst::signals
