#pragma once
// One emitter per model family: the C code of a model (and its inverse) in its current state.
// Each reads the model's parameters and state in their model-file form and builds the concrete
// model with the library, so that every table (inverse weights, Everett table, ...) holds the
// library's own numbers.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "c_writer.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst::detail {

CModelCode emit_prandtl_ishlinskii_c(const DynamicModel& model, const CWriter& writer,
                                     const CExportOptions& options);
CModelCode emit_modified_prandtl_ishlinskii_c(const DynamicModel& model, const CWriter& writer,
                                              const CExportOptions& options);
CModelCode emit_generalized_prandtl_ishlinskii_c(const DynamicModel& model, const CWriter& writer,
                                                 const CExportOptions& options);
CModelCode emit_preisach_c(const DynamicModel& model, const CWriter& writer,
                           const CExportOptions& options);
CModelCode emit_bouc_wen_c(const DynamicModel& model, const CWriter& writer,
                           const CExportOptions& options);

//! The "play" array of a PI-family state in model-file form.
inline std::vector<double> play_of(const nlohmann::json& state) {
  return state.at("play").get<std::vector<double>>();
}

}  // namespace hyst::detail
