#pragma once
// The parts of an FMU (export_fmu.hpp): the FMI 2.0 declarations, the C wrapper around the C
// export, the model description, the compiled binary and the zip archive that holds them.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hyst/export/c_code.hpp"

namespace hyst::detail {

//! One FMU, the model's or its inverse's, as its wrapper and its model description see it.
struct FmuUnit {
  std::string identifier;  //!< modelIdentifier: the binary's name, a C identifier
  std::string guid;        //!< "{8-4-4-4-12 hex digits}", a digest of the export
  std::uint64_t digest = 0;
  const CCode* code = nullptr;  //!< the C export both FMUs are built from
  std::string c_prefix;         //!< its prefix
  bool inverse = false;         //!< wraps <prefix>_inverse_step
  std::string input_name;
  std::string output_name;
  std::string model_input_unit;  //!< the model's units (CUnit is relative to them); may be empty
  std::string model_output_unit;
  std::string model_name;  //!< registry name, e.g. "pi"
  std::string source;      //!< the model file's name, or empty
  bool single = false;     //!< float code

  const std::vector<CParameterField>& parameters() const {
    return inverse ? code->inverse_parameters : code->parameters;
  }
  //! The unit of an FMU variable of the model's `unit`, or "" when it has none.
  std::string unit_name(CUnit unit) const;
  //! The FMU's input and output units.
  std::string input_unit() const { return inverse ? model_output_unit : model_input_unit; }
  std::string output_unit() const { return inverse ? model_input_unit : model_output_unit; }
  //! The step follows the host's communication step: a model (not an inverse) whose C export
  //! can be discretised at another sample time (CCode::set_sample_time), or one without any.
  bool variable_step() const {
    return code->sample_time == 0.0 || (!inverse && !code->set_sample_time.empty());
  }
  //! The wrapper's file name, "<identifier>_fmi2.c".
  std::string wrapper_name() const { return identifier + "_fmi2.c"; }
};

//! The FMU's name of element `k` of a parameter field: "thresholds[3]" (counted from 1) for an
//! array, the field's name for a scalar.
std::string fmu_variable_name(const CParameterField& field, std::size_t k);

//! The FMI 2.0 types and co-simulation functions, declared from the standard's text.
inline constexpr std::string_view kFmi2DeclarationsName = "fmi2_declarations.h";
std::string_view fmi2_declarations();

//! The C source that implements the FMI 2.0 co-simulation interface of `unit` on its C export.
std::string fmu_wrapper(const FmuUnit& unit);

//! modelDescription.xml of `unit`.
std::string fmu_model_description(const FmuUnit& unit);

//! One source file for compile_shared_library().
struct SourceFile {
  std::string name;
  std::string_view text;
};

//! Compiles `sources` (the .c files among them) into a shared library with `compiler` (empty:
//! $CC, else "cc"); returns its bytes. Throws hyst::Error with the compiler's messages.
std::string compile_shared_library(const std::string& compiler,
                                   std::span<const SourceFile> sources);

//! One member of zip_archive().
struct ArchiveMember {
  std::string name;  //!< path inside the archive, '/'-separated
  std::string_view bytes;
};

//! A deflated zip archive of `members`, in memory, with a fixed modification time so that the
//! same members give the same bytes.
std::string zip_archive(std::span<const ArchiveMember> members);

}  // namespace hyst::detail
