#pragma once
//! \file
//! Exact inverse of the PI model with creep (prandtl_ishlinskii_creep.hpp), for feedforward
//! compensation. Within a sample the model is a PI in the current input,
//!
//!     y[k] = y_off + sum_j ph_j w_j[k] + m[k],   ph_j = p_j + sum_i c_ij (1 - a_i),
//!     m[k] = sum_ij c_ij a_i z_ij[k-1]   (fixed by the past),
//!
//! so the input for a target y_d is the analytic inverse PI of the weights ph_j applied to
//! y_d - m[k] (the creep part inverted exactly, the hysteresis by its inverse operator); the
//! model's state is then advanced with that input. It exists when ph_0 > 0 and every partial sum of
//! the ph_j is > 0, which a fit (p_0 > 0, all other weights >= 0) guarantees. An input outside
//! [input_min, input_max] is limited and reported; the state follows the limited input.

#include <cstddef>
#include <vector>

#include "hyst/core/inverse_status.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"

namespace hyst {

class InversePrandtlIshlinskiiCreep {
 public:
  using Options = InversePrandtlIshlinskii::Options;
  struct State {
    PrandtlIshlinskiiCreep::State model;    //!< the forward model's state
    InversePrandtlIshlinskii::State plays;  //!< the inverse operator's plays, consistent with it
  };

  //! Throws hyst::Error when the instantaneous PI is not invertible (names the partial sum).
  InversePrandtlIshlinskiiCreep(const PrandtlIshlinskiiCreep& model, const Options& options = {});

  const PrandtlIshlinskiiCreep& forward() const { return forward_; }
  //! The inverse PI of the instantaneous weights ph_j (no offset).
  const InversePrandtlIshlinskii& instantaneous_inverse() const { return instantaneous_; }

  //! The state that continues from the forward model's state `model_state`.
  State state_consistent_with(const PrandtlIshlinskiiCreep::State& model_state) const;
  State initial_state() const { return state_consistent_with(forward_.initial_state()); }

  //! The input that makes the model produce `target` now; advances the state. No allocation.
  InverseSample solve(State& state, double target) const noexcept {
    const double memory = forward_.creep_memory(state.model);
    const InverseSample sample =
        instantaneous_.solve(state.plays, target - forward_.params().offset - memory);
    forward_.step(state.model, sample.input);
    if (sample.status != InverseStatus::ok) resynchronise(state);
    return sample;
  }
  double step(State& state, double target) const noexcept { return solve(state, target).input; }

 private:
  // After a limited input: the inverse plays from the forward plays,
  // wh_j = S_j w_j + sum_{i>j} ph_i w_i, in place.
  void resynchronise(State& state) const noexcept;

  PrandtlIshlinskiiCreep forward_;
  InversePrandtlIshlinskii instantaneous_;
};

}  // namespace hyst
