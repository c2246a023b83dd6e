#pragma once
//! \file
//! The options and the result of the C export (export_c.hpp). A registry entry whose model can be
//! exported provides its code with these types (ModelEntry::c_code).

#include <string>
#include <vector>

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

//! The unit of an exported parameter, in terms of the model's input and output units (an FMU names
//! them with the units the user gives).
enum class CUnit : unsigned char {
  none,              //!< dimensionless, or a unit the wrappers cannot name (see the description)
  input,             //!< [input units]
  output,            //!< [output units]
  output_per_input,  //!< [output units / input units]
  input_per_output,  //!< [input units / output units]
};

//! One field of the exported parameter struct (<prefix>_params or <prefix>_inverse_params) that a
//! wrapper may expose for tuning (an FMU's parameters): a real scalar or an array of reals. Fields
//! derived from others (tables a step needs to be fast) and integer fields are not listed.
struct CParameterField {
  std::string name;            //!< the struct field, a C identifier
  std::vector<double> values;  //!< as exported (one for a scalar)
  bool array = false;          //!< declared as an array (even with one element)
  CUnit unit = CUnit::none;
  std::string description;  //!< one line, e.g. "play thresholds r_j"
};

//! The generated code, in memory.
struct CCode {
  std::string header_name;  //!< "<prefix>.h"
  std::string header;
  std::string source_name;  //!< "<prefix>.c"
  std::string source;
  bool has_inverse = false;  //!< the _inverse_ functions exist
  //! The fields of <prefix>_params and of <prefix>_inverse_params a wrapper may expose.
  std::vector<CParameterField> parameters;
  std::vector<CParameterField> inverse_parameters;
  //! The sample time [s] a step assumes (the creep models' lags); 0 for a rate-independent model,
  //! whose step may follow any sample spacing.
  double sample_time = 0.0;
};

}  // namespace hyst
