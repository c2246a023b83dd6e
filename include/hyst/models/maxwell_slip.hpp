#pragma once
//! \file
//! Maxwell-slip model of pre-sliding friction / elasto-plastic hysteresis: N elasto-slide
//! elements in parallel (a spring k_i in series with a block that slips at the break-away force
//! f_i), optionally with a linear spring k_lin in parallel.
//!
//!     delta_i[k] = min(D_i, max(-D_i, delta_i[k-1] + x[k] - x[k-1])),   D_i = f_i / k_i
//!     F[k]       = F_off + k_lin x[k] + s sum_i k_i delta_i[k]
//!
//! Each element is a stop operator of half-width D_i (its spring deflection), so the model is the
//! stop-type Prandtl-Ishlinskii model; with k_lin = 0 it saturates at F_off +- sum f_i. The sign s
//! is the loop orientation in the (x, F) plane: s = +1 (clockwise, the physical friction force:
//! the force leads, its rising branch lies above the falling one) or s = -1 (counter-clockwise:
//! the force lags, as a reaction force or the output of a PI model with positive weights does).
//! Written with play operators (E_D = x - F_D) it is a classical PI model:
//!
//!     F = F_off + (k_lin + s sum k_i) x - s sum_i k_i F_{D_i}[x],   play states w_i = x - delta_i
//!
//! whose slope is k_lin + s sum k_i just after a reversal and k_lin once every element slips; it
//! is therefore invertible (analytically, by the PI inverse) iff both are > 0: k_lin > 0
//! (clockwise) or k_lin > sum k_i (counter-clockwise). to_prandtl_ishlinskii() gives that PI
//! model.
//!
//! Parameters: stiffness k_i > 0 [force/position units], break-away forces f_i > 0 [force units],
//! listed so that the slip displacements D_i = f_i/k_i strictly increase; k_lin >= 0; F_off;
//! orientation (default clockwise, the classical model).
//! State: the deflections delta_i [position units] and the previous position x[k-1]; initial:
//! all delta_i = 0 at x = 0 (relaxed springs). Rate independent (no viscous term); the
//! generalised Maxwell-slip with velocity-dependent slip is out of scope.
//! Sources: Lampaert, Al-Bender & Swevers (2003), IEEE TAC 48:1883; Al-Bender, Lampaert &
//! Swevers (2004); reference other_models.md sec. 6.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string_view>
#include <vector>

#include "hyst/core/assert.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {

class MaxwellSlip {
 public:
  //! Sense in which the (x, F) loop is traversed; fixes the sign s of the element forces.
  enum class Orientation { clockwise, counter_clockwise };

  struct Params {
    std::vector<double> stiffness{};   //!< k_i > 0 [force/position units]
    std::vector<double> break_away{};  //!< f_i > 0 [force units], f_i/k_i increasing
    double linear_stiffness = 0.0;     //!< k_lin >= 0 [force/position units]
    double offset = 0.0;               //!< F_off [force units]
    Orientation orientation = Orientation::clockwise;  //!< s = +1 clockwise, -1 counter-clockwise
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
  //! Slopes k_lin + s sum k_i (after a reversal) and k_lin (all slipping) are > 0 (file comment).
  bool is_invertible() const;
  //! s of the file comment: +1 clockwise, -1 counter-clockwise.
  double element_sign() const { return sign_; }

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
    double elements = 0.0;
    for (std::size_t i = 0; i < slip_.size(); ++i) {
      delta[i] = std::clamp(delta[i] + move, -limit[i], limit[i]);
      elements += k[i] * delta[i];
    }
    state.input = input;
    return params_.offset + params_.linear_stiffness * input + sign_ * elements;
  }

 private:
  Params params_;
  std::vector<double> slip_;
  double sign_ = 1.0;
};

//! "clockwise" / "counter-clockwise" (the model-file and fit-option spelling).
std::string_view orientation_name(MaxwellSlip::Orientation orientation);
//! Throws hyst::Error naming `what` unless text is "clockwise" or "counter-clockwise".
MaxwellSlip::Orientation parse_orientation(std::string_view text, std::string_view what);

}  // namespace hyst
