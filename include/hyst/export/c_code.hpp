#pragma once
//! \file
//! The options and the result of the C export (export_c.hpp). A registry entry whose model can be
//! exported provides its code with these types (ModelEntry::c_code).

#include <optional>
#include <string>
#include <vector>

#include "hyst/identify/fitted_domain.hpp"
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
  //! The domain the model was fitted on (a model file's info.domain): with it, the code also
  //! declares <prefix>_DOMAIN and <prefix>_check_input (and _check_target with an inverse), which
  //! count the samples beyond it as the library's checks do (fitted_domain.hpp).
  std::optional<FittedDomain> domain;
};

//! The unit of an exported parameter, in terms of the model's input and output units (an FMU names
//! them with the units the user gives).
enum class CUnit : unsigned char {
  none,              //!< dimensionless, or a unit the wrappers cannot name (see the description)
  input,             //!< [input units]
  output,            //!< [output units]
  output_per_input,  //!< [output units / input units]
  input_per_output,  //!< [input units / output units]
  seconds,           //!< [s]
};

//! What a wrapper that lets a user change an exported parameter (an FMU) checks before using it:
//! the rule of the library's own validation of that field, element by element. Every value must
//! also be finite, except where the rule says otherwise.
enum class CRule : unsigned char {
  finite,                 //!< any finite value
  increasing_from_zero,   //!< element 0 is 0, each later one > the one before (play thresholds)
  increasing,             //!< each element > the one before (levels, dead-zone thresholds)
  partial_sums_positive,  //!< element 0 > 0 and every partial sum > 0 (invertible weights)
  positive,               //!< > 0
  nonnegative,            //!< >= 0
  at_least_one,           //!< >= 1
  unit_interval,          //!< 0 <= value <= 1
  open_unit_interval,     //!< 0 < value < 1 (a lag's decay per sample)
  within_previous,  //!< previous + value > 0 and previous - value >= 0 (Bouc-Wen's gamma of beta)
  lower_limit,      //!< may be -inf, never NaN, <= the value of the next element (the upper limit)
  upper_limit,      //!< may be +inf, never NaN
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
  CRule rule = CRule::finite;
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
  //! The C function `void f(<prefix>_params *params, double sample_time)` that discretises the
  //! model's parameters at another sample time (the creep models: the lags' decays from their
  //! time constants), so that a host may step at its own rate; empty when the model's step holds
  //! at `sample_time` only (or at any spacing, for a rate-independent model). The inverse keeps
  //! the exported sample time.
  std::string set_sample_time;
  //! A C expression, true when the state `s` (a `const <prefix>_state *`) is one the step can
  //! take: finite values, a memory within its bounds. A wrapper checks a restored state with it.
  std::string state_check = "1";
  std::string inverse_state_check = "1";  //!< the same for `const <prefix>_inverse_state *s`
};

}  // namespace hyst
