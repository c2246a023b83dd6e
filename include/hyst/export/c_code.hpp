#pragma once
//! \file
//! The options and the result of the C export (export_c.hpp). A registry entry whose model can be
//! exported provides its code with these types (ModelEntry::c_code).

#include <string>

#include "hyst/registry/dynamic_model.hpp"

namespace hyst {

//! The C scalar type of the generated code.
enum class CScalar : unsigned char { double_precision, single_precision };

struct CExportOptions {
  //! Prefix of every C identifier and of the file names; empty = "hyst_" + model name. Must be a
  //! C identifier (letters, digits, '_', not starting with a digit).
  std::string prefix;
  CScalar scalar = CScalar::double_precision;
  //! The inverse's admissible input range (as for `hyst invert`).
  InverseLimits limits{};
  //! The file the model came from, named in the generated comments (may be empty).
  std::string source;
};

//! The generated code, in memory.
struct CCode {
  std::string header_name;  //!< "<prefix>.h"
  std::string header;
  std::string source_name;  //!< "<prefix>.c"
  std::string source;
  bool has_inverse = false;  //!< the _inverse_ functions exist
};

}  // namespace hyst
