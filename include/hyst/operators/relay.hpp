#pragma once
//! \file
//! Relay (Preisach hysteron) gamma_{alpha,beta}.
//!
//!     s[k] = +1       if v[k] >= alpha
//!            -1       else if v[k] <= beta
//!            s[k-1]   otherwise
//!
//! Parameters: switch-up threshold alpha >= switch-down threshold beta [input units].
//! The `>= alpha` test comes first, so for alpha == beta an input equal to the threshold gives +1.
//! Initial state: -1 (negative saturation) unless given; the first step already applies the rule.
//! Source: Preisach (1935); Mayergoyz (1991), "Mathematical Models of Hysteresis".

#include <cmath>

#include "hyst/core/assert.hpp"

namespace hyst {

class Relay {
 public:
  struct State {
    double output = -1.0;  //!< s, either -1 or +1
  };

  //! Throws hyst::Error unless both thresholds are finite and alpha >= beta.
  Relay(double alpha, double beta);

  double alpha() const { return alpha_; }
  double beta() const { return beta_; }

  //! Negative saturation (s = -1).
  State initial_state() const { return State{}; }
  //! A chosen initial output; throws hyst::Error unless it is -1 or +1.
  State make_state(double output) const;

  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    if (input >= alpha_) {
      state.output = 1.0;
    } else if (input <= beta_) {
      state.output = -1.0;
    }
    return state.output;
  }

 private:
  double alpha_;
  double beta_;
};

}  // namespace hyst
