#include "hyst/data/loop_metrics.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/data/cycles.hpp"
#include "record_checks.hpp"

namespace hyst::data {
namespace {

//! Crossings of `level` by `crossed`, with `other` interpolated; the direction is the input's.
std::vector<LevelCrossing> crossings(std::span<const double> input, std::span<const double> crossed,
                                     std::span<const double> other, double level) {
  require_finite(level, "level");
  std::vector<LevelCrossing> result;
  Direction direction =
      input.size() > 1 && input[1] < input[0] ? Direction::descending : Direction::ascending;
  for (std::size_t k = 0; k + 1 < crossed.size(); ++k) {
    if (input[k + 1] > input[k]) direction = Direction::ascending;
    if (input[k + 1] < input[k]) direction = Direction::descending;
    const double a = crossed[k];
    const double b = crossed[k + 1];
    if ((a < level && b >= level) || (a > level && b <= level)) {
      const double t = (level - a) / (b - a);
      result.push_back({other[k] + t * (other[k + 1] - other[k]), k, direction});
    }
  }
  return result;
}

}  // namespace

double loop_area(std::span<const double> input, std::span<const double> output) {
  detail::require_record(input, output, 3);
  double twice = 0.0;
  const std::size_t n = input.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = k + 1 == n ? 0 : k + 1;
    twice += input[k] * output[next] - input[next] * output[k];
  }
  return 0.5 * twice;
}

std::vector<LevelCrossing> coercive_inputs(std::span<const double> input,
                                           std::span<const double> output, double output_level) {
  detail::require_record(input, output, 2);
  return crossings(input, output, input, output_level);
}

std::vector<LevelCrossing> remanent_outputs(std::span<const double> input,
                                            std::span<const double> output, double input_level) {
  detail::require_record(input, output, 2);
  return crossings(input, input, output, input_level);
}

LoopMetrics loop_metrics(std::span<const double> input, std::span<const double> output,
                         std::size_t first, std::size_t last, double input_level,
                         double output_level) {
  detail::require_record(input, output, 3);
  if (!(first < last && last < input.size() && last - first >= 2)) {
    throw Error(fmt::format(
        "loop samples {}..{} must lie in the record (0..{}) and span at least 3 samples", first,
        last, input.size() - 1));
  }
  const auto x = input.subspan(first, last - first + 1);
  const auto y = output.subspan(first, last - first + 1);
  LoopMetrics metrics;
  metrics.first = first;
  metrics.last = last;
  metrics.area = loop_area(x, y);
  metrics.closure_error = y.back() - y.front();
  metrics.input_mismatch = x.back() - x.front();
  const auto [x_min, x_max] = std::minmax_element(x.begin(), x.end());
  const auto [y_min, y_max] = std::minmax_element(y.begin(), y.end());
  metrics.input_min = *x_min;
  metrics.input_max = *x_max;
  metrics.output_min = *y_min;
  metrics.output_max = *y_max;
  metrics.coercive = crossings(x, y, x, output_level);
  metrics.remanent = crossings(x, x, y, input_level);
  for (auto& crossing : metrics.coercive)
    crossing.index += first;
  for (auto& crossing : metrics.remanent)
    crossing.index += first;
  return metrics;
}

std::vector<LoopMetrics> cycle_metrics(std::span<const double> input,
                                       std::span<const double> output, double band,
                                       double input_level, double output_level) {
  detail::require_record(input, output, 2);
  std::vector<LoopMetrics> result;
  for (const auto& cycle : cycles(input, band)) {
    result.push_back(
        loop_metrics(input, output, cycle.first, cycle.last, input_level, output_level));
  }
  return result;
}

}  // namespace hyst::data
