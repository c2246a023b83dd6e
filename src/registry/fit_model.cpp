// Fitting through the registry with the preparation of the measured record (hyst/data).

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

void add_steps(std::vector<std::string>& report, std::string_view prefix,
               const std::vector<std::string>& steps) {
  for (const auto& step : steps)
    report.push_back(fmt::format("{}{}", prefix, step));
}

}  // namespace

FitOutcome fit_model(const ModelEntry& entry, const FitRequest& request) {
  if (!entry.can_fit()) throw Error(fmt::format("model '{}' has no fitter", entry.name));
  if (!request.preprocessing.any()) return entry.fit(request);
  const auto prepared = data::preprocess(request.input, request.output, request.preprocessing);
  FitRequest prepared_request = request;
  prepared_request.input = prepared.input;
  prepared_request.output = prepared.output;

  // Drift is an artefact of the measurement, so a separate validation record loses its drift
  // too; the choice of cycles and the resampling concern the fit alone. A held-out fraction is
  // the end of the prepared record and so prepared with it.
  std::vector<std::string> steps;
  data::PreparedRecord validation;
  if (!request.validation_input.empty()) {
    validation = data::prepare_validation(request.validation_input, request.validation_output,
                                          request.preprocessing);
    prepared_request.validation_input = validation.input;
    prepared_request.validation_output = validation.output;
    add_steps(steps, "fit record: ", prepared.steps);
    add_steps(steps, "validation record: ", validation.steps);
  } else if (request.validate_fraction > 0.0) {
    add_steps(steps, "fit and held-out validation part: ", prepared.steps);
  } else {
    steps = prepared.steps;
  }
  auto outcome = entry.fit(prepared_request);
  outcome.report.preprocessing = std::move(steps);
  return outcome;
}

}  // namespace hyst
