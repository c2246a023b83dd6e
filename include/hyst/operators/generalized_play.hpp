#pragma once
//! \file
//! Generalized play operator G_r (also written S_r): a play whose two branches follow an ascending
//! envelope gamma_l and a descending envelope gamma_r instead of the input itself.
//!
//!     z[k] = max( gamma_l(v[k]) - r , min( gamma_r(v[k]) + r , z[k-1] ) )
//!
//! Parameters: envelopes gamma_l <= gamma_r (envelopes.hpp; strictly increasing), threshold
//! r >= 0 [envelope units]. Output z [envelope units]. Input v [input units].
//! Under the ordering gamma_l <= gamma_r this max/min form equals the direction-switched form of
//! the MSMA paper (v rising: z = max(gamma_l(v) - r, z_prev); v falling: z = min(gamma_r(v) + r,
//! z_prev); checked in the tests), it is rate independent, and the output never moves against
//! the input. With gamma_l = gamma_r = identity it is the classical play F_r.
//! Initial state: z[-1] (default 0); the first step clips it into [gamma_l(v0) - r,
//! gamma_r(v0) + r]. After that, gamma_l(v) - r <= z <= gamma_r(v) + r, so z is bounded by the
//! envelope ranges.
//!
//! Pitfalls:
//! - Do not implement it as the classical play applied to h = gamma_l(v) if v rises, else
//!   gamma_r(v) ("play on h", found in tutorial code): h jumps at every reversal, the output then
//!   moves against the input (8 samples in pi_check.py) and differs from G_r by up to 1.97 on a
//!   +-1.1 range. The two agree only for gamma_l = gamma_r.
//! - Swapped envelopes (gamma_l > gamma_r) make max/min collapse to gamma_l(v) - r: no memory.
//!   The constructor checks the ordering on the declared operating range.
//! Sources: Al Janaideh, Rakheja & Su (2009), Smart Mater. Struct. 18:045001, and (2011) IEEE/ASME
//! TMech 16(4):734-744; reference operators.md section 5.

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "hyst/core/assert.hpp"
#include "hyst/core/scalar_value.hpp"
#include "hyst/models/envelopes.hpp"

namespace hyst {

//! One generalized play step from the envelope values at the current input,
//! ascending = gamma_l(v[k]) and descending = gamma_r(v[k]), which all operators of a GPI model
//! share: z = max(ascending - r, min(descending + r, z)), in place. For gamma_l = gamma_r = v this
//! is bit for bit the classical play_step().
//! With Ceres Jets the branch is chosen on the values with exactly the rule of std::max/std::min,
//! and only the chosen branch is computed (most operators keep their state: no Jet arithmetic at
//! all). The derivative is the one of the active branch: max/min are piecewise linear, and at an
//! exact tie the branch std::max/std::min would return is taken.
template <class T>
inline void generalized_play_update(const T& ascending, const T& descending, const T& threshold,
                                    T& state) {
  if constexpr (std::is_floating_point_v<T>) {
    state = std::max(ascending - threshold, std::min(descending + threshold, state));
  } else {
    const double lower = scalar_value(ascending) - scalar_value(threshold);
    const double upper = scalar_value(descending) + scalar_value(threshold);
    const bool keep = scalar_value(state) < upper;  // std::min(upper, z): z if z < upper
    const double middle = keep ? scalar_value(state) : upper;
    if (lower < middle) {  // std::max(lower, middle): middle if lower < middle
      if (!keep) state = descending + threshold;
    } else {
      state = ascending - threshold;
    }
  }
}

//! generalized_play_update() returning the new state.
template <class T>
inline T generalized_play_step(const T& ascending, const T& descending, const T& threshold,
                               const T& previous) {
  T state = previous;
  generalized_play_update(ascending, descending, threshold, state);
  return state;
}

//! A single generalized play operator with its own envelopes (the building block; the GPI model
//! evaluates the envelopes once per sample for all its operators instead).
template <Envelope E = TanhEnvelope>
class GeneralizedPlay {
 public:
  struct Params {
    std::vector<double> ascending{};   //!< gamma_l coefficients (tanh: a0..a3)
    std::vector<double> descending{};  //!< gamma_r coefficients (tanh: b0..b3)
    double threshold = 0.0;            //!< r >= 0 [envelope units]
    //! Operating range of the input [input units] on which gamma_l <= gamma_r is checked.
    double input_min = std::numeric_limits<double>::quiet_NaN();
    double input_max = std::numeric_limits<double>::quiet_NaN();
  };
  struct State {
    double output = 0.0;  //!< z [envelope units]
  };

  //! Validates the envelopes (envelopes.hpp), r (finite, >= 0) and the ordering on the operating
  //! range; throws hyst::Error naming the parameter ("generalized play threshold r = -0.1 must be
  //! >= 0").
  explicit GeneralizedPlay(Params params);

  const Params& params() const { return params_; }

  //! z[-1] = 0 (clipped into the admissible band by the first step).
  State initial_state() const { return State{}; }
  //! z[-1] = output; throws hyst::Error unless it is finite.
  State make_state(double output) const;

  //! gamma_l(v) and gamma_r(v).
  double ascending(double input) const { return E::value(params_.ascending.data(), input); }
  double descending(double input) const { return E::value(params_.descending.data(), input); }

  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    state.output =
        generalized_play_step(ascending(input), descending(input), params_.threshold, state.output);
    return state.output;
  }

 private:
  Params params_;
};

extern template class GeneralizedPlay<LinearEnvelope>;
extern template class GeneralizedPlay<TanhEnvelope>;
extern template class GeneralizedPlay<ArctanEnvelope>;

}  // namespace hyst
