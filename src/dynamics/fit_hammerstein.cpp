#include "hyst/dynamics/fit_hammerstein.hpp"

#include <utility>

#include "detail/hammerstein_parametrisation.hpp"
#include "detail/simulation_error_fit.hpp"

namespace hyst {

HammersteinFit fit_hammerstein(const StateSpace& linear,
                               std::span<const PeriodicExperiment> experiments,
                               const HammersteinFitOptions& options) {
  auto fit = detail::fit_structure<detail::HammersteinParametrisation>(
      linear, experiments, options, "Hammerstein fit", "hammerstein");
  return {std::move(fit.model), std::move(fit.report)};
}

}  // namespace hyst
