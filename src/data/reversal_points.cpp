#include "hyst/data/reversal_points.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "record_checks.hpp"

namespace hyst::data {

std::string_view to_string(Extremum kind) {
  return kind == Extremum::maximum ? "maximum" : "minimum";
}

std::vector<ReversalPoint> reversal_points(std::span<const double> input, double band) {
  detail::require_samples(input, "input", 2);
  detail::require_band(band);

  std::vector<ReversalPoint> points;
  int direction = 0;  // +1 rising, -1 falling, 0 not yet known
  std::size_t highest = 0;
  std::size_t lowest = 0;
  std::size_t candidate = 0;  // running extreme of the current direction
  for (std::size_t k = 1; k < input.size(); ++k) {
    const double v = input[k];
    if (direction == 0) {
      if (v > input[highest]) highest = k;
      if (v < input[lowest]) lowest = k;
      if (input[highest] - input[lowest] > band) {
        // The extreme reached last sets the direction; the other one is only the start.
        direction = highest == k ? 1 : -1;
        candidate = k;
      }
    } else if (direction > 0) {
      if (v > input[candidate]) {
        candidate = k;
      } else if (input[candidate] - v > band) {
        points.push_back({candidate, input[candidate], Extremum::maximum});
        direction = -1;
        candidate = k;
      }
    } else {
      if (v < input[candidate]) {
        candidate = k;
      } else if (v - input[candidate] > band) {
        points.push_back({candidate, input[candidate], Extremum::minimum});
        direction = 1;
        candidate = k;
      }
    }
  }
  return points;
}

std::vector<ReversalPoint> preisach_memory(std::span<const ReversalPoint> points) {
  std::vector<ReversalPoint> memory;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& point = points[i];
    if (i > 0 && points[i - 1].kind == point.kind) {
      throw Error(fmt::format(
          "reversal points must alternate between maxima and minima, but points[{}] and "
          "points[{}] are both {} (indices {} and {})",
          i - 1, i, to_string(point.kind), points[i - 1].index, point.index));
    }
    const bool maximum = point.kind == Extremum::maximum;
    // Wiping-out: the new extreme deletes each earlier extreme of its kind that it reaches, with
    // the opposite extreme stored after it.
    while (memory.size() >= 2 && memory.back().kind != point.kind) {
      const double earlier = memory[memory.size() - 2].value;
      if (maximum ? earlier > point.value : earlier < point.value) break;
      memory.resize(memory.size() - 2);
    }
    memory.push_back(point);
  }
  return memory;
}

double default_band(std::span<const double> input, double fraction) {
  detail::require_samples(input, "input", 1);
  if (!(fraction > 0.0 && fraction < 1.0)) {
    throw Error(fmt::format("band fraction = {} must be > 0 and < 1", fraction));
  }
  const auto [lowest, highest] = std::minmax_element(input.begin(), input.end());
  const double range = *highest - *lowest;
  if (!(range > 0.0)) {
    throw Error(
        fmt::format("input is constant ({} samples = {}): no hysteresis band from its range",
                    input.size(), *lowest));
  }
  return fraction * range;
}

}  // namespace hyst::data
