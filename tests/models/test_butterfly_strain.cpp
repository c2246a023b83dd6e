// Butterfly strain model: a hand calculation on a three-level grid, the brute-force relay grid
// plus the polynomial as a second algorithm, the periodic state, the slope of the map, and
// validation.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/models/butterfly_strain.hpp"
#include "hyst/models/preisach_relay_grid.hpp"

namespace hyst {
namespace {

// Three levels on [-1, 1] (thresholds -2/3, 0, 2/3); y = P^2.
ButterflyStrain::Params three_levels() {
  ButterflyStrain::Params p;
  p.polarisation.everett = {
      .levels = 3, .lower = -1.0, .upper = 1.0, .weights = {0.1, 0.0, 0.1, 0.7, 0.0, 0.1}};
  p.polarisation_coefficients = {0.0, 1.0};
  return p;
}

TEST(ButterflyStrain, ThreeLevelsByHand) {
  const ButterflyStrain model(three_levels());
  auto state = model.initial_state();
  // v = 0 from negative saturation: relays (0,0) and (1,1) (alpha <= 0, weights 0.1 + 0.1) are
  // up, P = -1 + 2 (0.2) = -0.6.
  EXPECT_NEAR(model.step(state, 0.0), 0.36, 1e-15);
  EXPECT_NEAR(model.step(state, 1.0), 1.0, 1e-15);  // positive saturation, P = 1
  // Back to 0: only relay (2,2) (beta = 2/3, weight 0.1) went down, P = -1 + 2 (0.9) = 0.8;
  // the diagonal relay at 0 stays up (the >= test comes first).
  EXPECT_NEAR(model.step(state, 0.0), 0.64, 1e-15);
  // Negative saturation: P = -1, the same strain as at positive saturation - the butterfly.
  EXPECT_NEAR(model.step(state, -1.0), 1.0, 1e-15);
  EXPECT_NEAR(model.polarisation(state), -1.0, 1e-15);
}

TEST(ButterflyStrain, EqualsTheRelayGridThroughThePolynomial) {
  ButterflyStrain::Params p;
  p.polarisation.everett.levels = 9;
  p.polarisation.everett.lower = -2.0;
  p.polarisation.everett.upper = 2.0;
  for (std::size_t r = 0; r < preisach_relay_count(9); ++r)
    p.polarisation.everett.weights.push_back(0.01 + 0.003 * static_cast<double>(r % 7));
  p.polarisation.offset = 0.05;
  p.field_coefficient = 0.3;
  p.polarisation_coefficients = {0.4, 1.5, -0.2};
  p.offset = -0.7;
  const ButterflyStrain model(p);
  const PreisachRelayGrid grid(p.polarisation);
  auto state = model.initial_state();
  auto grid_state = grid.initial_state();
  const auto input = test::random_walk(3000, 7, 2.5);
  for (double v : input) {
    const double P = grid.step(grid_state, v);
    const double expected = -0.7 + 0.3 * v + 0.4 * P + 1.5 * P * P - 0.2 * P * P * P;
    const double previewed = model.preview(state, v);
    const double y = model.step(state, v);
    ASSERT_NEAR(y, expected, 1e-12) << "v = " << v;
    ASSERT_EQ(previewed, y);
  }
}

TEST(ButterflyStrain, PeriodicStateRepeatsEveryPeriod) {
  const ButterflyStrain model(three_levels());
  const std::vector<double> period = {0.1, 0.9, 0.2, -0.5, -0.3, 0.05};
  auto state = model.periodic_state(period);
  const auto first = simulate(model, state, std::span<const double>(period));
  const auto second = simulate(model, state, std::span<const double>(period));
  EXPECT_EQ(first, second);
  // From negative saturation the first period differs: at 0.1 P = -0.6, not 0.8 (the relays
  // with beta = -2/3 stay up at the minimum -0.5).
  auto virgin = model.initial_state();
  EXPECT_NE(model.step(virgin, period[0]), first[0]);
}

TEST(ButterflyStrain, SlopeIsTheDerivativeOfTheMap) {
  auto p = three_levels();
  p.polarisation_coefficients = {0.4, 1.5, -0.2, 0.05};
  const ButterflyStrain model(p);
  for (double P : {-1.0, -0.3, 0.0, 0.5, 0.9}) {
    const double h = 1e-6;
    const double numeric = (model.strain(0.0, P + h) - model.strain(0.0, P - h)) / (2 * h);
    EXPECT_NEAR(model.strain_slope(P), numeric, 1e-8);
  }
}

TEST(ButterflyStrain, RejectsInvalidParameters) {
  auto p = three_levels();
  p.polarisation_coefficients.clear();
  EXPECT_HYST_ERROR(ButterflyStrain{p}, "polarisation coefficients q_n = 0 must be in [1, 16]");
  p = three_levels();
  p.polarisation_coefficients[1] = NAN;
  EXPECT_HYST_ERROR(ButterflyStrain{p}, "polarisation coefficient q_2 = nan is not finite");
  p = three_levels();
  p.field_coefficient = INFINITY;
  EXPECT_HYST_ERROR(ButterflyStrain{p}, "field coefficient d = inf is not finite");
  p = three_levels();
  p.polarisation.everett.weights[2] = -1.0;
  EXPECT_HYST_ERROR(ButterflyStrain{p}, "butterfly strain model polarisation:");
  EXPECT_HYST_ERROR(ButterflyStrain(three_levels()).periodic_state({}),
                    "the period has no samples");
}

}  // namespace
}  // namespace hyst
