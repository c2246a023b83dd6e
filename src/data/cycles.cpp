#include "hyst/data/cycles.hpp"

#include <algorithm>
#include <cmath>

#include "hyst/data/reversal_points.hpp"

namespace hyst::data {

std::vector<Cycle> cycles(std::span<const double> input, double band) {
  const auto points = reversal_points(input, band);
  std::vector<Cycle> result;
  if (points.size() < 2) return result;

  const double anchor = input.front();
  // +1 when the record starts rising (its first reversal is a maximum).
  const double sense = points.front().kind == Extremum::maximum ? 1.0 : -1.0;
  const std::size_t last = input.size() - 1;
  std::size_t start = 0;
  std::size_t i = 0;  // points[i] is the next reversal of the first branch's kind
  while (i + 1 < points.size()) {
    const auto& turn_back = points[i + 1];  // the reversal that starts the closing branch
    const std::size_t branch_end = i + 2 < points.size() ? points[i + 2].index : last;
    // Did the input come back to (or within band of) the anchor level before turning?
    if ((turn_back.value - anchor) * sense <= band) {
      for (std::size_t k = turn_back.index; k <= branch_end; ++k) {
        if ((input[k] - anchor) * sense >= 0.0) {
          result.push_back({start, k, false});
          start = k;
          break;
        }
      }
      const bool closed = !result.empty() && result.back().last >= turn_back.index &&
                          result.back().first < turn_back.index;
      if (!closed && i + 2 >= points.size() && std::abs(input[last] - anchor) <= band) {
        result.push_back({start, last, true});
        break;
      }
    }
    i += 2;
  }
  // A record that starts at an extreme (it never goes more than band beyond its first value) and
  // stops at the opposite reversal's return, back at that extreme: the last sample is the
  // unconfirmed reversal that closes the last cycle.
  const bool starts_at_extreme = std::all_of(
      input.begin(), input.end(), [&](double v) { return (v - anchor) * sense >= -band; });
  if (starts_at_extreme && i + 1 == points.size() && start < points[i].index &&
      std::abs(input[last] - anchor) <= band) {
    result.push_back({start, last, true});
  }
  return result;
}

}  // namespace hyst::data
