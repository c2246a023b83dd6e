#include "hyst/control/tracking_metrics.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst::control {

TrackingMetrics tracking_metrics(std::span<const double> reference, std::span<const double> output,
                                 std::span<const double> effort, double sample_time,
                                 const std::optional<StepEvent>& step, double band) {
  require_not_empty(reference.size(), "reference");
  require_same_size(reference.size(), "reference", output.size(), "output");
  require_same_size(reference.size(), "reference", effort.size(), "effort");
  require_finite(reference, "reference");
  require_finite(output, "output");
  require_finite(effort, "effort");
  if (!(band > 0.0 && band < 1.0)) {
    throw Error(fmt::format("settling band = {} must be in (0, 1)", band), "band");
  }
  TrackingMetrics metrics;
  double squared = 0.0;
  double effort_squared = 0.0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const double error = reference[k] - output[k];
    squared += error * error;
    metrics.max_error = std::max(metrics.max_error, std::abs(error));
    effort_squared += effort[k] * effort[k];
  }
  const auto n = static_cast<double>(reference.size());
  metrics.rms_error = std::sqrt(squared / n);
  metrics.control_effort = std::sqrt(effort_squared / n);
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  metrics.settling_time = nan;
  metrics.overshoot = nan;
  if (!step || step->to == step->from) return metrics;
  const double size = step->to - step->from;
  const auto first = static_cast<std::size_t>(std::ceil(step->time / sample_time - 1e-9));
  if (first >= output.size()) return metrics;
  double peak = 0.0;
  std::size_t last_outside = first;
  bool ever_outside = false;
  for (std::size_t k = first; k < output.size(); ++k) {
    const double relative = (output[k] - step->to) / size;
    peak = std::max(peak, relative);
    if (std::abs(relative) > band) {
      last_outside = k;
      ever_outside = true;
    }
  }
  metrics.overshoot = 100.0 * peak;
  if (!ever_outside) {
    metrics.settling_time = 0.0;
  } else if (last_outside + 1 < output.size()) {
    metrics.settling_time = static_cast<double>(last_outside + 1 - first) * sample_time;
  }
  return metrics;
}

}  // namespace hyst::control
