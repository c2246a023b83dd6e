// Fitting through the registry with the preparation of the measured record (hyst/data).

#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {

FitOutcome fit_model(const ModelEntry& entry, const FitRequest& request) {
  if (!entry.can_fit()) throw Error(fmt::format("model '{}' has no fitter", entry.name));
  if (!request.preprocessing.any()) return entry.fit(request);
  auto prepared = data::preprocess(request.input, request.output, request.preprocessing);
  FitRequest prepared_request = request;
  prepared_request.input = prepared.input;
  prepared_request.output = prepared.output;
  auto outcome = entry.fit(prepared_request);
  outcome.report.preprocessing = std::move(prepared.steps);
  return outcome;
}

}  // namespace hyst
