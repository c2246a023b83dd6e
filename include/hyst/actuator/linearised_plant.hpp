#pragma once
//! \file
//! The linearised actuator, with the hysteresis replaced by its compensated law F = k_F i:
//!
//!     G(s) = X(s)/U(s) = k_F e^{-sT} / ((L s + R)(m s^2 + b s + k))
//!
//! as the 3-state system (i, x, x'):  A = [[-R/L, 0, 0], [0, 0, 1], [k_F/m, -k/m, -b/m]],
//! B = [1/L, 0, 0]^T, output x delayed by T. Poles, DC gain k_F/(R k), the analytic step response
//! x(t) = [A^-1 (exp(A (t - T)) - I) B]_x for t >= T, and the exact zero-order-hold discrete
//! system (one 3x3 update per sample; cascading separately held blocks is not exact, since F is
//! not piecewise constant). Source: reference actuator_msma.md sections 1 and 3.

#include <complex>
#include <vector>

#include <Eigen/Core>

#include "hyst/actuator/actuator.hpp"
#include "hyst/actuator/transport_delay.hpp"

namespace hyst {

class LinearisedPlant {
 public:
  struct Params {
    double resistance = 1.0;  //!< R [Ohm], > 0
    double inductance = 1.0;  //!< L [H], > 0
    double force_gain = 1.0;  //!< k_F [N/A], > 0
    double mass = 1.0;        //!< m [kg], > 0
    double damping = 0.0;     //!< b [N s/m], >= 0
    double stiffness = 1.0;   //!< k [N/m], > 0
    double delay = 0.0;       //!< T [s], >= 0
  };

  //! hyst::Error naming the first invalid field.
  explicit LinearisedPlant(const Params& params);
  //! The plant of an actuator's linear blocks with the compensated force gain k_F.
  static LinearisedPlant of(const ActuatorParams& actuator, double force_gain);

  const Params& params() const { return params_; }
  const Eigen::Matrix3d& a() const { return a_; }
  const Eigen::Vector3d& b() const { return b_; }
  //! -R/L and the two roots of m s^2 + b s + k [rad/s].
  std::vector<std::complex<double>> poles() const;
  //! G(0) = k_F / (R k) [m/V].
  double dc_gain() const;
  //! G(j omega) [m/V].
  std::complex<double> frequency_response(double omega) const;
  //! x(t) [m] for a voltage step of `amplitude` [V] at t = 0 from rest (analytic).
  double step_response(double time, double amplitude = 1.0) const;

  //! The plant sampled exactly at period h (zero-order hold on u), delay on the output.
  class Discrete {
   public:
    struct State {
      Eigen::Vector3d x = Eigen::Vector3d::Zero();  //!< (i, x, x')
      TransportDelay::State delay;
    };
    Discrete(const Eigen::Matrix3d& transition, const Eigen::Vector3d& input, double delay,
             double period)
        : transition_(transition), input_(input), delay_(delay, period) {}
    const Eigen::Matrix3d& transition() const { return transition_; }
    const Eigen::Vector3d& input_matrix() const { return input_; }
    State initial_state() const { return {Eigen::Vector3d::Zero(), delay_.initial_state()}; }
    //! Applies u over one period; returns the delayed position. No allocation.
    double step(State& state, double voltage) const noexcept {
      state.x = transition_ * state.x + input_ * voltage;
      return delay_.step(state.delay, state.x(1));
    }

   private:
    Eigen::Matrix3d transition_;
    Eigen::Vector3d input_;
    TransportDelay delay_;
  };
  Discrete discretise(double period) const;

 private:
  Params params_;
  Eigen::Matrix3d a_;
  Eigen::Vector3d b_;
};

}  // namespace hyst
