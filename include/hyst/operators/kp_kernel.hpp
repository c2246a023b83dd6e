#pragma once
//! \file
//! Krasnosel'skii-Pokrovskii (KP) kernel: a relay whose switching is spread over a ramp of width
//! a > 0, the hysteron of the KP model (krasnoselskii_pokrovskii.hpp).
//!
//!     rho_a(x) = -1 (x < 0),  -1 + 2x/a (0 <= x <= a),  +1 (x > a)
//!     kappa[k] = max( rho_a(v[k] - s2), min( rho_a(v[k] - s1), kappa[k-1] ) )      s1 <= s2
//!
//! The ascending branch ramps from -1 at v = s2 to +1 at s2 + a, the descending one from +1 at
//! s1 + a to -1 at s1. The max/min form equals the direction-switched textbook form (rising:
//! max(kappa, rho(v - s2)), falling: min(kappa, rho(v - s1))) because rho_a(v - s2) <=
//! rho_a(v - s1). a -> 0 gives the relay with alpha = s2, beta = s1. Initial state kappa = -1.
//! Sources: Krasnosel'skii & Pokrovskii (1989); Banks, Kurdila & Webb (1997); reference
//! operators.md sec. 6.

#include <algorithm>
#include <cmath>

#include "hyst/core/assert.hpp"

namespace hyst {

//! rho_a(x), with 2/a passed in (the model evaluates it for many kernels).
inline double kp_ridge(double x, double two_over_ramp) noexcept {
  return std::clamp(-1.0 + x * two_over_ramp, -1.0, 1.0);
}

//! One kernel step from the ridge values at the up- and down-switching points.
inline double kp_kernel_step(double up, double down, double previous) noexcept {
  return std::max(up, std::min(down, previous));
}

class KpKernel {
 public:
  struct State {
    double output = -1.0;  //!< kappa in [-1, 1]
  };

  //! Throws hyst::Error unless s1 <= s2, a > 0 and all are finite.
  KpKernel(double down_switch, double up_switch, double ramp);

  double down_switch() const { return down_; }
  double up_switch() const { return up_; }
  double ramp() const { return ramp_; }

  State initial_state() const { return State{}; }

  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    state.output = kp_kernel_step(kp_ridge(input - up_, two_over_ramp_),
                                  kp_ridge(input - down_, two_over_ramp_), state.output);
    return state.output;
  }

 private:
  double down_;
  double up_;
  double ramp_;
  double two_over_ramp_;
};

}  // namespace hyst
