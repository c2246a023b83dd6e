#include "hyst/identify/fit_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

constexpr std::array<std::pair<Termination, std::string_view>, 4> kTerminationNames{{
    {Termination::converged, "converged"},
    {Termination::max_iterations, "max_iterations"},
    {Termination::no_progress, "no_progress"},
    {Termination::failed, "failed"},
}};

std::string metrics_sentence(std::string_view part, const ErrorMetrics& metrics) {
  return fmt::format("{}: RMSE {:.4g}, NRMSE {:.4g} %, max error {:.4g} on {} samples.", part,
                     metrics.rmse, 100.0 * metrics.nrmse, metrics.max_error, metrics.samples);
}

std::string metrics_row(std::string_view part, const ErrorMetrics& metrics) {
  return fmt::format("  {:<12}{:>10}{:>14.4g}{:>12.4g}{:>14.4g}\n", part, metrics.samples,
                     metrics.rmse, 100.0 * metrics.nrmse, metrics.max_error);
}

}  // namespace

std::string_view to_string(Termination termination) {
  for (const auto& [value, name] : kTerminationNames) {
    if (value == termination) return name;
  }
  return "unknown";
}

Termination termination_from_string(std::string_view text) {
  for (const auto& [value, name] : kTerminationNames) {
    if (name == text) return value;
  }
  throw Error(fmt::format(
      "unknown termination '{}' (expected converged, max_iterations, no_progress or failed)",
      text));
}

ErrorMetrics error_metrics(std::span<const double> measured, std::span<const double> predicted) {
  require_same_size(measured.size(), "measured", predicted.size(), "predicted");
  require_not_empty(measured.size(), "measured");
  require_finite(measured, "measured");
  require_finite(predicted, "predicted");
  const auto [lowest, highest] = std::minmax_element(measured.begin(), measured.end());
  const double range = *highest - *lowest;
  if (!(range > 0.0)) {
    throw Error(fmt::format(
        "measured is constant (every one of its {} samples = {}): its range normalises the NRMSE "
        "and must be > 0",
        measured.size(), *lowest));
  }
  double sum_of_squares = 0.0;
  double max_error = 0.0;
  for (std::size_t k = 0; k < measured.size(); ++k) {
    const double error = measured[k] - predicted[k];
    sum_of_squares += error * error;
    max_error = std::max(max_error, std::abs(error));
  }
  ErrorMetrics metrics;
  metrics.samples = measured.size();
  metrics.rmse = std::sqrt(sum_of_squares / static_cast<double>(measured.size()));
  metrics.nrmse = metrics.rmse / range;
  metrics.max_error = max_error;
  return metrics;
}

std::string FitReport::brief() const {
  std::string text = fmt::format(
      "{} fitted by {}: {} after {} iterations in {:.3g} s ({}). Cost 0.5*sum(e^2) {:.6g} -> "
      "{:.6g} with {} parameters. {}",
      model, method, to_string(termination), iterations, seconds, message, initial_cost, final_cost,
      parameters, metrics_sentence("Fit", fit));
  if (validation) {
    text += fmt::format(" {}", metrics_sentence("Validation", *validation));
    if (!validation_rule.empty()) text += fmt::format(" Validation on the {}.", validation_rule);
  }
  if (!preprocessing.empty()) {
    text += fmt::format(" Preprocessing: {}.", fmt::join(preprocessing, "; "));
  }
  return text;
}

std::string FitReport::full() const {
  std::string text;
  const auto line = [&text](std::string_view name, const std::string& value) {
    text += fmt::format("  {:<26}{}\n", name, value);
  };
  text += "Fit report\n";
  line("model", model);
  line("method", method);
  line("termination", std::string(to_string(termination)));
  line("message", message);
  line("iterations", fmt::format("{}", iterations));
  line("parameters", fmt::format("{}", parameters));
  line("initial cost 0.5*sum(e^2)", fmt::format("{:.6g}", initial_cost));
  line("final cost 0.5*sum(e^2)", fmt::format("{:.6g}", final_cost));
  line("time [s]", fmt::format("{:.3g}", seconds));
  if (preprocessing.empty()) line("preprocessing", "the record as measured");
  for (std::size_t i = 0; i < preprocessing.size(); ++i) {
    line(i == 0 ? "preprocessing" : "", preprocessing[i]);
  }
  if (validation && !validation_rule.empty()) line("validation", validation_rule);
  text += "\n";
  text += fmt::format("  {:<12}{:>10}{:>14}{:>12}{:>14}\n", "part", "samples", "RMSE", "NRMSE [%]",
                      "max error");
  text += metrics_row("fit", fit);
  if (validation) {
    text += metrics_row("validation", *validation);
  } else {
    text += fmt::format("  {:<12}{:>10}\n", "validation", "none");
  }
  return text;
}

}  // namespace hyst
