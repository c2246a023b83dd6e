#pragma once
//! \file
//! The backlash-like hysteresis model of Su, Stepanenko, Svoboda & Leung (2000), IEEE TAC
//! 45(12):2427-2432, a Duhem model with f(v) = c v and g(v) = B1:
//!
//!     w' = a |v'| (c v - w) + B1 v'          a > 0, c > 0, B1 < c
//!
//! It is rate independent, and for an input that is linear between two samples (s = sign(dv),
//! dv = v[k] - v[k-1] != 0) it has the exact solution
//!
//!     K_s  = (B1 - c) / (a s)
//!     w[k] = c v[k] + K_s + (w[k-1] - c v[k-1] - K_s) exp(-a |dv|)
//!
//! (dv = 0 leaves w unchanged), so step() is exact whatever the sample spacing. The branches
//! converge to w = c v -+ (c - B1)/a (rising below, falling above). Right after a reversal from a
//! converged branch dw/dv = 2 B1 - c: for B1 < c/2 the output moves against the input;
//! is_monotone() tells whether c/2 <= B1 (reference other_models.md section 4).
//! State: the previous input v and the output w; initial state v = 0, w = 0.

#include <cmath>

#include "hyst/core/assert.hpp"

namespace hyst {

class BacklashLike {
 public:
  struct Params {
    double a = 1.0;   //!< rate of approach to the branches [1/input units] > 0
    double c = 1.0;   //!< slope of the branches [output/input units] > 0
    double b1 = 0.5;  //!< B1, slope right after a reversal at w = c v [output/input units] < c
  };
  struct State {
    double input = 0.0;   //!< v of the previous sample
    double output = 0.0;  //!< w
  };

  //! Throws hyst::Error naming the parameter and the rule (a > 0, c > 0, B1 < c, all finite).
  explicit BacklashLike(Params params);

  const Params& params() const { return params_; }
  State initial_state() const { return {}; }
  //! At rest at input v0 on the curve w = c v0.
  State state_at(double input, double output) const;
  //! True iff B1 >= c / 2: the output never moves against the input.
  bool is_monotone() const { return params_.b1 >= 0.5 * params_.c; }

  //! Exact step for an input linear between the samples. No allocation.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    const double dv = input - state.input;
    if (dv != 0.0) {
      const double s = dv > 0.0 ? 1.0 : -1.0;
      const double k_s = (params_.b1 - params_.c) / (params_.a * s);
      state.output =
          params_.c * input + k_s +
          (state.output - params_.c * state.input - k_s) * std::exp(-params_.a * std::abs(dv));
      state.input = input;
    }
    return state.output;
  }

 private:
  Params params_;
};

}  // namespace hyst
