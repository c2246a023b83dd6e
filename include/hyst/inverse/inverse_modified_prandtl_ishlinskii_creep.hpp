#pragma once
//! \file
//! Exact inverse of the modified PI model with creep (modified_prandtl_ishlinskii_creep.hpp), for
//! feedforward compensation:
//!
//!     v[k] = Gamma_c^{-1}[ S^{-1}(y_d[k] - y_off) ]
//!
//! S^{-1} is again a dead-zone superposition (DeadZoneSuperposition::inverse()); Gamma_c^{-1} is
//! the exact inverse of the PI with creep (InversePrandtlIshlinskiiCreep: the creep memory
//! subtracted, then the analytic inverse PI of the instantaneous weights). Exists when both are;
//! construction throws hyst::Error naming the weight or partial sum that breaks it. The output
//! limits are not inverted: a target beyond them asks for an input the model clamps. An input
//! outside [input_min, input_max] is limited and reported; the state follows the limited input.

#include "hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/modified_prandtl_ishlinskii_creep.hpp"

namespace hyst {

class InverseModifiedPrandtlIshlinskiiCreep {
 public:
  using Options = InversePrandtlIshlinskiiCreep::Options;  //!< input limits [v_min, v_max]
  using State = InversePrandtlIshlinskiiCreep::State;

  InverseModifiedPrandtlIshlinskiiCreep(const ModifiedPrandtlIshlinskiiCreep& model,
                                        const Options& options = {});

  const ModifiedPrandtlIshlinskiiCreep& forward() const { return forward_; }
  //! S^{-1}: thresholds d'_i and weights g'_i.
  const DeadZoneSuperposition& dead_zone_inverse() const { return dead_zone_inverse_; }
  const InversePrandtlIshlinskiiCreep& hysteresis_creep_inverse() const { return core_inverse_; }

  //! The state that continues from the forward model's state `model_state`.
  State state_consistent_with(const ModifiedPrandtlIshlinskiiCreep::State& model_state) const {
    return core_inverse_.state_consistent_with(model_state);
  }
  State initial_state() const { return core_inverse_.initial_state(); }

  //! The input that makes the model produce `target` now; advances the state. No allocation.
  InverseSample solve(State& state, double target) const noexcept {
    return core_inverse_.solve(state, dead_zone_inverse_(target - forward_.params().offset));
  }
  double step(State& state, double target) const noexcept { return solve(state, target).input; }

 private:
  ModifiedPrandtlIshlinskiiCreep forward_;
  DeadZoneSuperposition dead_zone_inverse_;
  InversePrandtlIshlinskiiCreep core_inverse_;
};

}  // namespace hyst
