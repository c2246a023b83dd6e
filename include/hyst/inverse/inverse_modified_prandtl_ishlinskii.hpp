#pragma once
//! \file
//! Analytic inverse of the modified Prandtl-Ishlinskii model (Kuhnen 2003):
//!
//!     v = Gamma^{-1}[ S^{-1}(y - y_off) ]
//!
//! S^{-1} is again a dead-zone superposition (DeadZoneSuperposition::inverse()), Gamma^{-1} the
//! analytic PI inverse (InversePrandtlIshlinskii), which handles the PI part's own offset.
//! Exists iff both parts are invertible; construction throws hyst::Error naming the weight or
//! partial sum that breaks it. The inverse's play state must be consistent with the forward
//! model's (state_consistent_with(), the PI rule wh_j = S_j z_j + sum_{i>j} p_i z_i).

#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"

namespace hyst {

class InverseModifiedPrandtlIshlinskii {
 public:
  using Options = InversePrandtlIshlinskii::Options;  //!< input limits [v_min, v_max]
  using State = InversePrandtlIshlinskii::State;

  InverseModifiedPrandtlIshlinskii(const ModifiedPrandtlIshlinskii& model, const Options& options);
  explicit InverseModifiedPrandtlIshlinskii(const ModifiedPrandtlIshlinskii& model)
      : InverseModifiedPrandtlIshlinskii(model, Options{}) {}

  //! S^{-1}: thresholds d'_i and weights g'_i.
  const DeadZoneSuperposition& dead_zone_inverse() const { return dead_zone_inverse_; }
  const InversePrandtlIshlinskii& hysteresis_inverse() const { return pi_inverse_; }

  //! Consistent with the forward model's initial_state() (all 0).
  State initial_state() const { return pi_inverse_.initial_state(); }
  State state_consistent_with(const ModifiedPrandtlIshlinskii::State& forward_state) const {
    return pi_inverse_.state_consistent_with(forward_state);
  }

  InverseSample solve(State& state, double target) const noexcept {
    return pi_inverse_.solve(state, dead_zone_inverse_(target - offset_));
  }
  double step(State& state, double target) const noexcept { return solve(state, target).input; }

 private:
  DeadZoneSuperposition dead_zone_inverse_;
  InversePrandtlIshlinskii pi_inverse_;
  double offset_;
};

}  // namespace hyst
