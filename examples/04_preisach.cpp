// Example 04: the Preisach model of the seed paper - 231 unweighted relays (21 input levels) -
// driven by a decaying oscillation, in the fast Everett form whose cost per sample does not
// depend on the number of relays, checked against the brute-force sum over every relay, and
// inverted numerically.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_preisach.hpp"
#include "hyst/models/preisach.hpp"
#include "hyst/models/preisach_relay_grid.hpp"
#include "hyst/signals/generators.hpp"

int main() {
  // mu = 1 for each of the N(N+1)/2 = 231 relays on [-1, 1]; start at negative saturation.
  const hyst::RelayGridEverett::Params grid{
      .levels = 21, .lower = -1, .upper = 1, .weights = std::vector<double>(231, 1.0)};
  const hyst::Preisach fast({.everett = grid});
  const hyst::PreisachRelayGrid brute_force({.everett = grid});

  // Each reversal lies inside the previous one: a staircase of internal loops.
  const auto input = hyst::signals::generate(
      hyst::signals::TimeGrid{2000, 1e-3},
      hyst::signals::DecayingSine{.amplitude = 1.2, .frequency = 5, .time_constant = 0.6});
  auto fast_state = fast.initial_state();
  auto brute_state = brute_force.initial_state();
  const auto output = hyst::simulate(fast, fast_state, input);
  const auto reference = hyst::simulate(brute_force, brute_state, input);
  double worst = 0;
  for (std::size_t k = 0; k < output.size(); ++k) {
    worst = std::max(worst, std::abs(output[k] - reference[k]));
  }
  std::printf("fast form vs every relay: max difference %.3g (output range +-%g)\n", worst,
              fast.total_weight());

  // The numerical inverse searches the input on a copy of the state; started from the model's
  // own state, it reproduces the output sequence.
  const hyst::InversePreisach inverse(fast);
  auto inverse_state = fast.initial_state();
  std::vector<double> recovered(output.size());
  const auto report = hyst::invert(inverse, inverse_state, output, recovered);
  auto check_state = fast.initial_state();
  const auto again = hyst::simulate(fast, check_state, recovered);
  double round_trip = 0;
  for (std::size_t k = 0; k < again.size(); ++k) {
    round_trip = std::max(round_trip, std::abs(again[k] - output[k]));
  }
  std::printf("inverse: max |P[P^-1[y]] - y| = %.3g, saturated samples %zu\n", round_trip,
              report.saturated_samples);
  return worst < 1e-9 && round_trip < 1e-9 ? 0 : 1;
}
