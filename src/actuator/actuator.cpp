#include "hyst/actuator/actuator.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

void validate_actuator_timing(const ActuatorParams& params) {
  if (!std::isfinite(params.sample_time) || !(params.sample_time > 0.0)) {
    throw Error(fmt::format("actuator sample_time = {} must be finite and > 0", params.sample_time),
                "sample_time");
  }
  if (params.substeps < 1 || params.substeps > 1000) {
    throw Error(fmt::format("actuator substeps = {} must be in 1..1000", params.substeps),
                "substeps");
  }
}

}  // namespace hyst
