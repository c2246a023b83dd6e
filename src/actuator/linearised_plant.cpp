#include "hyst/actuator/linearised_plant.hpp"

#include <cmath>

#include <fmt/format.h>
#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include "hyst/actuator/zero_order_hold.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

void require(double value, bool positive, const char* field) {
  const bool ok = std::isfinite(value) && (positive ? value > 0.0 : value >= 0.0);
  if (!ok) {
    throw Error(fmt::format("linearised plant {} = {} must be finite and {}", field, value,
                            positive ? "> 0" : ">= 0"),
                field);
  }
}

}  // namespace

LinearisedPlant::LinearisedPlant(const Params& params) : params_(params) {
  require(params.resistance, true, "resistance");
  require(params.inductance, true, "inductance");
  require(params.force_gain, true, "force_gain");
  require(params.mass, true, "mass");
  require(params.damping, false, "damping");
  require(params.stiffness, true, "stiffness");
  require(params.delay, false, "delay");
  const auto& p = params;
  a_ << -p.resistance / p.inductance, 0.0, 0.0,  //
      0.0, 0.0, 1.0,                             //
      p.force_gain / p.mass, -p.stiffness / p.mass, -p.damping / p.mass;
  b_ << 1.0 / p.inductance, 0.0, 0.0;
}

LinearisedPlant LinearisedPlant::of(const ActuatorParams& actuator, double force_gain) {
  return LinearisedPlant({actuator.coil.resistance, actuator.coil.inductance, force_gain,
                          actuator.mechanics.mass, actuator.mechanics.damping,
                          actuator.mechanics.stiffness, actuator.delay});
}

std::vector<std::complex<double>> LinearisedPlant::poles() const {
  const auto& p = params_;
  const std::complex<double> discriminant(p.damping * p.damping - 4.0 * p.mass * p.stiffness, 0.0);
  const std::complex<double> root = std::sqrt(discriminant);
  return {std::complex<double>(-p.resistance / p.inductance, 0.0),
          (-p.damping + root) / (2.0 * p.mass), (-p.damping - root) / (2.0 * p.mass)};
}

double LinearisedPlant::dc_gain() const {
  return params_.force_gain / (params_.resistance * params_.stiffness);
}

std::complex<double> LinearisedPlant::frequency_response(double omega) const {
  const auto& p = params_;
  const std::complex<double> s(0.0, omega);
  return p.force_gain * std::exp(-s * p.delay) /
         ((p.inductance * s + p.resistance) * (p.mass * s * s + p.damping * s + p.stiffness));
}

double LinearisedPlant::step_response(double time, double amplitude) const {
  const double t = time - params_.delay;
  if (!(t > 0.0)) return 0.0;
  // x(t) = [A^-1 (exp(A t) - I) B]_x u: A is invertible (R, k > 0).
  const Eigen::Matrix3d exponential = (a_ * t).exp();
  const Eigen::Vector3d state =
      a_.partialPivLu().solve((exponential - Eigen::Matrix3d::Identity()) * b_);
  return state(1) * amplitude;
}

LinearisedPlant::Discrete LinearisedPlant::discretise(double period) const {
  const auto hold = zero_order_hold(a_, b_, period);
  return Discrete(hold.transition, hold.input, params_.delay, period);
}

}  // namespace hyst
