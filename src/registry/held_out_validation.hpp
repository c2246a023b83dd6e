#pragma once
// Error metrics of a fitted model on a separate held-out record (FitRequest::validation_input),
// simulated from the given state, for fitters that only split one record themselves.

#include <vector>

#include "hyst/core/checks.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst::detail {

template <class Model>
void add_held_out_validation(const FitRequest& request, const Model& model,
                             typename Model::State state, FitReport& report) {
  if (request.validation_input.empty()) return;
  require_same_size(request.validation_input.size(), "validation input",
                    request.validation_output.size(), "validation output");
  std::vector<double> predicted(request.validation_input.size());
  simulate(model, state, request.validation_input, predicted);
  report.validation = error_metrics(request.validation_output, predicted);
}

}  // namespace hyst::detail
