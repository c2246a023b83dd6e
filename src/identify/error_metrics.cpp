#include "hyst/identify/error_metrics.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

ErrorMetrics error_metrics(std::span<const double> measured, std::span<const double> predicted) {
  require_same_size(measured.size(), "measured", predicted.size(), "predicted");
  require_not_empty(measured.size(), "measured");
  require_finite(measured, "measured");
  require_finite(predicted, "predicted");
  const auto [lowest, highest] = std::minmax_element(measured.begin(), measured.end());
  const double range = *highest - *lowest;
  if (!(range > 0.0)) {
    throw Error(fmt::format(
        "measured is constant (every one of its {} samples = {}): its range normalises the NRMSE "
        "and must be > 0",
        measured.size(), *lowest));
  }
  double sum_of_squares = 0.0;
  double max_error = 0.0;
  for (std::size_t k = 0; k < measured.size(); ++k) {
    const double error = measured[k] - predicted[k];
    sum_of_squares += error * error;
    max_error = std::max(max_error, std::abs(error));
  }
  ErrorMetrics metrics;
  metrics.samples = measured.size();
  metrics.rmse = std::sqrt(sum_of_squares / static_cast<double>(measured.size()));
  metrics.nrmse_percent = 100.0 * metrics.rmse / range;
  metrics.max_error = max_error;
  return metrics;
}

}  // namespace hyst
