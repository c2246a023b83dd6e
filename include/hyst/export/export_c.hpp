#pragma once
//! \file
//! Export of a model (and its inverse, where the library has one) as dependency-free C99 code for
//! a real-time controller: one header and one source file.
//!
//! The generated code has no heap, no libc beyond <math.h>, no recursion, only loops with a bound
//! fixed at export time, and `const` tables. For a prefix P it declares
//!
//!     typedef double P_real;                      (float with CScalar::single_precision)
//!     P_params, P_state, const P_params P_PARAMS  the fitted values
//!     void   P_init(P_state*)                     the state stored in the model file
//!     void   P_reset(P_state*)                    the model's default initial state
//!     P_real P_step(const P_params*, P_state*, P_real input)
//!     P_inverse_params, P_inverse_state, P_INVERSE_PARAMS, P_inverse_init/_reset/_step
//!                                                 when the model has an inverse
//!
//! Supported models (registry names; the entries that provide ModelEntry::c_code): "pi" (+ inverse
//! PI), "gpi" (+ inverse GPI), "modified_pi"
//! (+ its analytic inverse), "preisach" (Everett table form + the numerical inverse by bracketed
//! search), "bouc_wen" (the library's exact n = 1 solution, or RK4 with its fixed step rule; no
//! inverse). In double precision the generated step reproduces the library's step to rounding
//! (same operations in the same order, tables computed by the library at export time; the weighted
//! sums are sequential where the library's are vectorised): tests/export/test_export_c.cpp checks
//! 1e-12 of the output scale. In single precision every operation is done in float; the same test
//! bounds the difference from the double library by 2e-5 of the output scale for the PI family,
//! the GPI and Bouc-Wen, and by one relay weight for the Preisach model (an input within float
//! rounding of a threshold level may switch a relay). The Preisach memory has the library's
//! capacity (PreisachState::max_pairs pairs) and the same overflow rule (the innermost pair is
//! dropped and counted). Bouc-Wen with n != 1 and tolerance > 0 (adaptive integration) is
//! refused: set tolerance = 0 for the fixed-step RK4 rule, which is exported.
//! Sources: the model headers named in the generated files.

#include <filesystem>
#include <string>
#include <string_view>

#include "hyst/export/c_code.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst {

//! Whether `name` is a C identifier: a letter or '_', then letters, digits and '_'.
bool is_c_identifier(std::string_view name);

//! The prefix of the export's names and files: options.prefix, or "hyst_" + the model's name.
//! Throws hyst::Error (field "prefix") when it is not a C identifier.
std::string c_export_prefix(const DynamicModel& model, const CExportOptions& options);

//! Generates the C code of `model` in its current state. Throws hyst::Error naming the model for
//! an unsupported model ("C export: the model 'kp' is not supported (supported: ...)") and for a
//! bad prefix (field "prefix").
CCode generate_c(const DynamicModel& model, const CExportOptions& options);

//! Writes the two files of `code` into `folder` (created when missing; hyst::Error naming it
//! when it cannot be) together, as io::write_files_atomically() does. The header defines
//! <PREFIX>_EXPORT_STAMP, a digest of both files' text, and the source refuses to compile
//! (#error) with a header of another export, so that a mixed pair cannot be built silently.
void write_c(const CCode& code, const std::filesystem::path& folder);

//! generate_c(), then write_c(). Returns what was written.
CCode export_c(const DynamicModel& model, const std::filesystem::path& folder,
               const CExportOptions& options);

}  // namespace hyst
