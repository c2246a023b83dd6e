#include "hyst/data/branches.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/data/reversal_points.hpp"

namespace hyst::data {

std::string_view to_string(Direction direction) {
  return direction == Direction::ascending ? "ascending" : "descending";
}

std::vector<Branch> branches(std::span<const double> input, double band) {
  const auto points = reversal_points(input, band);
  const std::size_t last = input.size() - 1;
  Direction direction = Direction::ascending;
  if (!points.empty()) {
    direction =
        points.front().kind == Extremum::maximum ? Direction::ascending : Direction::descending;
  } else {
    const auto [lowest, highest] = std::minmax_element(input.begin(), input.end());
    if (!(*highest - *lowest > band)) {
      throw Error(fmt::format(
          "input never moves by more than the hysteresis band {} (its range is {}): no branch",
          band, *highest - *lowest));
    }
    // A monotone record: its direction is that of its last extreme reached.
    direction = highest > lowest ? Direction::ascending : Direction::descending;
  }

  std::vector<Branch> result;
  std::size_t first = 0;
  for (const auto& point : points) {
    if (point.index > first) result.push_back({first, point.index, direction});
    first = point.index;
    direction = point.kind == Extremum::maximum ? Direction::descending : Direction::ascending;
  }
  if (last > first) result.push_back({first, last, direction});
  return result;
}

}  // namespace hyst::data
