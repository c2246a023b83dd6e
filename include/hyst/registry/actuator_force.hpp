#pragma once
//! \file
//! The models an actuator's hysteretic force can follow (AnyHysteresis), and the capability by
//! which a registry entry provides one: its concrete model as an alternative of the variant.
//! The actuator (hysteretic_force.hpp) takes its list of force models from the entries that have
//! this capability, reads a force model with the entry's create() and compensates it with
//! InverseModel<H>.
//!
//! The variant is the one compile-time list of force model types: a loop visits it once per run
//! (or per sample through std::visit), so no sample pays for a virtual call. Its order is the
//! order in which the actuator lists the force models.

#include <cstddef>
#include <functional>
#include <type_traits>
#include <variant>
#include <vector>

#include "hyst/models/bouc_wen.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"
#include "hyst/models/ikuta_sma.hpp"
#include "hyst/models/krasnoselskii_pokrovskii.hpp"
#include "hyst/models/maxwell_slip.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/models/preisach.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst {

//! Every hysteresis model an actuator's force can follow, chosen at run time.
using AnyHysteresis = std::variant<
    GeneralizedPrandtlIshlinskii<TanhEnvelope>, GeneralizedPrandtlIshlinskii<ArctanEnvelope>,
    GeneralizedPrandtlIshlinskii<LinearEnvelope>, PrandtlIshlinskii, Preisach,
    ModifiedPrandtlIshlinskii, KrasnoselskiiPokrovskii, MaxwellSlip, IkutaSma, BoucWen>;

//! The position of model type H among the alternatives of AnyHysteresis.
template <class H>
constexpr std::size_t hysteresis_index = []<class... Models>(std::variant<Models...>*) {
  static_assert((std::is_same_v<H, Models> || ...), "not an alternative of AnyHysteresis");
  std::size_t index = 0;
  (void)((std::is_same_v<H, Models> ? true : (++index, false)) || ...);
  return index;
}(static_cast<AnyHysteresis*>(nullptr));

//! A registry entry's model as an actuator force (ModelEntry::actuator_force).
struct ActuatorForce {
  //! The concrete model of a DynamicModel made by the entry's create(); hyst::Error for a model
  //! of another entry.
  std::function<AnyHysteresis(const DynamicModel&)> hysteresis;
  //! The alternatives of AnyHysteresis the entry's models take (hysteresis_index; the GPI has one
  //! per envelope), so that a held model names its entry.
  std::vector<std::size_t> alternatives;
};

}  // namespace hyst
