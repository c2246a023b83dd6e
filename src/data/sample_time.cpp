#include "hyst/data/sample_time.hpp"

#include <algorithm>
#include <cmath>

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
  const double step = (times.back() - times.front()) / static_cast<double>(times.size() - 1);
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double actual = times[k] - times[k - 1];
    const double rounding = 1e-6 * std::max(std::abs(times[k]), std::abs(times[k - 1]));
    if (std::abs(actual - step) > 1e-3 * step + rounding) {
      throw Error(
          fmt::format("{}: the sampling is not uniform: time[{}] - time[{}] = {:.6g} s but "
                      "the mean step is {:.6g} s (resample the record to a uniform time "
                      "grid first)",
                      what, k, k - 1, actual, step));
    }
  }
  return step;
}

}  // namespace hyst::data
