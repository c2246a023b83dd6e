#include "hyst/data/sample_time.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::data {

namespace {

void require_increasing_times(std::span<const double> times, std::string_view what) {
  if (times.size() < 2) {
    throw Error(
        fmt::format("{}: {} time values, a sample time needs at least 2", what, times.size()));
  }
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k])) {
      throw Error(fmt::format("{}: time[{}] = {} is not finite", what, k, times[k]));
    }
    if (k > 0 && !(times[k] > times[k - 1])) {
      throw Error(fmt::format("{}: time[{}] = {} is not after time[{}] = {}", what, k, times[k],
                              k - 1, times[k - 1]));
    }
  }
}

double median_step(std::span<const double> times) {
  std::vector<double> steps(times.size() - 1);
  for (std::size_t k = 1; k < times.size(); ++k)
    steps[k - 1] = times[k] - times[k - 1];
  const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
  std::nth_element(steps.begin(), middle, steps.end());
  return *middle;
}

// The first k whose step departs from `median` by more than the tolerance plus the rounding of a
// value printed with 7 significant digits; times.size() when none does.
std::size_t first_nonuniform_step(std::span<const double> times, double median) {
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double rounding = 1e-6 * std::max(std::abs(times[k]), std::abs(times[k - 1]));
    if (std::abs(times[k] - times[k - 1] - median) > kSampleTimeTolerance * median + rounding)
      return k;
  }
  return times.size();
}

// The mean step: the most accurate from values printed with few digits.
double mean_step(std::span<const double> times) {
  return (times.back() - times.front()) / static_cast<double>(times.size() - 1);
}

}  // namespace

bool same_sample_time(double a, double b) {
  return std::abs(a - b) <= kSampleTimeTolerance * std::max(std::abs(a), std::abs(b));
}

double uniform_sample_time(std::span<const double> times, std::string_view what) {
  require_increasing_times(times, what);
  // Each step against the median one, so that a single gap is named where it is.
  const double median = median_step(times);
  const std::size_t k = first_nonuniform_step(times, median);
  if (k < times.size()) {
    throw Error(
        fmt::format("{}: the sampling is not uniform: time[{}] - time[{}] = {:.6g} s but "
                    "the median step is {:.6g} s (resample the record to a uniform time "
                    "grid first)",
                    what, k, k - 1, times[k] - times[k - 1], median));
  }
  return mean_step(times);
}

TimeAxis time_axis(std::span<const double> times, std::string_view what) {
  require_increasing_times(times, what);
  const double median = median_step(times);
  if (first_nonuniform_step(times, median) == times.size()) return {mean_step(times), {}};
  TimeAxis axis{median, std::vector<double>(times.size())};
  for (std::size_t k = 1; k < times.size(); ++k)
    axis.steps[k] = times[k] - times[k - 1];
  axis.steps[0] = axis.steps[1];
  return axis;
}

}  // namespace hyst::data
