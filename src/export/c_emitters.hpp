#pragma once
// One emitter per model family: the C code of a concrete model (and its inverse) in a given state.
// Each builds its tables (inverse weights, Everett table, ...) with the library, so that they hold
// the library's own numbers. The registry entries call them (registry/c_code_capability.hpp), one
// overload per model type.

#include "c_writer.hpp"
#include "hyst/identify/fitted_domain.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "hyst/models/modified_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"
#include "hyst/models/preisach.hpp"

namespace hyst::detail {

CModelCode emit_c(const PrandtlIshlinskii& model, const PrandtlIshlinskii::State& state,
                  const CWriter& writer, const CExportOptions& options);
CModelCode emit_c(const PrandtlIshlinskiiCreep& model, const PrandtlIshlinskiiCreep::State& state,
                  const CWriter& writer, const CExportOptions& options);
CModelCode emit_c(const ModifiedPrandtlIshlinskiiCreep& model,
                  const ModifiedPrandtlIshlinskiiCreep::State& state, const CWriter& writer,
                  const CExportOptions& options);
CModelCode emit_c(const ModifiedPrandtlIshlinskii& model,
                  const ModifiedPrandtlIshlinskii::State& state, const CWriter& writer,
                  const CExportOptions& options);
template <Envelope E>
CModelCode emit_c(const GeneralizedPrandtlIshlinskii<E>& model,
                  const typename GeneralizedPrandtlIshlinskii<E>::State& state,
                  const CWriter& writer, const CExportOptions& options);
CModelCode emit_c(const Preisach& model, const PreisachState& state, const CWriter& writer,
                  const CExportOptions& options);
CModelCode emit_c(const BoucWen& model, const BoucWen::State& state, const CWriter& writer,
                  const CExportOptions& options);

//! Adds the fitted domain to `code` (CExportOptions::domain): <prefix>_DOMAIN, the status type
//! and <prefix>_check_input, and <prefix>_check_target when the code has an inverse.
void add_c_domain(const CWriter& writer, const FittedDomain& domain, CModelCode& code);

}  // namespace hyst::detail
