// Example 07: the modified Prandtl-Ishlinskii model (Kuhnen) - a PI model followed by a
// dead-zone superposition, which makes the loops asymmetric - with its analytic inverse as a
// feedforward compensator, and the fit of such a model to a record by constrained least squares.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_modified_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "hyst/signals/generators.hpp"

int main() {
  // The PI part and the dead-zone map of the reference (Kuhnen 2003, misc_check.py).
  const hyst::ModifiedPrandtlIshlinskii model(
      {.pi = {.thresholds = {0, 0.3, 0.7, 1.0}, .weights = {0.8, 0.5, 0.3, 0.2}},
       .dead_zone = {.thresholds = {-1.5, -0.8, -0.3, 0, 0.4, 0.9, 1.6},
                     .weights = {0.05, 0.1, 0.2, 1.0, -0.15, -0.2, -0.1}},
       .offset = 0.0});
  const hyst::InverseModifiedPrandtlIshlinskii inverse(model);
  const auto& map = inverse.dead_zone_inverse().params();
  std::printf("inverse dead-zone map: d' =");
  for (double d : map.thresholds)
    std::printf(" %.4g", d);
  std::printf("\n                       g' =");
  for (double g : map.weights)
    std::printf(" %.4g", g);
  std::printf("\n");

  // Feedforward: the inverse gives the input for a desired output with internal loops; the model
  // driven by it reproduces the desired output.
  const auto desired = hyst::signals::generate(
      hyst::signals::TimeGrid{3000, 1e-3},
      hyst::signals::DecayingSine{.amplitude = 2.0, .frequency = 4, .time_constant = 1.0});
  auto inverse_state = inverse.initial_state();
  std::vector<double> input(desired.size());
  hyst::invert(inverse, inverse_state, desired, input);
  auto state = model.initial_state();
  const auto reached = hyst::simulate(model, state, input);
  double worst = 0;
  for (std::size_t k = 0; k < desired.size(); ++k)
    worst = std::max(worst, std::abs(reached[k] - desired[k]));
  std::printf("max |P[P^-1[y_d]] - y_d| = %.3g\n", worst);

  // Identification: fit a model with default grids to the model's own response.
  const auto fit = hyst::fit_modified_prandtl_ishlinskii(input, reached, {.operators = 10});
  std::printf("%s\nfitted model invertible: %s\n", fit.report.brief().c_str(),
              fit.model.is_invertible() ? "yes" : "no");
  return worst < 1e-12 && fit.model.is_invertible() && fit.report.fit.nrmse_percent < 2 ? 0 : 1;
}
