#include "hyst/actuator/mechanics.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/actuator/zero_order_hold.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

Mechanics::Mechanics(const Params& params, double period) : params_(params), period_(period) {
  if (!std::isfinite(params.mass) || !(params.mass > 0.0)) {
    throw Error(fmt::format("mechanics mass m = {} must be finite and > 0", params.mass), "mass");
  }
  if (!std::isfinite(params.damping) || params.damping < 0.0) {
    throw Error(fmt::format("mechanics damping b = {} must be finite and >= 0", params.damping),
                "damping");
  }
  if (!std::isfinite(params.stiffness) || !(params.stiffness > 0.0)) {
    throw Error(fmt::format("mechanics stiffness k = {} must be finite and > 0", params.stiffness),
                "stiffness");
  }
  Eigen::MatrixXd a(2, 2);
  a << 0.0, 1.0, -params.stiffness / params.mass, -params.damping / params.mass;
  Eigen::MatrixXd b(2, 1);
  b << 0.0, 1.0 / params.mass;
  const auto hold = zero_order_hold(a, b, period);
  transition_ = hold.transition;
  input_ = hold.input;
}

double Mechanics::natural_frequency() const {
  return std::sqrt(params_.stiffness / params_.mass);
}

double Mechanics::damping_ratio() const {
  return params_.damping / (2.0 * std::sqrt(params_.stiffness * params_.mass));
}

}  // namespace hyst
