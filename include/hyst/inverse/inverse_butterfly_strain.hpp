#pragma once
//! \file
//! Inverse of the butterfly strain model where it exists.
//!
//! From a given state the polarisation P(u) of the next input u never decreases with u (the
//! Preisach weights are >= 0), and the strain y = y_off + d u + q(P(u)) increases with u wherever
//! q'(P) and d do not have opposite signs. A butterfly has a vertex: at the critical
//! polarisations P*, the real roots of q'(P) = sum n q_n P^(n-1) (computed once, at
//! construction), the strain turns back. So each sample first checks the branch: with
//! P_lo = P(u_min) and P_hi = P(u_max) from the current state, the map u -> y is monotone over
//! [u_min, u_max] if no critical polarisation lies strictly inside (P_lo, P_hi) and the field term
//! does not oppose q' there (d q'(P) >= 0). Then the bracketed search of the numerical inverse
//! (numerical_inverse.hpp) solves it (status ok, below_range or above_range); otherwise no input
//! is unique: the previous input is held (applied again) and the status is not_invertible.
//!
//! In practice: a unipolar drive below the coercive voltage stays on one side of the vertex and
//! is inverted exactly; limits that reach the coercive voltage give not_invertible on the samples
//! where switching would be possible, never a wrong input.

#include <cmath>
#include <utility>
#include <vector>

#include "hyst/core/inverse_status.hpp"
#include "hyst/inverse/numerical_inverse.hpp"
#include "hyst/models/butterfly_strain.hpp"

namespace hyst {

class InverseButterflyStrain {
 public:
  using Model = ButterflyStrain;
  using State = ButterflyStrain::State;  //!< the forward model's state

  //! Throws hyst::Error unless input_min < input_max are finite (NumericalInverseOptions).
  InverseButterflyStrain(ButterflyStrain model, const NumericalInverseOptions& options);

  const ButterflyStrain& model() const { return search_.forward(); }
  double input_min() const { return search_.input_min(); }
  double input_max() const { return search_.input_max(); }
  //! The forward model's initial state.
  State initial_state() const { return model().initial_state(); }
  //! The real roots of dy/dP, increasing [P units].
  const std::vector<double>& critical_polarisations() const { return critical_; }

  //! True if u -> y is monotone over the input limits from `state` (file comment).
  bool invertible_from(const State& state) const noexcept;

  //! The input that makes the model produce `target` from `state` (advanced with it). Never
  //! throws, never allocates.
  InverseSample solve(State& state, double target) const noexcept {
    if (invertible_from(state)) return search_.solve(state, target);
    const double held = std::isfinite(state.input) ? state.input : hold_default_;
    model().step(state, held);
    return {held, InverseStatus::not_invertible};
  }
  double step(State& state, double target) const noexcept { return solve(state, target).input; }

 private:
  NumericalInverse<ButterflyStrain> search_;
  std::vector<double> critical_;
  double hold_default_;  // held before any input: the limit nearest zero
};

}  // namespace hyst
