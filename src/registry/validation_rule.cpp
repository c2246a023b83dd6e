#include "hyst/registry/validation_rule.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
// These messages have their own form ("'x' is not known (a, b, c)"), which users match.
ValidationStart validation_start_from_string(std::string_view text) {
  if (const auto start = detail::find_named(text, enum_names<ValidationStart>)) return *start;
  throw Error(fmt::format("validation start '{}' is not known ({})", text,
                          detail::names_list(enum_names<ValidationStart>, ", ")),
              "validation_start");
}

ValidationAlignment validation_alignment_from_string(std::string_view text) {
  if (const auto align = detail::find_named(text, enum_names<ValidationAlignment>)) return *align;
  throw Error(fmt::format("validation align '{}' is not known ({})", text,
                          detail::names_list(enum_names<ValidationAlignment>, ", ")),
              "validation_align");
}

std::string describe(const ValidationRule& rule) {
  std::string_view start;
  switch (rule.start) {
    case ValidationStart::rest:
      start = "started from the model's initial state";
      break;
    case ValidationStart::periodic:
      start = "started from its own periodic steady state";
      break;
    case ValidationStart::continued:
      start = "continued from the end of the fit record";
      break;
  }
  const std::string_view align = rule.align == ValidationAlignment::first_sample
                                     ? "prediction shifted to the measured first sample"
                                     : "prediction compared as it is";
  return fmt::format("separate record, {} (validation start '{}'), {} (validation align '{}')",
                     start, to_string(rule.start), align, to_string(rule.align));
}

namespace {

// The checks of a validation record that both functions below make.
void check_record(std::span<const double> input, std::span<const double> output) {
  require_same_size(input.size(), "validation input", output.size(), "validation output");
  require_not_empty(input.size(), "validation input");
  require_finite(input, "validation input");
  require_finite(output, "validation output");
  const auto [lowest, highest] = std::minmax_element(output.begin(), output.end());
  if (!(*highest > *lowest)) {
    throw Error(fmt::format("the validation output is constant ({}): its range normalises the "
                            "validation NRMSE",
                            *lowest),
                "validation_output");
  }
}

// The prediction of `predictor` (a copy, in the state "continue" goes on from) for the record.
std::vector<double> predict_from(DynamicModel& predictor, std::span<const double> input,
                                 std::span<const double> output, const ValidationRule& rule) {
  std::vector<double> predicted(input.size());
  if (rule.start != ValidationStart::continued) predictor.reset();
  // One pass from rest leaves the state the record's own period returns to.
  if (rule.start == ValidationStart::periodic) predictor.simulate(input, predicted);
  predictor.simulate(input, predicted);
  if (rule.align == ValidationAlignment::first_sample) {
    const double shift = output.front() - predicted.front();
    for (double& value : predicted)
      value += shift;
  }
  return predicted;
}

}  // namespace

ErrorMetrics validate_on_record(const DynamicModel& model, std::span<const double> fit_input,
                                std::span<const double> validation_input,
                                std::span<const double> validation_output,
                                const ValidationRule& rule) {
  check_record(validation_input, validation_output);
  const auto predictor = model.clone();
  if (rule.start == ValidationStart::continued) {
    std::vector<double> fitted(fit_input.size());
    predictor->simulate(fit_input, fitted);
  }
  return error_metrics(validation_output,
                       predict_from(*predictor, validation_input, validation_output, rule));
}

ValidationRule saved_model_rule(std::string_view start, std::string_view align,
                                std::string_view tool) {
  ValidationRule rule;
  if (start == "file") {
    rule.start = ValidationStart::continued;
  } else if (start == "continue") {
    throw Error(fmt::format("validation start 'continue' needs the record the model was fitted "
                            "to; {} starts from 'rest', 'periodic' or 'file' (the state the "
                            "model file holds)",
                            tool),
                "validation_start");
  } else if (const auto named = detail::find_named(start, enum_names<ValidationStart>)) {
    rule.start = *named;
  } else {
    throw Error(fmt::format("validation start '{}' is not known (rest, periodic, file)", start),
                "validation_start");
  }
  rule.align = validation_alignment_from_string(align);
  return rule;
}

std::vector<double> predict_record(const DynamicModel& model, std::span<const double> input,
                                   std::span<const double> output, const ValidationRule& rule) {
  check_record(input, output);
  const auto predictor = model.clone();
  return predict_from(*predictor, input, output, rule);
}

}  // namespace hyst
