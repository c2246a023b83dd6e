#include "hyst/dynamics/fit_hysteretic_lfr.hpp"

#include <utility>

#include "detail/feedback_lfr_parametrisation.hpp"
#include "detail/simulation_error_fit.hpp"

namespace hyst {

HystereticLfrFit fit_hysteretic_lfr(const StateSpace& linear,
                                    std::span<const PeriodicExperiment> experiments,
                                    const HystereticLfrFitOptions& options) {
  auto fit = detail::fit_structure<detail::FeedbackLfrParametrisation>(
      linear, experiments, options, "hysteretic LFR fit", "hysteretic_lfr");
  return {std::move(fit.model), std::move(fit.report)};
}

}  // namespace hyst
