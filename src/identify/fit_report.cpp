#include "hyst/identify/fit_report.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/checks.hpp"

namespace hyst {
namespace {

std::string metrics_sentence(std::string_view part, const ErrorMetrics& metrics) {
  return fmt::format("{}: RMSE {:.4g}, NRMSE {:.4g} %, max error {:.4g} on {} samples.", part,
                     metrics.rmse, metrics.nrmse_percent, metrics.max_error, metrics.samples);
}

std::string yardstick_sentence(const FitReport& report) {
  const auto* best = report.best_reference();
  if (best == nullptr || !report.validation) return "";
  return fmt::format(
      " Yardstick: the best reference predictor on the held-out part is '{}' with NRMSE {:.4g} %; "
      "the model {} it.",
      best->name, best->validation->nrmse_percent,
      *report.beats_yardstick() ? "beats" : "does not beat");
}

std::string metrics_row(std::string_view part, const ErrorMetrics& metrics) {
  return fmt::format("  {:<12}{:>10}{:>14.4g}{:>12.4g}{:>14.4g}\n", part, metrics.samples,
                     metrics.rmse, metrics.nrmse_percent, metrics.max_error);
}

}  // namespace

Termination termination_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<Termination>, "termination");
}

std::string_view FitReport::status() const {
  if (termination == Termination::failed) return "failed";
  if (quality == FitQuality::unstable || quality == FitQuality::degenerate) {
    return to_string(quality);
  }
  switch (termination) {
    case Termination::max_iterations:
      return "iteration limit";
    case Termination::no_progress:
      return "no progress";
    default:
      return "converged";
  }
}

void FitReport::take_verdict(FitQuality verdict, std::string note) {
  const auto gravity = [](FitQuality q) {
    switch (q) {
      case FitQuality::unstable:
        return 3;
      case FitQuality::degenerate:
        return 2;
      case FitQuality::sound:
        return 1;
      case FitQuality::unchecked:
        return 0;
    }
    return 0;
  };
  if (gravity(verdict) < gravity(quality)) return;
  quality = verdict;
  quality_note = std::move(note);
}

std::optional<bool> FitReport::beats_yardstick() const {
  const auto* best = best_reference();
  if (best == nullptr || !validation) return std::nullopt;
  return validation->nrmse_percent < best->validation->nrmse_percent;
}

std::string FitReport::brief() const {
  // The method's own ending is named too when the status overrules it.
  const bool overruled = termination != Termination::failed &&
                         (quality == FitQuality::degenerate || quality == FitQuality::unstable);
  std::string text = fmt::format(
      "{} fitted by {}: {}{} after {} iterations in {:.3g} s ({}). Cost 0.5*sum(e^2) {:.6g} -> "
      "{:.6g} with {} parameters. {}",
      model, method, status(),
      overruled ? fmt::format(" (the method: {}; {})", to_string(termination), quality_note) : "",
      iterations, seconds, message, initial_cost, final_cost, parameters,
      metrics_sentence("Fit", fit));
  if (validation) {
    text += fmt::format(" {}", metrics_sentence("Validation", *validation));
    if (!validation_rule.empty()) text += fmt::format(" Validation on the {}.", validation_rule);
  }
  text += yardstick_sentence(*this);
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
  line("status", std::string(status()));
  line("termination", std::string(to_string(termination)));
  if (!quality_note.empty()) line("simulation", quality_note);
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
  if (domain) {
    line("fitted domain",
         fmt::format("input [{:.6g}, {:.6g}], output [{:.6g}, {:.6g}], {} samples{}",
                     domain->input_min, domain->input_max, domain->output_min, domain->output_max,
                     domain->samples,
                     domain->sample_time ? fmt::format(" at {:.6g} s", *domain->sample_time)
                                         : std::string()));
    if (domain->sample_time) {
      line("", fmt::format(
                   "duration {:.6g} s, largest input rate {:.6g} per s, longest hold "
                   "(run without a reversal) {:.6g} s{}",
                   *domain->duration(), *domain->largest_input_rate(), *domain->longest_hold(),
                   domain->largest_time_constant ? fmt::format(", largest time constant {:.6g} s",
                                                               *domain->largest_time_constant)
                                                 : std::string()));
    } else {
      line("", fmt::format("largest input step {:.6g}, longest run without a reversal {} samples "
                           "(no sample time: a rate-independent model)",
                           domain->largest_input_step, domain->longest_hold_samples));
    }
  }
  text += "\n";
  text += fmt::format("  {:<12}{:>10}{:>14}{:>12}{:>14}\n", "part", "samples", "RMSE", "NRMSE [%]",
                      "max error");
  text += metrics_row("fit", fit);
  if (validation) {
    text += metrics_row("validation", *validation);
  } else {
    text += fmt::format("  {:<12}{:>10}\n", "validation", "none");
  }
  if (!references.empty()) {
    text += "\n  Yardstick: reference predictors on the held-out part (reference_predictors.hpp)\n";
    for (const auto& reference : references) {
      if (reference.validation) {
        text += fmt::format("  {:<30}{:>10.4g} % NRMSE\n", reference.name,
                            reference.validation->nrmse_percent);
      } else {
        text += fmt::format("  {:<30}not made: {}\n", reference.name, reference.error);
      }
    }
    text += yardstick_sentence(*this).substr(1) + "\n";
  }
  return text;
}

}  // namespace hyst
