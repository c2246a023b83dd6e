// Uses the installed headers and library: a PI model, its inverse and the model registry.
#include <cmath>
#include <cstdio>
#include <vector>

#include <hyst/core/invert.hpp>
#include <hyst/core/simulate.hpp>
#include <hyst/inverse/inverse_prandtl_ishlinskii.hpp>
#include <hyst/models/prandtl_ishlinskii.hpp>
#include <hyst/registry/model_registry.hpp>

int main() {
  const hyst::PrandtlIshlinskii model({.thresholds = {0.0, 0.5}, .weights = {1.0, 0.5}});
  const hyst::InversePrandtlIshlinskii inverse(model);
  const std::vector<double> desired{0.0, 1.0, -0.5, 0.7, 0.2};
  std::vector<double> input(desired.size());
  auto inverse_state = inverse.initial_state();
  hyst::invert(inverse, inverse_state, desired, input);
  auto state = model.initial_state();
  const auto output = hyst::simulate(model, state, input);
  double worst = 0;
  for (std::size_t k = 0; k < output.size(); ++k) {
    worst = std::fmax(worst, std::fabs(output[k] - desired[k]));
  }
  std::printf("models: %s; round trip error %.3g\n", hyst::ModelRegistry::builtin().names().c_str(),
              worst);
  return worst < 1e-12 ? 0 : 1;
}
