#pragma once
//! \file
//! Discrete parallel PID controller run at the sample period h, in the form of Astrom &
//! Hagglund (2006), "Advanced PID Control" (reference actuator_msma.md section 5):
//!
//!     e[k] = r[k] - y[k]
//!     P    = Kp e[k]
//!     D[k] = Tf/(Tf + h) D[k-1] - Kd/(Tf + h) (y[k] - y[k-1])     derivative on the measurement,
//!                                                                first-order filter Tf
//!     v    = P + I[k] + D[k] + feedforward
//!     u[k] = sat(v, u_min, u_max)
//!
//! Anti-windup, selectable:
//! - none:              I[k+1] = I[k] + Ki h e[k]
//! - clamping:          the same, except that the integral is frozen while the output is
//!                      saturated and e[k] would drive it further into saturation
//! - back_calculation:  I[k+1] = I[k] + Ki h e[k] + (h/Tt)(u[k] - v)
//!                      (tracking time Tt; default sqrt(Ti Td) with Ti = Kp/Ki, Td = Kd/Kp, or
//!                      Ti without derivative action, or h without proportional action)
//!
//! The first step takes y[k-1] = y[k] (no derivative kick); start() initialises the integral for
//! a bumpless switch-on at a given output.

#include <algorithm>
#include <limits>
#include <string_view>

#include "hyst/core/enum_names.hpp"

namespace hyst::control {

using hyst::to_string;

enum class AntiWindup : unsigned char { none, clamping, back_calculation };
constexpr EnumNames<AntiWindup, 3> enumerator_names(AntiWindup) {
  return {{
      {AntiWindup::none, "none"},
      {AntiWindup::clamping, "clamping"},
      {AntiWindup::back_calculation, "back_calculation"},
  }};
}
//! The inverse of to_string(); hyst::Error for other text.
AntiWindup anti_windup_from_string(std::string_view text);

class Pid {
 public:
  struct Params {
    double kp = 0.0;                 //!< proportional gain [output/error units], >= 0
    double ki = 0.0;                 //!< integral gain [output/(error units s)], >= 0
    double kd = 0.0;                 //!< derivative gain [output s/error units], >= 0
    double derivative_filter = 0.0;  //!< Tf [s], >= 0 (0: unfiltered difference)
    double output_min = -std::numeric_limits<double>::infinity();
    double output_max = std::numeric_limits<double>::infinity();  //!< > output_min
    AntiWindup anti_windup = AntiWindup::back_calculation;
    //! Tt [s] of back-calculation, > 0; NaN: the default of the file comment.
    double tracking_time = std::numeric_limits<double>::quiet_NaN();
  };
  struct State {
    double integral = 0.0;              //!< I[k]
    double derivative = 0.0;            //!< D[k-1]
    double previous_measurement = 0.0;  //!< y[k-1]
    bool started = false;               //!< false until the first step
  };

  //! Validates the parameters (hyst::Error naming the field); `period` h > 0 [s].
  Pid(const Params& params, double period);

  const Params& params() const { return params_; }
  double period() const { return period_; }
  //! The tracking time in use (the default resolved).
  double tracking_time() const { return tracking_time_; }

  State initial_state() const { return {}; }
  //! Bumpless start: the state in which step(r, y, feedforward) returns `output` (within the
  //! limits), I = output - P - feedforward.
  State start(double output, double reference, double measurement, double feedforward = 0.0) const;

  //! One controller period; returns u[k]. No allocation, never throws.
  double step(State& state, double reference, double measurement,
              double feedforward = 0.0) const noexcept {
    const double error = reference - measurement;
    if (!state.started) {
      state.previous_measurement = measurement;
      state.started = true;
    }
    state.derivative = derivative_memory_ * state.derivative -
                       derivative_gain_ * (measurement - state.previous_measurement);
    state.previous_measurement = measurement;
    const double unsaturated = params_.kp * error + state.integral + state.derivative + feedforward;
    const double output = std::clamp(unsaturated, params_.output_min, params_.output_max);
    const double increment = params_.ki * period_ * error;
    switch (params_.anti_windup) {
      case AntiWindup::none:
        state.integral += increment;
        break;
      case AntiWindup::clamping:
        if (!((unsaturated > params_.output_max && increment > 0.0) ||
              (unsaturated < params_.output_min && increment < 0.0))) {
          state.integral += increment;
        }
        break;
      case AntiWindup::back_calculation:
        state.integral += increment + period_ / tracking_time_ * (output - unsaturated);
        break;
    }
    return output;
  }

 private:
  Params params_;
  double period_;
  double tracking_time_ = 0.0;
  double derivative_memory_ = 0.0;  // Tf / (Tf + h)
  double derivative_gain_ = 0.0;    // Kd / (Tf + h)
};

}  // namespace hyst::control
