#pragma once
//! \file
//! Inverse of the generalized Prandtl-Ishlinskii model (IGPI), built as Al Janaideh, Rakheja & Su
//! (2011) do: the analytic inverse of the classical PI with the same thresholds and weights,
//! applied to the desired output, followed by the inverse envelope of the current direction.
//!
//!     u[k] = P^-1[y_d][k]                       (InversePrandtlIshlinskii of the model's
//!                                                classical() PI: thresholds rh_j, weights ph_j)
//!     d[k] = +1 if u[k] > u[k-1],  -1 if u[k] < u[k-1],  d[k-1] otherwise
//!     v[k] = gamma_l^-1(u[k]) if d[k] = +1,   gamma_r^-1(u[k]) if d[k] = -1
//!     tanh: gamma_l^-1(u) = (atanh((u - a3)/a0) - a2)/a1,  gamma_r^-1(u) = (atanh((u - b3)/b0) -
//!     b2)/b1
//!
//! Exactness: GPI[IGPI[y_d]] = y_d (to rounding, 1.6e-15 on pi_check.py's targets) provided
//! gamma_l <= gamma_r and the two states are consistent: the GPI's z_j then follow the classical
//! plays of u, whose PI output is y_d.
//! Units: target y_d [output units], u [envelope units], returned input v [input units].
//!
//! Initial states. The GPI state z_j (u-space) and the inverse state (the inverse-PI plays wh_j,
//! the last u and the direction d) are consistent when wh_j = S_j z_j + sum_{i>j} p_i z_i (the
//! classical PI rule), u = z_0 and d is the branch the GPI arrived on.
//! - initial_state() matches the GPI's initial_state() (at rest at i0, arrived rising, d = +1).
//! - state_at_rest(y0): every wh_j = y0, d = +1; the matching GPI state has every z_j = y0 / S
//!   (forward_state_consistent_with()). This is the convention of msma_synth.py; with y0 = 0 and
//!   z = 0 it is the one of pi_check.py.
//!
//! Saturation: a saturating envelope reaches only the open interval (lower, upper) of its range,
//! so u must stay in (max(a3 - a0, b3 - b0), min(a3 + a0, b3 + b0)) for tanh. Outside it,
//! solve() clamps the atanh argument to +-(1 - 1e-12), returns the (large, finite) input this
//! gives and the status below_range / above_range; it never throws. Optional input limits
//! [input_min, input_max] (e.g. a 0..8 A current drive) clamp the input further, with the same
//! statuses. After a saturated sample the inverse's state no longer matches the model's exactly:
//! keep targets inside reachable_envelope_range() times the weight sum.
//!
//! Pitfall: at every reversal of u the input jumps from gamma_l^-1(u) to gamma_r^-1(u) (down when
//! u starts to fall). This is the exact inverse of the r = 0 operator's built-in play, but a coil
//! current cannot jump: expect compensation error at reversals unless a fast current loop follows.
//! Sources: Al Janaideh, Rakheja & Su (2011), IEEE/ASME TMech 16(4):734-744; Krejci & Kuhnen
//! (2001); reference generalized_pi.md section 4.

#include <limits>

#include "hyst/core/inverse_status.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"

namespace hyst {

template <Envelope E = TanhEnvelope>
class InverseGeneralizedPrandtlIshlinskii {
 public:
  using Model = GeneralizedPrandtlIshlinskii<E>;
  struct Options {
    double input_min = -std::numeric_limits<double>::infinity();  //!< v_min [input units]
    double input_max = std::numeric_limits<double>::infinity();   //!< v_max >= v_min
  };
  struct State {
    PrandtlIshlinskii::State pi;                //!< inverse-PI plays wh_j [output units]
    double u = 0.0;                             //!< u[k-1] [envelope units]
    LoopBranch branch = LoopBranch::ascending;  //!< d[k-1]
  };

  //! Builds the inverse of `model`; throws hyst::Error when the input limits are NaN or
  //! v_min > v_max (the model's own validation already guarantees p_0 > 0 and S_j > 0).
  InverseGeneralizedPrandtlIshlinskii(const Model& model, const Options& options);
  //! Same, without input limits.
  explicit InverseGeneralizedPrandtlIshlinskii(const Model& model)
      : InverseGeneralizedPrandtlIshlinskii(model, Options{}) {}

  const Model& forward() const { return forward_; }
  //! The classical inverse PI that maps y_d to u.
  const InversePrandtlIshlinskii& inverse_pi() const { return inverse_pi_; }
  const Options& options() const { return options_; }
  //! The open interval of u both inverse envelopes can reach [envelope units].
  EnvelopeRange reachable_envelope_range() const;

  //! Consistent with forward().initial_state(): at rest at i0, arrived rising.
  State initial_state() const;
  //! The inverse state consistent with a GPI state z that was reached on `branch`. Throws
  //! hyst::Error when z is not a reachable state of the model.
  State state_consistent_with(const typename Model::State& forward_state,
                              LoopBranch branch = LoopBranch::ascending) const;
  //! The GPI state consistent with an inverse state (the map above, inverted).
  typename Model::State forward_state_consistent_with(const State& inverse_state) const;
  //! At rest at the output y0: every wh_j = y0, direction ascending. Throws for non-finite y0.
  State state_at_rest(double target) const;

  //! The input that makes the model produce `target`, and whether it had to be limited.
  //! No allocation, never throws.
  InverseSample solve(State& state, double target) const noexcept {
    // A NaN or overflowing target is the inverse PI's to answer (held, or its bound).
    const InverseSample classical = inverse_pi_.solve(state.pi, target);
    const double u = classical.input;
    if (u > state.u) {
      state.branch = LoopBranch::ascending;
    } else if (u < state.u) {
      state.branch = LoopBranch::descending;
    }
    state.u = u;
    const auto& params = forward_.params();
    const InverseSample sample = state.branch == LoopBranch::ascending
                                     ? E::inverse(params.ascending.data(), u)
                                     : E::inverse(params.descending.data(), u);
    if (!(sample.input >= options_.input_min))  // NaN cannot pass
      return {options_.input_min, InverseStatus::below_range};
    if (sample.input > options_.input_max) return {options_.input_max, InverseStatus::above_range};
    if (classical.status != InverseStatus::ok) return {sample.input, classical.status};
    return sample;
  }

  //! solve() without the status, so the inverse also runs wherever a model does.
  double step(State& state, double target) const noexcept { return solve(state, target).input; }

 private:
  Model forward_;
  InversePrandtlIshlinskii inverse_pi_;
  Options options_;
};

extern template class InverseGeneralizedPrandtlIshlinskii<LinearEnvelope>;
extern template class InverseGeneralizedPrandtlIshlinskii<TanhEnvelope>;
extern template class InverseGeneralizedPrandtlIshlinskii<ArctanEnvelope>;

}  // namespace hyst
