#include "hyst/control/references.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/csv.hpp"

namespace hyst::control {
namespace {

void require_period(double sample_time) {
  if (!std::isfinite(sample_time) || !(sample_time > 0.0)) {
    throw Error(fmt::format("reference sample time h = {} must be finite and > 0", sample_time),
                "sample_time");
  }
}

std::size_t sample_count(double duration, double sample_time) {
  require_period(sample_time);
  if (!std::isfinite(duration) || !(duration > 0.0) || duration / sample_time > 1e8) {
    throw Error(
        fmt::format("reference duration = {} s must be > 0 and at most 1e8 samples", duration),
        "duration");
  }
  return static_cast<std::size_t>(std::llround(duration / sample_time)) + 1;
}

}  // namespace

std::vector<double> Reference::times() const {
  std::vector<double> t(values.size());
  for (std::size_t k = 0; k < t.size(); ++k)
    t[k] = static_cast<double>(k) * sample_time;
  return t;
}

Reference step_reference(double from, double to, double step_time, double duration,
                         double sample_time) {
  require_finite(from, "step reference level 'from'");
  require_finite(to, "step reference level 'to'");
  const std::size_t n = sample_count(duration, sample_time);
  if (!std::isfinite(step_time) || step_time < 0.0 || step_time >= duration) {
    throw Error(
        fmt::format("step time = {} s must be in [0, duration = {} s)", step_time, duration),
        "step_time");
  }
  Reference reference{"step", sample_time, std::vector<double>(n), StepEvent{step_time, from, to}};
  for (std::size_t k = 0; k < n; ++k)
    reference.values[k] = static_cast<double>(k) * sample_time < step_time ? from : to;
  return reference;
}

Reference sine_reference(double offset, double amplitude, double frequency, double duration,
                         double sample_time) {
  require_finite(offset, "sine reference offset");
  require_finite(amplitude, "sine reference amplitude");
  if (!std::isfinite(frequency) || frequency < 0.0) {
    throw Error(fmt::format("sine reference frequency = {} Hz must be finite and >= 0", frequency),
                "frequency");
  }
  const std::size_t n = sample_count(duration, sample_time);
  Reference reference{fmt::format("sine_{:g}Hz", frequency), sample_time, std::vector<double>(n)};
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * sample_time;
    reference.values[k] = offset + amplitude * std::sin(2.0 * std::numbers::pi * frequency * t);
  }
  return reference;
}

Reference triangle_reference(double low, double high, std::size_t loops, double rate,
                             double sample_time) {
  require_period(sample_time);
  if (!std::isfinite(low) || !std::isfinite(high) || !(low < high)) {
    throw Error(fmt::format("triangle reference low = {} must be < high = {}", low, high), "low");
  }
  if (!std::isfinite(rate) || !(rate > 0.0)) {
    throw Error(fmt::format("triangle reference rate = {} must be finite and > 0", rate), "rate");
  }
  if (loops > 100) {
    throw Error(fmt::format("triangle reference loops = {} must be <= 100", loops), "loops");
  }
  // Turning points: low, high, high - s, low + s, high - 2s, ... narrowing, then low again.
  const double s = (high - low) / (2.0 * static_cast<double>(loops) + 2.0);
  std::vector<double> turning{low, high};
  for (std::size_t j = 1; j <= loops; ++j) {
    const double inset = static_cast<double>(j) * s;
    turning.push_back(j % 2 == 1 ? low + inset : high - inset);
  }
  turning.push_back(low);
  Reference reference{"triangle", sample_time, {turning.front()}};
  for (std::size_t j = 1; j < turning.size(); ++j) {
    const double from = turning[j - 1];
    const double to = turning[j];
    const auto steps = static_cast<std::size_t>(
        std::max(1.0, std::ceil(std::abs(to - from) / (rate * sample_time))));
    for (std::size_t k = 1; k <= steps; ++k) {
      reference.values.push_back(from +
                                 (to - from) * static_cast<double>(k) / static_cast<double>(steps));
    }
  }
  return reference;
}

Reference reference_from_csv(const std::filesystem::path& path, double sample_time) {
  require_period(sample_time);
  const auto table = io::read_csv(path);
  if (table.rows() == 0) throw Error(fmt::format("{}: no data rows", path.string()));
  const std::string column = table.has_column("reference") ? "reference" : table.names.back();
  Reference reference{path.stem().string(), sample_time, table.column(column)};
  if (table.has_column("t") && column != "t") {
    const auto& t = table.column("t");
    for (std::size_t k = 1; k < t.size(); ++k) {
      const double spacing = t[k] - t[k - 1];
      if (std::abs(spacing - sample_time) > 1e-6 * sample_time) {
        throw Error(
            fmt::format("{}: column 't', data row {}: spacing {} s differs from the sample time "
                        "{} s (resample the trajectory first)",
                        path.string(), k + 1, spacing, sample_time),
            "t");
      }
    }
  }
  return reference;
}

}  // namespace hyst::control
