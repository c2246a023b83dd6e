#include "hyst/operators/backlash.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

Backlash::Backlash(const Params& params) : params_(params) {
  require_finite(params.gain, "backlash gain K");
  require_finite(params.half_width, "backlash half-width h");
  if (params.gain <= 0.0) {
    throw Error(fmt::format("backlash gain K = {} must be > 0", params.gain));
  }
  if (params.half_width < 0.0) {
    throw Error(fmt::format("backlash half-width h = {} must be >= 0", params.half_width));
  }
  if (std::isnan(params.output_min) || std::isnan(params.output_max) ||
      params.output_min > params.output_max) {
    throw Error(
        fmt::format("backlash output limits y_min = {} and y_max = {} must satisfy "
                    "y_min <= y_max",
                    params.output_min, params.output_max));
  }
}

Backlash::State Backlash::make_state(double output) const {
  require_finite(output, "backlash state y");
  return State{output};
}

}  // namespace hyst
