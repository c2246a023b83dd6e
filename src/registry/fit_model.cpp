// Fitting through the registry with the preparation of the measured record (hyst/data).

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/registry/validation_rule.hpp"

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
  data::PreparedRecord prepared{{request.input.begin(), request.input.end()},
                                {request.output.begin(), request.output.end()},
                                {}};
  if (request.preprocessing.any()) {
    prepared = data::preprocess(request.input, request.output, request.preprocessing);
  }
  // The fitter sees the fit record alone (with its held-out fraction); a separate validation
  // record is predicted here, by the one rule every model follows (validation_rule.hpp).
  FitRequest fit_request = request;
  fit_request.input = prepared.input;
  fit_request.output = prepared.output;
  fit_request.validation_input = {};
  fit_request.validation_output = {};

  // Drift is an artefact of the measurement, so a separate validation record loses its drift
  // too; the choice of cycles and the resampling concern the fit alone. A held-out fraction is
  // the end of the prepared record and so prepared with it.
  std::vector<std::string> steps;
  data::PreparedRecord validation{
      {request.validation_input.begin(), request.validation_input.end()},
      {request.validation_output.begin(), request.validation_output.end()},
      {}};
  const bool separate_record = !request.validation_input.empty();
  if (separate_record && request.preprocessing.any()) {
    validation = data::prepare_validation(request.validation_input, request.validation_output,
                                          request.preprocessing);
    add_steps(steps, "fit record: ", prepared.steps);
    add_steps(steps, "validation record: ", validation.steps);
  } else if (request.validate_fraction > 0.0) {
    add_steps(steps, "fit and held-out validation part: ", prepared.steps);
  } else {
    steps = prepared.steps;
  }
  auto outcome = entry.fit(fit_request);
  outcome.report.preprocessing = std::move(steps);
  if (separate_record) {
    outcome.report.validation = validate_on_record(*outcome.model, prepared.input, validation.input,
                                                   validation.output, request.validation);
    outcome.report.validation_rule = describe(request.validation);
  } else if (request.validate_fraction > 0.0) {
    outcome.report.validation_rule =
        fmt::format("the last {:.4g} % of the record, continued from the end of the fit part",
                    100.0 * request.validate_fraction);
  }
  return outcome;
}

}  // namespace hyst
