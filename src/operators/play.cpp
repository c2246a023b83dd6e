#include "hyst/operators/play.hpp"

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

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
