#pragma once
//! \file
//! Stop operator E_r (elastic-plastic element: spring of stiffness 1, yield level r).
//!
//!     e[k] = min(r, max(-r, e[k-1] + v[k] - v[k-1]))
//!
//! With the same initial history, E_r[v] = v - F_r[v] (F_r the play operator); the output stays
//! in [-r, r]. The state holds e[k-1] and v[k-1]; the default (e = 0, v = 0) is the history of a
//! play started at w = 0.
//! Sources: Brokate & Sprekels (1996); Kuhnen (2003).

#include <algorithm>
#include <cmath>

#include "hyst/core/assert.hpp"

namespace hyst {

class Stop {
 public:
  struct State {
    double output = 0.0;      //!< e[k-1] [input units]
    double last_input = 0.0;  //!< v[k-1] [input units]
  };

  //! Throws hyst::Error unless r is finite and >= 0.
  explicit Stop(double half_width);

  double half_width() const { return half_width_; }

  State initial_state() const { return State{}; }
  //! The state equivalent to a play operator with output `play_output` at input `input`;
  //! throws hyst::Error unless |input - play_output| <= r.
  State state_from_play(double play_output, double input) const;

  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    state.output =
        std::min(half_width_, std::max(-half_width_, state.output + input - state.last_input));
    state.last_input = input;
    return state.output;
  }

 private:
  double half_width_;
};

}  // namespace hyst
