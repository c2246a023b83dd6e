#pragma once
// One function per built-in model, each in its own <model>_entry.cpp.

#include "hyst/registry/model_registry.hpp"

namespace hyst::detail {

ModelEntry prandtl_ishlinskii_entry();
ModelEntry generalized_prandtl_ishlinskii_entry();
ModelEntry preisach_entry();
ModelEntry tabulated_preisach_entry();
ModelEntry ikuta_sma_entry();
ModelEntry krasnoselskii_pokrovskii_entry();
ModelEntry maxwell_slip_entry();
ModelEntry modified_prandtl_ishlinskii_entry();
ModelEntry rate_dependent_prandtl_ishlinskii_entry();
ModelEntry prandtl_ishlinskii_creep_entry();
ModelEntry modified_prandtl_ishlinskii_creep_entry();
ModelEntry butterfly_strain_entry();
ModelEntry butterfly_strain_creep_entry();
ModelEntry bouc_wen_entry();
ModelEntry bouc_wen_oscillator_entry();
ModelEntry duhem_entry();
ModelEntry backlash_like_entry();
ModelEntry jiles_atherton_entry();
ModelEntry narx_entry();

}  // namespace hyst::detail
