#pragma once
//! \file
//! Moving part of an actuator: mass m, damping b, stiffness k driven by a force F [N],
//!
//!     m x'' + b x' + k x = F      G_m(s) = X(s)/F(s) = 1/(m s^2 + b s + k),
//!
//! on the state (x [m], x' [m/s]), discretised exactly for a force held over the period h:
//! Phi = exp(A h), Gamma from the augmented-matrix exponential (zero_order_hold.hpp), with
//! A = [[0, 1], [-k/m, -b/m]], B = [0, 1/m]^T. The step is a fixed-size 2x2 update.
//! Source: reference actuator_msma.md sections 1 and 3.

#include <Eigen/Core>

namespace hyst {

class Mechanics {
 public:
  struct Params {
    double mass = 1.0;       //!< m [kg], > 0
    double damping = 0.0;    //!< b [N s/m], >= 0
    double stiffness = 1.0;  //!< k [N/m], > 0
  };
  struct State {
    double position = 0.0;  //!< x [m]
    double velocity = 0.0;  //!< x' [m/s]
  };

  //! Validates the parameters (hyst::Error naming the field) and discretises for `period` [s].
  Mechanics(const Params& params, double period);

  const Params& params() const { return params_; }
  double period() const { return period_; }
  const Eigen::Matrix2d& transition() const { return transition_; }
  const Eigen::Vector2d& input_matrix() const { return input_; }
  //! omega_n = sqrt(k/m) [rad/s] and zeta = b / (2 sqrt(k m)).
  double natural_frequency() const;
  double damping_ratio() const;

  State initial_state() const { return {}; }
  //! At rest under the constant force F: x = F/k.
  State state_at_rest(double force) const { return {force / params_.stiffness, 0.0}; }
  //! One period with the force held; returns the new position. No allocation.
  double step(State& state, double force) const noexcept {
    const double x =
        transition_(0, 0) * state.position + transition_(0, 1) * state.velocity + input_(0) * force;
    const double v =
        transition_(1, 0) * state.position + transition_(1, 1) * state.velocity + input_(1) * force;
    state.position = x;
    state.velocity = v;
    return x;
  }

 private:
  Params params_;
  double period_;
  Eigen::Matrix2d transition_;
  Eigen::Vector2d input_;
};

}  // namespace hyst
