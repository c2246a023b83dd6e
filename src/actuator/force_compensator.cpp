#include "hyst/actuator/force_compensator.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

void validate_compensator_params(double force_gain, double current_min, double current_max) {
  if (!std::isfinite(force_gain) || !(force_gain > 0.0)) {
    throw Error(fmt::format("compensated force gain k_F = {} must be finite and > 0", force_gain),
                "force_gain");
  }
  if (!std::isfinite(current_min) || !std::isfinite(current_max) || !(current_min < current_max)) {
    throw Error(fmt::format("compensator current range [{}, {}] must be finite with min < max",
                            current_min, current_max),
                "current_min");
  }
}

}  // namespace hyst
