#include "hyst/dynamics/fit_hysteretic_lfr.hpp"

#include <string>
#include <utility>

#include <fmt/format.h>

#include "detail/feedback_lfr_parametrisation.hpp"
#include "detail/general_lfr_parametrisation.hpp"
#include "detail/simulation_error_fit.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

HystereticLfrFit fit_hysteretic_lfr(const StateSpace& linear,
                                    std::span<const PeriodicExperiment> experiments,
                                    const HystereticLfrFitOptions& options) {
  const std::string name = "hysteretic LFR fit";
  detail::check_experiments(linear, experiments, name);
  detail::check_threshold_fractions(options.threshold_fractions, name);
  if (options.feedback_channels > kMaxFeedbackChannels)
    throw Error(fmt::format("{}: feedback_channels = {} is above the limit of {}", name,
                            options.feedback_channels, kMaxFeedbackChannels));
  const detail::FeedbackLfrParametrisation structure(
      linear, detail::signal_scales(experiments, name), options, name);
  const auto data = detail::realisations(experiments, name);
  auto fit = detail::fit_simulation_error(
      structure, data,
      {"hysteretic_lfr", options.max_iterations, options.threads, options.progress});
  if (options.general_iterations == 0) return {std::move(fit.model), std::move(fit.report)};

  const detail::GeneralLfrParametrisation general(fit.model, options.fit_poles,
                                                  options.max_pole_radius, name);
  auto refined =
      detail::fit_simulation_error(general, data,
                                   {"hysteretic_lfr (every matrix free)",
                                    options.general_iterations, options.threads, options.progress});
  auto& report = refined.report;
  report.model = "hysteretic_lfr";
  report.method = fmt::format("{} ({} iterations); then of {} ({} iterations)", fit.report.method,
                              fit.report.iterations, general.description(), report.iterations);
  report.iterations += fit.report.iterations;
  report.initial_cost = fit.report.initial_cost;
  report.seconds += fit.report.seconds;
  return {std::move(refined.model), std::move(report)};
}

}  // namespace hyst
