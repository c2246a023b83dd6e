#include "hyst/actuator/sensor_noise.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

SensorNoise::SensorNoise(const Params& params) : params_(params) {
  if (!std::isfinite(params.standard_deviation) || params.standard_deviation < 0.0) {
    throw Error(fmt::format("sensor noise standard_deviation = {} must be finite and >= 0",
                            params.standard_deviation),
                "standard_deviation");
  }
}

}  // namespace hyst
