#include "hyst/operators/stop.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

Stop::Stop(double half_width) : half_width_(half_width) {
  require_finite(half_width, "stop half-width r");
  if (half_width < 0.0) {
    throw Error(fmt::format("stop half-width r = {} must be >= 0", half_width));
  }
}

Stop::State Stop::state_from_play(double play_output, double input) const {
  require_finite(play_output, "stop: play output w");
  require_finite(input, "stop: input v");
  const double stress = input - play_output;
  if (std::abs(stress) > half_width_) {
    throw Error(fmt::format("stop state e = v - w = {} must lie in [-r, r] = [{}, {}]", stress,
                            -half_width_, half_width_));
  }
  return State{stress, input};
}

}  // namespace hyst
