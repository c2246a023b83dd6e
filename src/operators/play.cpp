#include "hyst/operators/play.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

void require_reachable_plays(std::span<const double> play, std::span<const double> thresholds,
                             std::string_view model, std::string_view symbol) {
  require_same_size(play.size(), fmt::format("{} state {}", model, symbol), thresholds.size(),
                    fmt::format("{} thresholds r", model));
  for (std::size_t j = 0; j < play.size(); ++j)
    require_finite(play[j], fmt::format("{} state {}[{}]", model, symbol, j));
  double scale = 1.0;
  for (double w : play)
    scale = std::max(scale, std::abs(w));
  const double slack = 1e-12 * scale;
  for (std::size_t j = 1; j < play.size(); ++j) {
    const double gap = std::abs(play[j] - play[j - 1]);
    const double allowed = thresholds[j] - thresholds[j - 1];
    if (gap > allowed + slack) {
      throw Error(
          fmt::format("{0} state {1}[{2}] = {3} and {1}[{4}] = {5} differ by {6}, more "
                      "than r[{2}] - r[{4}] = {7}: no input history reaches this state",
                      model, symbol, j, play[j], j - 1, play[j - 1], gap, allowed));
    }
  }
}

Play::Play(double half_width) : half_width_(half_width) {
  require_finite(half_width, "play half-width r");
  if (half_width < 0.0) {
    throw Error(fmt::format("play half-width r = {} must be >= 0", half_width));
  }
}

Play::State Play::make_state(double output) const {
  require_finite(output, "play state w");
  return State{output};
}

}  // namespace hyst
