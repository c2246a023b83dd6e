#pragma once
//! \file
//! Rate-dependent Prandtl-Ishlinskii model (Al Janaideh, Su & Rakheja 2008): play operators whose
//! thresholds grow with the magnitude of the input rate, so that the loops widen with the
//! excitation frequency.
//!
//!     y[k]   = y_off + sum_{j=0..n} p_j w_j[k]
//!     w_j[k] = max(v[k] - r_j[k], min(v[k] + r_j[k], w_j[k-1]))
//!     r_0[k] = 0,   r_j[k] = r_j + beta |vdot[k]|   (j >= 1)
//!     vdot[k]: backward difference (v[k] - v[k-1]) / Ts, optionally low-pass filtered:
//!              vdot[k] = vdot[k-1] + (raw - vdot[k-1]) Ts / (T_f + Ts)   (T_f = 0: no filter)
//!
//! The published form is r_j(t) = alpha j + beta |vdot(t)| with the density p(r) = rho e^{-tau r};
//! rate_dependent_pi_exponential() builds it, with the weights p_j = rho e^{-tau alpha j} taken at
//! the nominal (zero-rate) thresholds so that only the thresholds carry the rate dependence, as in
//! the reference's statement of the model. r_0 = 0 is kept at every rate (the linear term; needed
//! for invertibility), and the thresholds stay increasing in j at every rate.
//!
//! Parameters: nominal thresholds 0 = r_0 < r_1 < ... [input units], weights p_j, rate gain
//! beta >= 0 [s], sample time Ts > 0 [s], rate filter time constant T_f >= 0 [s], offset y_off.
//! With beta = 0 (or at zero rate) it is the classical PrandtlIshlinskii, sample for sample (up
//! to the rounding of a different summation order).
//! State: play outputs w_j (default 0), the previous input and the filtered rate (default 0 at
//! v = 0). Not rate independent: the output depends on the sample time; noise on v makes the
//! thresholds jitter (use T_f). The inverse (Al Janaideh & Krejci 2013) is not provided.
//! Sources: Al Janaideh, Su & Rakheja (2008), Smart Mater. Struct. 17:035026; reference
//! prandtl_ishlinskii.md sec. 4.

#include <cmath>
#include <cstddef>
#include <vector>

#include "hyst/core/assert.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {

class RateDependentPrandtlIshlinskii {
 public:
  struct Params {
    std::vector<double> thresholds{};  //!< nominal r_j [input units], 0 = r_0 < r_1 < ...
    std::vector<double> weights{};     //!< p_j, one per threshold
    double rate_gain = 0.0;            //!< beta >= 0 [s]: threshold increase per unit |rate|
    double sample_time = 1.0;          //!< Ts > 0 [s]
    double rate_filter = 0.0;          //!< T_f >= 0 [s], 0 = unfiltered backward difference
    double offset = 0.0;               //!< y_off [output units]
  };
  struct State {
    std::vector<double> play;  //!< w_j [input units]
    double input = 0.0;        //!< v[k-1]
    double rate = 0.0;         //!< filtered vdot[k-1] [input units / s]
  };

  //! Throws hyst::Error naming the field.
  explicit RateDependentPrandtlIshlinskii(Params params);

  const Params& params() const { return params_; }
  std::size_t size() const { return params_.thresholds.size(); }
  //! The classical PI with the nominal thresholds: this model at zero rate.
  const PrandtlIshlinskii& classical() const { return classical_; }

  //! All plays at 0, at rest at v = 0.
  State initial_state() const { return State{std::vector<double>(size(), 0.0), 0.0, 0.0}; }
  //! At rest at v0 (every play centred, zero rate).
  State state_at_rest(double input) const;
  //! A given state; throws hyst::Error unless the values are finite and every play lies within
  //! its current threshold r_j + beta |rate| of the input (as after any step).
  State make_state(std::vector<double> play, double input, double rate) const;

  double output(const State& state) const {
    return classical_.output(PrandtlIshlinskii::State{state.play});
  }

  //! Advances one sample. No allocation.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    HYST_ASSERT(state.play.size() == params_.thresholds.size(), "state of another model");
    const double raw = (input - state.input) * inverse_sample_time_;
    state.rate += (raw - state.rate) * filter_gain_;
    state.input = input;
    const double widening = params_.rate_gain * std::abs(state.rate);
    const double* __restrict r = params_.thresholds.data();
    double* __restrict w = state.play.data();
    double y = params_.offset + params_.weights[0] * input;
    w[0] = input;
    for (std::size_t j = 1; j < size(); ++j) {
      w[j] = play_step(input, r[j] + widening, w[j]);
      y += params_.weights[j] * w[j];
    }
    return y;
  }

 private:
  Params params_;
  PrandtlIshlinskii classical_;
  double inverse_sample_time_;
  double filter_gain_;
};

//! Al Janaideh's form: nominal thresholds r_j = alpha j and weights p_j = rho e^{-tau alpha j},
//! j = 0..n, rate gain beta. Throws hyst::Error unless alpha > 0, rho > 0, tau finite, beta >=
//! 0, Ts > 0.
RateDependentPrandtlIshlinskii::Params rate_dependent_pi_exponential(double alpha, double rho,
                                                                     double tau, std::size_t n,
                                                                     double beta,
                                                                     double sample_time);

}  // namespace hyst
