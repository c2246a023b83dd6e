#pragma once
//! \file
//! Maxwell-slip model of pre-sliding friction / elasto-plastic hysteresis: N elasto-slide
//! elements in parallel (a spring k_i in series with a block that slips at the break-away force
//! f_i), optionally with a linear spring k_lin in parallel.
//!
//!     delta_i[k] = min(D_i, max(-D_i, delta_i[k-1] + x[k] - x[k-1])),   D_i = f_i / k_i
//!     F[k]       = F_off + k_lin x[k] + sum_i k_i delta_i[k]
//!
//! Each element is a stop operator of half-width D_i (its spring deflection), so the model is the
//! stop-type Prandtl-Ishlinskii model; with k_lin = 0 it saturates at F_off +- sum f_i. Written
//! with play operators (E_D = x - F_D) it is a classical PI model:
//!
//!     F = F_off + (k_lin + sum k_i) x - sum_i k_i F_{D_i}[x],   play states w_i = x - delta_i
//!
//! whose partial sums are k_lin + sum_{i > j} k_i; it is therefore invertible (analytically, by
//! the PI inverse) iff k_lin > 0. to_prandtl_ishlinskii() gives that PI model.
//!
//! Parameters: stiffness k_i > 0 [force/position units], break-away forces f_i > 0 [force units],
//! listed so that the slip displacements D_i = f_i/k_i strictly increase; k_lin >= 0; F_off.
//! State: the deflections delta_i [position units] and the previous position x[k-1]; initial:
//! all delta_i = 0 at x = 0 (relaxed springs). Rate independent (no viscous term); the
//! generalised Maxwell-slip with velocity-dependent slip is out of scope.
//! Sources: Lampaert, Al-Bender & Swevers (2003), IEEE TAC 48:1883; Al-Bender, Lampaert &
//! Swevers (2004); reference other_models.md sec. 6.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "hyst/core/assert.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {

class MaxwellSlip {
 public:
  struct Params {
    std::vector<double> stiffness{};   //!< k_i > 0 [force/position units]
    std::vector<double> break_away{};  //!< f_i > 0 [force units], f_i/k_i increasing
    double linear_stiffness = 0.0;     //!< k_lin >= 0 [force/position units]
    double offset = 0.0;               //!< F_off [force units]
  };
  struct State {
    std::vector<double> deflection;  //!< delta_i [position units], |delta_i| <= D_i
    double input = 0.0;              //!< x[k-1] [position units]
  };

  //! Throws hyst::Error naming the field ("Maxwell-slip stiffness k[2] = 0 must be > 0").
  explicit MaxwellSlip(Params params);

  const Params& params() const { return params_; }
  std::size_t size() const { return params_.stiffness.size(); }
  //! D_i = f_i / k_i [position units].
  const std::vector<double>& slip_displacements() const { return slip_; }
  bool is_invertible() const { return params_.linear_stiffness > 0.0; }

  //! Relaxed springs at x = 0.
  State initial_state() const { return state_at_rest(0.0); }
  //! Relaxed springs at position x0; throws hyst::Error unless x0 is finite.
  State state_at_rest(double input) const;
  //! Given deflections at position `input`; throws hyst::Error unless sizes match, values are
  //! finite and |delta_i| <= D_i.
  State make_state(std::vector<double> deflection, double input) const;

  double output(const State& state) const;

  //! The same model as a classical PI model (file comment), and its play state for `state`.
  PrandtlIshlinskii to_prandtl_ishlinskii() const;
  PrandtlIshlinskii::State prandtl_ishlinskii_state(const State& state) const;

  //! Advances one sample and returns F. No allocation.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    HYST_ASSERT(state.deflection.size() == slip_.size(), "state of another model");
    const double move = input - state.input;
    const double* __restrict k = params_.stiffness.data();
    const double* __restrict limit = slip_.data();
    double* __restrict delta = state.deflection.data();
    double force = params_.offset + params_.linear_stiffness * input;
    for (std::size_t i = 0; i < slip_.size(); ++i) {
      delta[i] = std::clamp(delta[i] + move, -limit[i], limit[i]);
      force += k[i] * delta[i];
    }
    state.input = input;
    return force;
  }

 private:
  Params params_;
  std::vector<double> slip_;
};

}  // namespace hyst
