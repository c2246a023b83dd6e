#pragma once
// One function per built-in model, each in its own <model>_entry.cpp.

#include <string>

#include "hyst/models/bouc_wen.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"
#include "hyst/models/ikuta_sma.hpp"
#include "hyst/models/krasnoselskii_pokrovskii.hpp"
#include "hyst/models/maxwell_slip.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/models/preisach.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst::detail {

ModelEntry prandtl_ishlinskii_entry();
ModelEntry generalized_prandtl_ishlinskii_entry();
ModelEntry preisach_entry();
ModelEntry ikuta_sma_entry();
ModelEntry krasnoselskii_pokrovskii_entry();
ModelEntry maxwell_slip_entry();
ModelEntry modified_prandtl_ishlinskii_entry();
ModelEntry rate_dependent_prandtl_ishlinskii_entry();
ModelEntry bouc_wen_entry();
ModelEntry bouc_wen_oscillator_entry();
ModelEntry duhem_entry();
ModelEntry backlash_like_entry();
ModelEntry jiles_atherton_entry();
ModelEntry narx_entry();

// The validated-by-shape parameters of a model file's "params" object (unknown fields rejected;
// messages name the path, e.g. "hysteresis.params.rho"), for code that builds the concrete model.
PrandtlIshlinskii::Params prandtl_ishlinskii_params_from_json(const nlohmann::json& params,
                                                              const std::string& path);
GpiParams generalized_prandtl_ishlinskii_params_from_json(const nlohmann::json& params,
                                                          const std::string& path);
Preisach::Params preisach_params_from_json(const nlohmann::json& params, const std::string& path);
ModifiedPrandtlIshlinskii::Params modified_prandtl_ishlinskii_params_from_json(
    const nlohmann::json& params, const std::string& path);
KrasnoselskiiPokrovskii::Params krasnoselskii_pokrovskii_params_from_json(
    const nlohmann::json& params, const std::string& path);
MaxwellSlip::Params maxwell_slip_params_from_json(const nlohmann::json& params,
                                                  const std::string& path);
IkutaSma::Params ikuta_sma_params_from_json(const nlohmann::json& params, const std::string& path);
BoucWen::Params bouc_wen_params_from_json(const nlohmann::json& params, const std::string& path);
// The model-file name of a modified PI model's field: "pi.weights[2]" -> "weights[2]",
// "pi.offset" -> "pi_offset", "dead_zone.weights" -> "dead_zone_weights".
std::string modified_prandtl_ishlinskii_file_field(const std::string& field);

}  // namespace hyst::detail
