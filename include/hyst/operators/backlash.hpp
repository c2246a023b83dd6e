#pragma once
//! \file
//! Backlash with gain K and half-width h, in the form of the seed paper
//! ("Modeling and control of nonlinearities hysteresis type", eqs. 3.1-3.2):
//!
//!     y(k) = K (u(k) + h)   if u(k) < u-
//!     y(k) = y(k-1)         if u- <= u(k) <= u+
//!     y(k) = K (u(k) - h)   if u(k) > u+
//!     u- = y(k-1)/K - h,    u+ = y(k-1)/K + h
//!
//! (The seed prints y(k+1) in the middle line; it must read y(k-1).) For K > 0 this equals
//! K * F_h[u] with play state w = y/K; K <= 0 flips the inequalities and is rejected.
//! Optional output saturation y = clamp(y, y_min, y_max) after the update gives the seed's
//! "backlash with saturation" (an assumed form: the seed gives no equation for it).

#include <algorithm>
#include <cmath>
#include <limits>

#include "hyst/core/assert.hpp"

namespace hyst {

class Backlash {
 public:
  struct Params {
    double gain = 1.0;                                             //!< K > 0 [output/input units]
    double half_width = 0.0;                                       //!< h >= 0 [input units]
    double output_min = -std::numeric_limits<double>::infinity();  //!< y_min [output units]
    double output_max = std::numeric_limits<double>::infinity();   //!< y_max >= y_min
  };
  struct State {
    double output = 0.0;  //!< y(k-1) [output units]
  };

  //! Throws hyst::Error naming the parameter that breaks K > 0, h >= 0 or y_min <= y_max.
  explicit Backlash(const Params& params);

  const Params& params() const { return params_; }

  State initial_state() const { return State{}; }
  //! y(-1) = output; throws hyst::Error unless it is finite.
  State make_state(double output) const;

  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    const double lower = state.output / params_.gain - params_.half_width;
    const double upper = state.output / params_.gain + params_.half_width;
    double y = state.output;
    if (input < lower) {
      y = params_.gain * (input + params_.half_width);
    } else if (input > upper) {
      y = params_.gain * (input - params_.half_width);
    }
    state.output = std::clamp(y, params_.output_min, params_.output_max);
    return state.output;
  }

 private:
  Params params_;
};

}  // namespace hyst
