#include "hyst/registry/validation_rule.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

std::string_view to_string(ValidationStart start) {
  switch (start) {
    case ValidationStart::rest:
      return "rest";
    case ValidationStart::periodic:
      return "periodic";
    case ValidationStart::continued:
      return "continue";
  }
  return "rest";
}

std::string_view to_string(ValidationAlignment align) {
  return align == ValidationAlignment::first_sample ? "first-sample" : "none";
}

ValidationStart validation_start_from_string(std::string_view text) {
  for (const auto start :
       {ValidationStart::rest, ValidationStart::periodic, ValidationStart::continued}) {
    if (text == to_string(start)) return start;
  }
  throw Error(fmt::format("validation start '{}' is not known (rest, periodic, continue)", text),
              "validation_start");
}

ValidationAlignment validation_alignment_from_string(std::string_view text) {
  for (const auto align : {ValidationAlignment::none, ValidationAlignment::first_sample}) {
    if (text == to_string(align)) return align;
  }
  throw Error(fmt::format("validation align '{}' is not known (none, first-sample)", text),
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

ErrorMetrics validate_on_record(const DynamicModel& model, std::span<const double> fit_input,
                                std::span<const double> validation_input,
                                std::span<const double> validation_output,
                                const ValidationRule& rule) {
  require_same_size(validation_input.size(), "validation input", validation_output.size(),
                    "validation output");
  require_not_empty(validation_input.size(), "validation input");
  require_finite(validation_input, "validation input");
  require_finite(validation_output, "validation output");
  const auto [lowest, highest] =
      std::minmax_element(validation_output.begin(), validation_output.end());
  if (!(*highest > *lowest)) {
    throw Error(fmt::format("the validation output is constant ({}): its range normalises the "
                            "validation NRMSE",
                            *lowest),
                "validation_output");
  }
  const auto predictor = model.clone();
  std::vector<double> predicted(validation_input.size());
  switch (rule.start) {
    case ValidationStart::rest:
      predictor->reset();
      break;
    case ValidationStart::periodic:
      // One pass from rest leaves the state the record's own period returns to.
      predictor->reset();
      predictor->simulate(validation_input, predicted);
      break;
    case ValidationStart::continued: {
      std::vector<double> fitted(fit_input.size());
      predictor->simulate(fit_input, fitted);
      break;
    }
  }
  predictor->simulate(validation_input, predicted);
  if (rule.align == ValidationAlignment::first_sample) {
    const double shift = validation_output.front() - predicted.front();
    for (double& value : predicted)
      value += shift;
  }
  return error_metrics(validation_output, predicted);
}

}  // namespace hyst
