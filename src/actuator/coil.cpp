#include "hyst/actuator/coil.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {
namespace {

void require_positive(double value, std::string_view what, const char* field) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    throw Error(fmt::format("{} = {} must be finite and > 0", what, value), field);
  }
}

}  // namespace

Coil::Coil(const Params& params, double period) : params_(params), period_(period) {
  require_positive(params.resistance, "coil resistance R", "resistance");
  require_positive(params.inductance, "coil inductance L", "inductance");
  require_positive(period, "coil sample period h", "period");
  if (std::isnan(params.current_min) || std::isnan(params.current_max) ||
      !(params.current_min < params.current_max)) {
    throw Error(fmt::format("coil current_min = {} must be < current_max = {}", params.current_min,
                            params.current_max),
                "current_min");
  }
  if (!std::isfinite(params.initial_current) || params.initial_current < params.current_min ||
      params.initial_current > params.current_max) {
    throw Error(fmt::format("coil initial_current = {} must be finite and in [{}, {}]",
                            params.initial_current, params.current_min, params.current_max),
                "initial_current");
  }
  // The scalar case of the zero-order hold: exp(-R h/L) and its integral.
  pole_ = std::exp(-params.resistance * period / params.inductance);
  input_gain_ = -std::expm1(-params.resistance * period / params.inductance) / params.resistance;
}

}  // namespace hyst
