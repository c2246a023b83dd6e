#include "hyst/data/sample_time.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::data {

double uniform_sample_time(std::span<const double> times, std::string_view what) {
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
  // Each step against the median one, so that a single gap is named where it is.
  std::vector<double> steps(times.size() - 1);
  for (std::size_t k = 1; k < times.size(); ++k)
    steps[k - 1] = times[k] - times[k - 1];
  std::vector<double> sorted = steps;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const double median = *middle;
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double rounding = 1e-6 * std::max(std::abs(times[k]), std::abs(times[k - 1]));
    if (std::abs(steps[k - 1] - median) > 1e-3 * median + rounding) {
      throw Error(
          fmt::format("{}: the sampling is not uniform: time[{}] - time[{}] = {:.6g} s but "
                      "the median step is {:.6g} s (resample the record to a uniform time "
                      "grid first)",
                      what, k, k - 1, steps[k - 1], median));
    }
  }
  // The mean step: the most accurate from values printed with few digits.
  return (times.back() - times.front()) / static_cast<double>(times.size() - 1);
}

}  // namespace hyst::data
