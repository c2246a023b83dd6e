// Uses the installed hyst::core alone: a PI model and its inverse, checked against hand-computed
// play operator outputs.
#include <cmath>
#include <cstdio>
#include <vector>

#include <hyst/core/invert.hpp>
#include <hyst/core/simulate.hpp>
#include <hyst/inverse/inverse_prandtl_ishlinskii.hpp>
#include <hyst/models/bouc_wen.hpp>  // includes Boost.Odeint: its headers come with hyst::core
#include <hyst/models/prandtl_ishlinskii.hpp>

int main() {
  // y = 1.0 * v + 0.5 * w, with w the play of half-width 0.5 started at 0:
  //   v  0    1     0     -1     0.5
  //   w  0    0.5   0.5   -0.5   0
  //   y  0    1.25  0.25  -1.25  0.5
  const hyst::PrandtlIshlinskii model({.thresholds = {0.0, 0.5}, .weights = {1.0, 0.5}});
  const std::vector<double> input{0.0, 1.0, 0.0, -1.0, 0.5};
  const std::vector<double> expected_output{0.0, 1.25, 0.25, -1.25, 0.5};

  auto state = model.initial_state();
  const auto output = hyst::simulate(model, state, input);
  // The inverse from its initial state maps the hand-computed outputs back to the inputs.
  const hyst::InversePrandtlIshlinskii inverse(model);
  auto inverse_state = inverse.initial_state();
  std::vector<double> inverted(expected_output.size());
  hyst::invert(inverse, inverse_state, expected_output, inverted);

  double worst = 0;
  for (std::size_t k = 0; k < input.size(); ++k) {
    worst = std::fmax(worst, std::fabs(output[k] - expected_output[k]));
    worst = std::fmax(worst, std::fabs(inverted[k] - input[k]));
  }
  std::printf("hyst::core: PI model and inverse, largest error %.3g\n", worst);
  return worst < 1e-12 ? 0 : 1;
}
