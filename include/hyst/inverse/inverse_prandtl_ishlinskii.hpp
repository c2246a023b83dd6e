#pragma once
//! \file
//! Analytic inverse of the Prandtl-Ishlinskii model (Krejci & Kuhnen 2001; Kuhnen 2003).
//!
//! The inverse of a PI operator is again a PI operator, acting on the desired output y:
//!
//!     v[k] = sum_j ph_j wh_j[k],   wh_j[k] = max(y'[k] - rh_j, min(y'[k] + rh_j, wh_j[k-1]))
//!     y'   = y - y_off
//!     rh_j = sum_{i<=j} p_i (r_j - r_i),   ph_0 = 1/p_0,   ph_j = -p_j / (S_j S_{j-1})
//!     S_j  = p_0 + ... + p_j
//!
//! It exists iff p_0 > 0 and every S_j > 0; otherwise construction throws hyst::Error naming the
//! index. **Initial states matter**: the inverse must start from the state consistent with the
//! forward model's, wh_j = S_j z_j + sum_{i>j} p_i z_i (state_consistent_with()); any other rule
//! leaves a permanent error of several percent of the range.
//!
//! Optional input limits [v_min, v_max] model an actuator's admissible input: a target that needs
//! more is answered with the limit and a status, never an exception.
//!
//! No target makes the answer NaN: a NaN target holds the last input (status not_invertible,
//! the state unchanged), and a target beyond +-target_bound() (+-inf, 1e308: where the inverse
//! operator's sum would overflow) is answered as that bound (status above_range / below_range).

#include <cmath>
#include <limits>
#include <vector>

#include "hyst/core/inverse_status.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {

class InversePrandtlIshlinskii {
 public:
  struct Options {
    double input_min = -std::numeric_limits<double>::infinity();  //!< v_min [input units]
    double input_max = std::numeric_limits<double>::infinity();   //!< v_max >= v_min
  };
  using State = PrandtlIshlinskii::State;  //!< wh_j [output units]

  //! Builds the inverse of `model`; throws hyst::Error when p_0 <= 0 or a partial sum S_j <= 0
  //! ("PI partial sum S[3] = p[0] + ... + p[3] = -0.1 must be > 0 for the inverse to exist").
  InversePrandtlIshlinskii(const PrandtlIshlinskii& model, const Options& options);
  //! Same, without input limits.
  explicit InversePrandtlIshlinskii(const PrandtlIshlinskii& model)
      : InversePrandtlIshlinskii(model, Options{}) {}

  //! The inverse as a PI operator on y - y_off: thresholds rh_j, weights ph_j, no offset.
  const PrandtlIshlinskii& inverse_operator() const { return inverse_; }
  const PrandtlIshlinskii& forward() const { return forward_; }
  const Options& options() const { return options_; }

  //! Consistent with the forward model's initial_state() (all zero): all wh_j = 0.
  State initial_state() const { return inverse_.initial_state(); }
  //! The inverse state consistent with a forward state z: wh_j = S_j z_j + sum_{i>j} p_i z_i.
  State state_consistent_with(const PrandtlIshlinskii::State& forward_state) const;
  //! The forward state consistent with an inverse state (the map above, inverted).
  PrandtlIshlinskii::State forward_state_consistent_with(const State& inverse_state) const;

  //! The input that makes the model produce `target`, and whether it had to be limited.
  InverseSample solve(State& state, double target) const noexcept {
    const double shifted = target - forward_.params().offset;
    if (std::isnan(shifted)) return limited(inverse_.output(state), InverseStatus::not_invertible);
    if (shifted > target_bound_)
      return limited(inverse_.step(state, target_bound_), InverseStatus::above_range);
    if (shifted < -target_bound_)
      return limited(inverse_.step(state, -target_bound_), InverseStatus::below_range);
    return limited(inverse_.step(state, shifted), InverseStatus::ok);
  }

  //! Largest |y - y_off| the inverse operator takes as it is: a quarter of the largest double
  //! over sum_j |ph_j|, so that v = sum_j ph_j wh_j stays finite.
  double target_bound() const { return target_bound_; }

  //! solve() without the status, so the inverse also runs wherever a model does.
  double step(State& state, double target) const noexcept { return solve(state, target).input; }

 private:
  PrandtlIshlinskii forward_;
  std::vector<double> partial_sums_;  // S_j; declared before inverse_, which is built from it
  PrandtlIshlinskii inverse_;
  double target_bound_;
  Options options_;

  // The input within [v_min, v_max], with the status of the limit it hit; written so that NaN
  // cannot pass (it becomes v_min).
  InverseSample limited(double input, InverseStatus status) const noexcept {
    const bool ok = status == InverseStatus::ok;
    if (!(input >= options_.input_min))
      return {options_.input_min, ok ? InverseStatus::below_range : status};
    if (input > options_.input_max)
      return {options_.input_max, ok ? InverseStatus::above_range : status};
    return {input, status};
  }
};

}  // namespace hyst
