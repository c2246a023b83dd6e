#pragma once
//! \file
//! Play (backlash) operator F_r in the threshold form.
//!
//!     w[k] = max(v[k] - r, min(v[k] + r, w[k-1]))
//!
//! Parameter: half-width r >= 0 [input units] (the dead band is 2r wide). Output w [input units].
//! Invariant: |v[k] - w[k]| <= r; F_0[v] = v. Exact at the samples for inputs that are monotone
//! between samples, hence rate independent.
//! Initial state: w[-1] (default 0); any value is admissible, it is clipped into
//! [v[0] - r, v[0] + r] by the first step.
//! Sources: Krasnosel'skii & Pokrovskii (1989); Brokate & Sprekels (1996); Kuhnen (2003).

#include <algorithm>
#include <cmath>
#include <span>
#include <string_view>

#include "hyst/core/assert.hpp"

namespace hyst {

//! One play step; the building block of the PI model and its inverse.
inline double play_step(double input, double half_width, double previous) noexcept {
  return std::max(input - half_width, std::min(input + half_width, previous));
}

//! Throws hyst::Error unless a bank of plays with half-widths `thresholds` (increasing) can reach
//! the outputs `play` from some input history: finite values, one per play, neighbours differing
//! by at most the difference of their thresholds (which implies it for every pair; a relative
//! slack of 1e-12 absorbs rounding in states computed by running a history). Messages name the
//! model and the state's symbol, e.g. "PI", "w": "PI state w[2] = 1.5 and w[1] = 0 differ by 1.5,
//! more than r[2] - r[1] = 0.4: no input history reaches this state".
void require_reachable_plays(std::span<const double> play, std::span<const double> thresholds,
                             std::string_view model, std::string_view symbol);

class Play {
 public:
  struct State {
    double output = 0.0;  //!< w [input units]
  };

  //! Throws hyst::Error unless r is finite and >= 0.
  explicit Play(double half_width);

  double half_width() const { return half_width_; }

  //! w[-1] = 0.
  State initial_state() const { return State{}; }
  //! w[-1] = output; throws hyst::Error unless it is finite.
  State make_state(double output) const;

  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    state.output = play_step(input, half_width_, state.output);
    return state.output;
  }

 private:
  double half_width_;
};

}  // namespace hyst
