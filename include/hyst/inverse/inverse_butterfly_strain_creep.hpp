#pragma once
//! \file
//! Inverse of the butterfly strain model with creep where it exists.
//!
//! At one sample the polarisation P(u) of the next input u never falls as u rises (the switching
//! part is a Preisach output, the creep adds its lags' current share of the plays, both monotone
//! in u), so P(u) covers [P(u_min), P(u_max)] and y(u) = y_off + d u + q(P(u)) is monotone over
//! the input limits when q'(P) keeps one sign over that interval and d does not oppose it. The
//! sign is checked at 65 evenly spaced polarisations of the interval and at its ends (a vertex of
//! q closer than 1/64 of the interval to another root of q' can be missed; q of degree 2, the
//! usual butterfly, has one vertex and is decided exactly up to that spacing). On a monotone
//! range the bracketed search of the numerical inverse (numerical_inverse.hpp) solves it (status
//! ok, below_range or above_range); otherwise the previous input is held (applied again) and the
//! status is not_invertible, as for the butterfly model without creep
//! (inverse_butterfly_strain.hpp).

#include <cmath>
#include <utility>

#include "hyst/core/inverse_status.hpp"
#include "hyst/inverse/numerical_inverse.hpp"
#include "hyst/models/butterfly_strain_creep.hpp"

namespace hyst {

class InverseButterflyStrainCreep {
 public:
  using Model = ButterflyStrainCreep;
  using State = ButterflyStrainCreep::State;  //!< the forward model's state

  //! Throws hyst::Error unless input_min < input_max are finite (NumericalInverseOptions).
  InverseButterflyStrainCreep(ButterflyStrainCreep model, const NumericalInverseOptions& options);

  const ButterflyStrainCreep& model() const { return search_.forward(); }
  double input_min() const { return search_.input_min(); }
  double input_max() const { return search_.input_max(); }
  //! The forward model's initial state.
  State initial_state() const { return model().initial_state(); }
  //! True if u -> y is monotone over the input limits from `state` (file comment).
  bool invertible_from(const State& state) const noexcept;

  //! The input that makes the model produce `target` from `state` (advanced with it). Never
  //! throws, never allocates.
  InverseSample solve(State& state, double target) const noexcept {
    if (invertible_from(state)) return search_.solve(state, target);
    const double held =
        std::isfinite(state.switching.input) ? state.switching.input : hold_default_;
    model().step(state, held);
    return {held, InverseStatus::not_invertible};
  }
  double step(State& state, double target) const noexcept { return solve(state, target).input; }

 private:
  NumericalInverse<ButterflyStrainCreep> search_;
  double hold_default_;  // held before any input: the limit nearest zero
};

}  // namespace hyst
