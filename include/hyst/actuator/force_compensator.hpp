#pragma once
//! \file
//! Inverse-model feedforward compensation of a hysteretic force: given a virtual current i_d
//! [A], it returns the coil current i_ref = H^-1[k_F i_d], so that the force H[i_ref] follows the
//! linear law k_F i_d. The desired force is limited to k_F [current_min, current_max] and the
//! current to [current_min, current_max] (the drive's range); the inverse starts in the state
//! consistent with the model's initial state.
//! Source: Minorowicz & Milecki (2022), Materials 15:4400, section 4.3 (IGPI in front of the
//! actuator); reference actuator_msma.md section 4.

#include <algorithm>

#include "hyst/actuator/hysteretic_force.hpp"

namespace hyst {

template <class H>
class InverseCompensator {
 public:
  using Model = H;
  using Inverse = typename ForceInverse<H>::type;
  struct Params {
    double force_gain = 1.0;   //!< k_F [N/A], > 0
    double current_min = 0.0;  //!< [A]
    double current_max = 1.0;  //!< [A], > current_min
  };
  struct State {
    typename Inverse::State inverse;
  };

  //! hyst::Error unless k_F > 0 and current_min < current_max (all finite).
  InverseCompensator(const H& model, const Params& params)
      : params_(validated(params)),
        inverse_(ForceInverse<H>::make(model, params.current_min, params.current_max)) {}

  const Params& params() const { return params_; }
  const Inverse& inverse() const { return inverse_; }
  State initial_state() const { return {inverse_.initial_state()}; }

  //! The current reference for the virtual current i_d. No allocation, never throws.
  double step(State& state, double virtual_current) const noexcept {
    const double force =
        params_.force_gain * std::clamp(virtual_current, params_.current_min, params_.current_max);
    return inverse_.step(state.inverse, force);
  }

 private:
  static Params validated(const Params& params);
  Params params_;
  Inverse inverse_;
};

//! The validation shared by every instantiation (force_compensator.cpp).
void validate_compensator_params(double force_gain, double current_min, double current_max);

template <class H>
typename InverseCompensator<H>::Params InverseCompensator<H>::validated(const Params& params) {
  validate_compensator_params(params.force_gain, params.current_min, params.current_max);
  return params;
}

}  // namespace hyst
