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
