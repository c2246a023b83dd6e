#pragma once
//! \file
//! Coil of an electromagnetic actuator: voltage u [V] -> current i [A],
//!
//!     L di/dt + R i = u          G_e(s) = I(s)/U(s) = 1/(L s + R),
//!
//! discretised exactly for a voltage held over the period h (zero-order hold):
//!
//!     i[k+1] = a i[k] + (1 - a)/R u[k],   a = exp(-R h / L).
//!
//! The current limit [current_min, current_max] is the amplifier's: the current is clamped to it
//! after each step (a current-limited drive), which also keeps a hysteresis model that follows
//! the coil inside its operating range.
//! Source: Minorowicz & Milecki (2022), Materials 15:4400, section 4.3; reference
//! actuator_msma.md sections 1 and 3.

#include <algorithm>
#include <limits>

namespace hyst {

class Coil {
 public:
  struct Params {
    double resistance = 1.0;                                        //!< R [Ohm], > 0
    double inductance = 1.0;                                        //!< L [H], > 0
    double current_min = -std::numeric_limits<double>::infinity();  //!< [A]
    double current_max = std::numeric_limits<double>::infinity();   //!< [A], > current_min
    double initial_current = 0.0;                                   //!< i[0] [A], inside the limits
  };
  struct State {
    double current = 0.0;  //!< i [A]
  };

  //! Validates the parameters (hyst::Error naming the field) and discretises for `period` [s].
  Coil(const Params& params, double period);

  const Params& params() const { return params_; }
  double period() const { return period_; }
  //! a = exp(-R h/L) and b = (1 - a)/R of the update above.
  double pole() const { return pole_; }
  double input_gain() const { return input_gain_; }
  //! tau_e = L / R [s].
  double time_constant() const { return params_.inductance / params_.resistance; }

  State initial_state() const { return {params_.initial_current}; }
  //! One period with the voltage held; returns the new current. No allocation.
  double step(State& state, double voltage) const noexcept {
    state.current = std::clamp(pole_ * state.current + input_gain_ * voltage, params_.current_min,
                               params_.current_max);
    return state.current;
  }

 private:
  Params params_;
  double period_;
  double pole_;
  double input_gain_;
};

}  // namespace hyst
