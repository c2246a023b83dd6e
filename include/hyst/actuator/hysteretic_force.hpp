#pragma once
//! \file
//! The hysteretic force F = H[i] of an actuator: any hysteresis model of the library, and its
//! inverse for feedforward compensation.
//!
//! - Compile time: Actuator<H> and InverseCompensator<H> are templates on the model type (the
//!   generalized Prandtl-Ishlinskii model with tanh envelopes by default).
//! - Run time (files, command line, Python): AnyHysteresis, a std::variant over the library's
//!   models, chosen by the model-file name ("gpi", "pi", "preisach"). Code that runs a loop
//!   visits the variant once and runs the whole loop inside the visit, so no sample pays for a
//!   virtual call or a variant dispatch.
//!
//! The inverse of each model (InverseModel<H>): IGPI for GPI (analytic), the inverse PI for PI
//! (analytic), the bracketed numerical inverse for Preisach.

#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "hyst/inverse/inverse_generalized_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_preisach.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/models/preisach.hpp"

namespace hyst {

//! Every hysteresis model an actuator's force can follow, chosen at run time.
using AnyHysteresis =
    std::variant<GeneralizedPrandtlIshlinskii<TanhEnvelope>,
                 GeneralizedPrandtlIshlinskii<ArctanEnvelope>,
                 GeneralizedPrandtlIshlinskii<LinearEnvelope>, PrandtlIshlinskii, Preisach>;

//! The inverse of model type H, built with input (current) limits.
template <class H>
struct InverseModel;

template <Envelope E>
struct InverseModel<GeneralizedPrandtlIshlinskii<E>> {
  using type = InverseGeneralizedPrandtlIshlinskii<E>;
  static type make(const GeneralizedPrandtlIshlinskii<E>& model, double input_min,
                   double input_max) {
    return type(model, {input_min, input_max});
  }
};

template <>
struct InverseModel<PrandtlIshlinskii> {
  using type = InversePrandtlIshlinskii;
  static type make(const PrandtlIshlinskii& model, double input_min, double input_max) {
    return type(model, {input_min, input_max});
  }
};

template <>
struct InverseModel<Preisach> {
  using type = InversePreisach;
  static type make(const Preisach& model, double input_min, double input_max) {
    InversePreisachOptions options;
    options.input_min = input_min;
    options.input_max = input_max;
    return type(model, options);
  }
};

//! The registry name of the model held: "gpi", "pi" or "preisach".
std::string_view hysteresis_name(const AnyHysteresis& model);

//! A model from {"model": "<name>", "params": {...}} (the model-file form without state);
//! `path` prefixes error messages ("actuator.json: hysteresis.params.rho: ...").
AnyHysteresis hysteresis_from_json(const nlohmann::json& document, const std::string& path);

}  // namespace hyst
