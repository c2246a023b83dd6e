#pragma once
//! \file
//! The one rule by which a fitted model is checked on a separate held-out record (another
//! amplitude, another measurement): the state the prediction starts from and how its level is
//! compared. fit_model() applies it to every model, so that the CLI (`hyst fit --validation-start
//! --validation-align`), Python (`hyst.fit(validation_start=, validation_align=)`) and the library
//! give the same numbers, and the report states the rule. A held-out fraction of the fit record
//! is different: it follows the fit part in time and always continues from its end.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hyst/core/enum_names.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst {

//! Where the prediction of a separate validation record starts.
enum class ValidationStart {
  rest,       //!< "rest": the model's default initial state (`hyst models NAME` names it)
  periodic,   //!< "periodic": the record's own periodic steady state (the record is one period
              //!< or a whole number of periods: the state after running it once from rest)
  continued,  //!< "continue": where the fit record ended (the record follows it in time)
};

//! How the predicted level is compared with the measured one.
enum class ValidationAlignment {
  none,          //!< "none": as predicted
  first_sample,  //!< "first-sample": shifted to the measured first sample (records zeroed
                 //!< separately, as many instruments do, carry no common level)
};

struct ValidationRule {
  ValidationStart start = ValidationStart::rest;
  ValidationAlignment align = ValidationAlignment::none;
};

constexpr EnumNames<ValidationStart, 3> enumerator_names(ValidationStart) {
  return {{
      {ValidationStart::rest, "rest"},
      {ValidationStart::periodic, "periodic"},
      {ValidationStart::continued, "continue"},
  }};
}
constexpr EnumNames<ValidationAlignment, 2> enumerator_names(ValidationAlignment) {
  return {{
      {ValidationAlignment::none, "none"},
      {ValidationAlignment::first_sample, "first-sample"},
  }};
}
//! The inverse of to_string(); hyst::Error naming the text and the known names otherwise.
ValidationStart validation_start_from_string(std::string_view text);
ValidationAlignment validation_alignment_from_string(std::string_view text);

//! The rule in words for reports, e.g. "separate record, started from its own periodic steady
//! state (validation start 'periodic'), prediction shifted to the measured first sample
//! (validation align 'first-sample')".
std::string describe(const ValidationRule& rule);

//! The error of `model` on the validation record under `rule`. `model` is in the state the fit
//! started from and `fit_input` is the record it was fitted to (for "continue"); the model
//! itself is not changed. hyst::Error for mismatched or empty records.
ErrorMetrics validate_on_record(const DynamicModel& model, std::span<const double> fit_input,
                                std::span<const double> validation_input,
                                std::span<const double> validation_output,
                                const ValidationRule& rule);

//! The rule for a saved model from its names: start "rest", "periodic" or "file" (the state the
//! model file holds, which predict_record() continues from); "continue" needs the fit record,
//! which a model file does not carry, and is refused with a message saying so, as is any other
//! name. `tool` names the command in that message ("'hyst evaluate'").
ValidationRule saved_model_rule(std::string_view start, std::string_view align,
                                std::string_view tool);

//! The prediction of a saved model for a record under `rule`, as validate_on_record() scores
//! it: "continue" goes on from the model's own state (a model file's state is where its fit
//! ended), "rest" and "periodic" start as above. The model itself is not changed. hyst::Error for
//! mismatched, empty or non-finite records and a constant output.
std::vector<double> predict_record(const DynamicModel& model, std::span<const double> input,
                                   std::span<const double> output, const ValidationRule& rule);

}  // namespace hyst
