#pragma once
// The common part of the C export: number and table formatting for the chosen scalar type,
// the substitution of the marks in C templates, the file preamble and the atomic write.

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hyst/export/c_code.hpp"

namespace hyst::detail {

//! What a model family's emitter produces: the declarations for the header and the definitions
//! for the source file, both as C templates (see CWriter::expand()).
struct CModelCode {
  std::string title;        //!< one line naming the model, e.g. "Prandtl-Ishlinskii model (pi)"
  std::string description;  //!< a few comment lines: equations, scheme, sizes
  std::string header;       //!< types, sizes and prototypes
  std::string source;       //!< tables and functions
  bool has_inverse = false;
  std::vector<CParameterField> parameters;          //!< see CCode::parameters
  std::vector<CParameterField> inverse_parameters;  //!< see CCode::inverse_parameters
  double sample_time = 0.0;                         //!< see CCode::sample_time
  bool resamplable = false;                         //!< see CCode::set_sample_time
  std::string state_check = "1";                    //!< see CCode::state_check
  std::string inverse_state_check = "1";            //!< see CCode::inverse_state_check
};

//! A scalar or an array field of an exported parameter struct, for CModelCode::parameters.
CParameterField c_scalar(std::string name, double value, CUnit unit, std::string description,
                         CRule rule = CRule::finite);
CParameterField c_array(std::string name, std::span<const double> values, CUnit unit,
                        std::string description, CRule rule = CRule::finite);

//! FNV-1a, 64 bits: a stable digest of exported text (identical exports, identical stamp).
std::uint64_t text_digest(std::initializer_list<std::string_view> parts);

//! Formats C text for one prefix and scalar type.
class CWriter {
 public:
  CWriter(std::string prefix, CScalar scalar) : prefix_(std::move(prefix)), scalar_(scalar) {}

  const std::string& prefix() const { return prefix_; }
  bool single() const { return scalar_ == CScalar::single_precision; }

  //! A C literal of the scalar type: "%.17g" in double, the value rounded to float as "%.9g" with
  //! an 'f' suffix in float (both read back exactly); +-inf as (-)HUGE_VAL(F).
  std::string number(double value) const;
  //! "{a, b, c}" with line breaks every few numbers.
  std::string table(std::span<const double> values) const;

  //! Substitutes the marks of a C template: '@' by the prefix, "$name" (a math.h function,
  //! e.g. $exp) by name or namef, and "#(x)" (a literal) by x or xf.
  std::string expand(std::string_view text) const;

  //! Replaces every "%NAME%" of `text` by its value (table or number text of the emitter).
  static std::string fill(std::string_view text,
                          std::initializer_list<std::pair<std::string_view, std::string>> values);

 private:
  std::string prefix_;
  CScalar scalar_;
};

//! The C template of the functions the PI family shares (one play step, a play-and-sum step over
//! n operators, the input clamp of the inverses); included once in a source file.
std::string_view c_play_functions();

//! The C template of what every inverse does with its target and its answer: @_bounded_target()
//! takes a target beyond +-@_TARGET_LIMIT (+-inf, or finite values so large that the inverse's sums
//! would overflow to inf - inf = NaN) as that limit, so that it gives the extreme input in its
//! direction; @_clamp() limits an input to [input_min, input_max] so that NaN cannot pass (it
//! gives input_min). `gain` bounds how much the inverse multiplies its target by (the product of
//! max(1, sum |w|) over its weighted sums, c_gain()): the limit is a quarter of the largest number
//! of the scalar type over it, the bound the library's inverse PI puts on its target. A NaN target
//! is each inverse's own business: it holds the last input.
std::string c_inverse_target_functions(const CWriter& writer, double gain);
//! max(1, sum |w_j|): the most a weighted sum with the weights `w` multiplies its values by.
double c_gain(std::span<const double> weights);

//! The C template of the dead-zone superposition S(x) = sum_i g_i S_{d_i}(x) over @_DEAD_ZONES
//! zones, as the library's DeadZoneSuperposition; included once in a source file.
std::string_view c_dead_zone_function();
//! C statements that clamp `output` to [output_min, output_max]; none for an infinite limit.
std::string c_output_limits(const CWriter& writer, double output_min, double output_max);

//! The declarations every model shares, after its @_params and @_state types: the fitted
//! parameters, init (the model file's state), reset (`reset_note`: the default initial state) and
//! step (`step_note`: what one sample does).
std::string c_model_declarations(std::string_view reset_note, std::string_view step_note);
//! The same for an inverse, after its @_inverse_params and @_inverse_state types.
std::string c_inverse_declarations(std::string_view step_note);

//! The complete header and source for a model's code, with the preamble that names the model, the
//! file it came from and the scalar type.
CCode assemble_c_files(const CWriter& writer, const CModelCode& code, std::string_view source_file);

}  // namespace hyst::detail
