#pragma once
//! \file
//! The hysteretic force F = H[i] of an actuator: any hysteresis model of the library, and its
//! inverse for feedforward compensation.
//!
//! - Compile time: Actuator<H> and InverseCompensator<H> are templates on the model type (the
//!   generalized Prandtl-Ishlinskii model with tanh envelopes by default).
//! - Run time (files, command line, Python): AnyHysteresis (registry/actuator_force.hpp), a
//!   std::variant over the models whose registry entry can be a force (ModelEntry::actuator_force:
//!   "gpi", "pi", "preisach", "modified_pi", "kp", "maxwell_slip", "ikuta_sma", "bouc_wen"). A
//!   model is read by its entry's create() and handed over by the entry as its concrete model.
//!   Code that runs a loop visits the variant once and runs the whole loop inside the visit, so no
//!   sample pays for a virtual call or a variant dispatch.
//!
//! The inverse of each model (ForceInverse<H>): analytic where the model has one - IGPI for GPI,
//! the inverse PI for PI and for Maxwell-slip (a stop-type PI model, invertible iff
//! linear_stiffness > 0, or > sum k_i for counter-clockwise loops), Kuhnen's inverse for the
//! modified PI - and otherwise the bracketed numerical inverse: InversePreisach for Preisach,
//! NumericalInverse<H> for every other model (KP, Ikuta SMA, Bouc-Wen), which needs a monotone
//! one-step map and a preview() or a trivially copyable state (numerical_inverse.hpp). Adding a
//! force model (docs/architecture.md): its type in AnyHysteresis and `actuator_force` in its
//! registry entry; a ForceInverse specialisation only for an analytic inverse.
//!
//! Not a force model: the rate-dependent PI ("rate_dependent_pi"). Its output depends on the
//! input rate (through the sample time of the model, not of the actuator) and hyst provides no
//! inverse for it, so hysteresis_from_json() rejects it with a message saying so. Nor is the
//! Bouc-Wen oscillator ("bouc_wen_oscillator"), a whole mass-spring system of its own.

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "hyst/core/error.hpp"
#include "hyst/inverse/inverse_generalized_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_preisach.hpp"
#include "hyst/inverse/numerical_inverse.hpp"
#include "hyst/registry/actuator_force.hpp"

namespace hyst {

//! The inverse of model type H, built with input (current) limits: by default the numerical
//! inverse; specialised below for the models with an analytic or their own inverse.
template <class H>
struct ForceInverse {
  using type = NumericalInverse<H>;
  static type make(const H& model, double input_min, double input_max) {
    NumericalInverseOptions options;
    options.input_min = input_min;
    options.input_max = input_max;
    return type(model, options);
  }
};

//! An analytic inverse whose options are the input limits {v_min, v_max}.
template <class Inverse>
struct LimitedInverse {
  using type = Inverse;
  template <class H>
  static type make(const H& model, double input_min, double input_max) {
    return type(model, {input_min, input_max});
  }
};

template <Envelope E>
struct ForceInverse<GeneralizedPrandtlIshlinskii<E>>
    : LimitedInverse<InverseGeneralizedPrandtlIshlinskii<E>> {};

template <>
struct ForceInverse<PrandtlIshlinskii> : LimitedInverse<InversePrandtlIshlinskii> {};

template <>
struct ForceInverse<ModifiedPrandtlIshlinskii> : LimitedInverse<InverseModifiedPrandtlIshlinskii> {
};

template <>
struct ForceInverse<Preisach> {
  using type = InversePreisach;
  static type make(const Preisach& model, double input_min, double input_max) {
    InversePreisachOptions options;
    options.input_min = input_min;
    options.input_max = input_max;
    return type(model, options);
  }
};

//! Maxwell-slip = a PI model (maxwell_slip.hpp) whose initial play state (all 0) matches the
//! relaxed springs at x = 0, so the PI inverse starts consistent with the forward model.
template <>
struct ForceInverse<MaxwellSlip> {
  using type = InversePrandtlIshlinskii;
  //! Throws hyst::Error unless the slope after a reversal is > 0 (maxwell_slip.hpp): without it
  //! the force saturates or falls and has no inverse.
  static type make(const MaxwellSlip& model, double input_min, double input_max) {
    require_invertible(model);
    return type(model.to_prandtl_ishlinskii(), {input_min, input_max});
  }
  static void require_invertible(const MaxwellSlip& model) {
    if (!model.is_invertible()) {
      throw Error(
          "a Maxwell-slip force needs linear_stiffness > 0 to be invertible (counter-clockwise: "
          "linear_stiffness > the sum of stiffness)",
          "linear_stiffness");
    }
  }
};

//! The registry name of the model held: the entry whose actuator_force takes its alternative.
std::string_view hysteresis_name(const AnyHysteresis& model);

//! The names hysteresis_from_json() accepts, comma separated: the entries with an actuator_force,
//! in the order of their alternatives in AnyHysteresis.
std::string hysteresis_names();

//! A model from {"model": "<name>", "params": {...}} (the model-file form without state), made by
//! the entry's create() and handed over by its actuator_force;
//! `path` prefixes error messages ("actuator.json: hysteresis.params.rho: ..."). A model that
//! cannot be inverted (Maxwell-slip without linear stiffness, a non-invertible modified PI) and
//! the rate-dependent PI are rejected with a message saying why.
AnyHysteresis hysteresis_from_json(const nlohmann::json& document, const std::string& path);

}  // namespace hyst
