#pragma once
//! \file
//! Inverse of the butterfly strain model where it exists.
//!
//! From a given state the polarisation P(u) of the next input u is piecewise constant: it changes
//! only at the relay grid's thresholds c_k, and between two thresholds the strain
//! y(u) = y_off + d u + q(P) moves with d u alone. So whether u -> y is monotone over
//! [u_min, u_max] is decided exactly by y at u_min, at u_max, at every threshold inside and at the
//! midpoints between them (at most 2 N + 2 previews, no allocation): the sampled values must not
//! change direction, and d must not oppose them. A butterfly turns back where P crosses a vertex
//! of q (a root of q'(P)); its branches on either side are monotone. On a monotone range the
//! bracketed search of the numerical inverse (numerical_inverse.hpp) solves it (status ok,
//! below_range or above_range); otherwise no input is unique: the previous input is held (applied
//! again) and the status is not_invertible.
//!
//! In practice: a unipolar drive below the coercive voltage stays on one branch and is inverted
//! exactly; limits that reach the coercive voltage give not_invertible on the samples where
//! switching would be possible, never a wrong input.

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
  std::vector<double> thresholds_;  // of the polarisation's relay grid, increasing
  double hold_default_;             // held before any input: the limit nearest zero
};

}  // namespace hyst
