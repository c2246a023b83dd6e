// Maxwell-slip model: a hand-computed element, the sum of stop operators, the equivalent PI
// model and its analytic inverse, saturation, and the NNLS fit.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_maxwell_slip.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/models/maxwell_slip.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/operators/stop.hpp"

namespace hyst {
namespace {

MaxwellSlip three_elements(double linear) {
  return MaxwellSlip({.stiffness = {3, 2, 1},
                      .break_away = {0.3, 0.4, 0.5},
                      .linear_stiffness = linear,
                      .offset = 0.1});
}

TEST(MaxwellSlip, OneElementByHand) {
  // k = 2, f = 1: D = 0.5. x = 0, 0.3, 1.0, 0.8, 0.5, -0.4 -> delta = 0, 0.3, 0.5 (slips),
  // 0.3, 0, -0.5 (slips).
  const MaxwellSlip model({.stiffness = {2}, .break_away = {1}});
  auto state = model.initial_state();
  const std::vector<double> expected{0, 0.6, 1.0, 0.6, 0.0, -1.0};
  const std::vector<double> x{0, 0.3, 1.0, 0.8, 0.5, -0.4};
  for (std::size_t k = 0; k < x.size(); ++k)
    EXPECT_NEAR(model.step(state, x[k]), expected[k], 1e-15) << "k = " << k;
}

TEST(MaxwellSlip, IsAWeightedSumOfStopOperatorsAndAPiModel) {
  const auto model = three_elements(0.5);
  const Stop s0(0.1), s1(0.2), s2(0.5);
  Stop::State e0, e1, e2;
  const auto pi = model.to_prandtl_ishlinskii();
  const auto v = test::random_walk(10000, 13, 1.5, 0.1);
  auto state = model.initial_state();
  auto pi_state = model.prandtl_ishlinskii_state(state);
  for (double x : v) {
    const double force = model.step(state, x);
    const double stops =
        0.1 + 0.5 * x + 3 * s0.step(e0, x) + 2 * s1.step(e1, x) + 1 * s2.step(e2, x);
    ASSERT_NEAR(force, stops, 1e-12);
    ASSERT_NEAR(pi.step(pi_state, x), force, 1e-12);
  }
}

TEST(MaxwellSlip, SaturatesWithoutLinearSpringAndInvertsWithOne) {
  const auto saturating = three_elements(0.0);
  EXPECT_FALSE(saturating.is_invertible());
  auto state = saturating.initial_state();
  EXPECT_NEAR(saturating.step(state, 5.0), 0.1 + 1.2, 1e-15);
  EXPECT_NEAR(saturating.step(state, -5.0), 0.1 - 1.2, 1e-15);

  const auto model = three_elements(0.5);
  ASSERT_TRUE(model.is_invertible());
  // Inverse started consistently after an arbitrary history: x -> F -> x.
  auto forward = model.initial_state();
  for (double x : test::random_walk(500, 17, 1.0, 0.2))
    model.step(forward, x);
  const InversePrandtlIshlinskii inverse(model.to_prandtl_ishlinskii());
  auto inverse_state = inverse.state_consistent_with(model.prandtl_ishlinskii_state(forward));
  double worst = 0.0;
  for (double x : test::pi_check_signal()) {
    const double force = model.step(forward, x);
    worst = std::max(worst, std::abs(inverse.step(inverse_state, force) - x));
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(MaxwellSlip, FitRecoversStiffnessesOnTheFitterGrid) {
  // Truth on the default grid D_i = i * range / (2 (N + 1)), range = 2 (walk in [-1, 1]).
  const auto v = test::random_walk(3000, 19, 1.0, 0.1);
  const double range =
      *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  std::vector<double> k{1.0, 0.0, 2.0, 0.5}, f, kept;
  for (std::size_t i = 0; i < k.size(); ++i) {
    if (k[i] == 0) continue;
    kept.push_back(k[i]);
    f.push_back(k[i] * static_cast<double>(i + 1) * range / 10.0);
  }
  const MaxwellSlip truth(
      {.stiffness = kept, .break_away = f, .linear_stiffness = 0.3, .offset = -0.2});
  auto state = truth.state_at_rest(v.front());
  const auto y = simulate(truth, state, v);
  const auto fit = fit_maxwell_slip(v, y, {.elements = 4, .validate_fraction = 0.25});
  EXPECT_LT(fit.report.fit.rmse, 1e-9);
  EXPECT_LT(fit.report.validation->rmse, 1e-9);
  ASSERT_EQ(fit.model.size(), 3u);  // the zero element is dropped
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(fit.model.params().stiffness[i], kept[i], 1e-8);
    EXPECT_NEAR(fit.model.params().break_away[i], f[i], 1e-8);
  }
  EXPECT_NEAR(fit.model.params().linear_stiffness, 0.3, 1e-8);
}

TEST(MaxwellSlip, CounterClockwiseIsAPiModelWithPositiveWeights) {
  // s = -1: F = F_off + k_lin x - sum k_i E_{D_i}[x] = F_off + (k_lin - sum k_i) x
  // + sum k_i F_{D_i}[x] (play F_D = x - E_D): a PI model with weights (k_lin - 6, 3, 2, 1).
  const MaxwellSlip model({.stiffness = {3, 2, 1},
                           .break_away = {0.3, 0.4, 0.5},
                           .linear_stiffness = 6.5,
                           .offset = 0.1,
                           .orientation = MaxwellSlip::Orientation::counter_clockwise});
  EXPECT_TRUE(model.is_invertible());  // 6.5 > 3 + 2 + 1
  const PrandtlIshlinskii pi(
      {.thresholds = {0, 0.1, 0.2, 0.5}, .weights = {0.5, 3, 2, 1}, .offset = 0.1});
  auto state = model.initial_state();
  auto pi_state = pi.initial_state();
  auto own_pi_state = model.prandtl_ishlinskii_state(state);
  const auto own_pi = model.to_prandtl_ishlinskii();
  for (double x : test::random_walk(5000, 23, 1.5, 0.1)) {
    const double force = model.step(state, x);
    ASSERT_NEAR(force, pi.step(pi_state, x), 1e-12);
    ASSERT_NEAR(own_pi.step(own_pi_state, x), force, 1e-12);
  }
  // One element by hand, k = 2, f = 1 (D = 0.5), k_lin = 3: F = 3 x - 2 delta.
  const MaxwellSlip one({.stiffness = {2},
                         .break_away = {1},
                         .linear_stiffness = 3,
                         .orientation = MaxwellSlip::Orientation::counter_clockwise});
  auto one_state = one.initial_state();
  const std::vector<double> x{0, 0.3, 1.0, 0.8};  // delta = 0, 0.3, 0.5, 0.3
  const std::vector<double> expected{0, 0.3, 2.0, 1.8};
  for (std::size_t k = 0; k < x.size(); ++k)
    EXPECT_NEAR(one.step(one_state, x[k]), expected[k], 1e-15) << "k = " << k;
  EXPECT_FALSE(MaxwellSlip({.stiffness = {2},
                            .break_away = {1},
                            .linear_stiffness = 2,
                            .orientation = MaxwellSlip::Orientation::counter_clockwise})
                   .is_invertible());  // slope after a reversal 2 - 2 = 0
}

TEST(MaxwellSlip, EnclosedAreaSignGivesTheOrientation) {
  // Unit square in the (x, F) plane: up, right, down (closing chord back left) is clockwise.
  const std::vector<double> x{0, 0, 1, 1}, f{0, 1, 1, 0};
  EXPECT_NEAR(enclosed_area(x, f), 1.0, 1e-15);
  const std::vector<double> x_back{1, 1, 0, 0}, f_back{0, 1, 1, 0};  // mirrored: counter-clockwise
  EXPECT_NEAR(enclosed_area(x_back, f_back), -1.0, 1e-15);
}

TEST(MaxwellSlip, FitReproducesACounterClockwisePiLoop) {
  // Truth: a PI model with positive weights (a counter-clockwise loop) whose thresholds lie on the
  // fitter's default grid D_i = i * range / (2 (N + 1)); by the identity of the test above it is
  // the counter-clockwise Maxwell-slip model k_i = p_i, k_lin = p_0 + sum p_i.
  const auto v = test::random_walk(3000, 29, 1.0, 0.1);
  const double range =
      *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  const std::vector<double> p{0.4, 1.0, 0.5, 2.0};
  const PrandtlIshlinskii pi(
      {.thresholds = {0, range / 8, 2 * range / 8, 3 * range / 8}, .weights = p, .offset = 0.25});
  auto pi_state = pi.make_state(std::vector<double>(4, v.front()));  // relaxed at x[0]
  const auto y = simulate(pi, pi_state, v);
  ASSERT_LT(enclosed_area(v, y), 0.0);
  const auto fit = fit_maxwell_slip(v, y, {.elements = 3, .validate_fraction = 0.25});
  EXPECT_EQ(fit.model.params().orientation, MaxwellSlip::Orientation::counter_clockwise);
  EXPECT_LT(fit.report.fit.rmse, 1e-9);
  EXPECT_LT(fit.report.validation->rmse, 1e-9);
  ASSERT_EQ(fit.model.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(fit.model.params().stiffness[i], p[i + 1], 1e-8);
  EXPECT_NEAR(fit.model.params().linear_stiffness, 0.4 + 1.0 + 0.5 + 2.0, 1e-8);
  EXPECT_NEAR(fit.model.params().offset, 0.25, 1e-8);
  EXPECT_TRUE(fit.model.is_invertible());

  // Forcing the clockwise sign on this loop fails and says which orientation was used.
  EXPECT_HYST_ERROR(
      fit_maxwell_slip(v, y, {.elements = 3, .orientation = MaxwellSlip::Orientation::clockwise}),
      "came out 0 for a clockwise loop (given");
}

TEST(MaxwellSlip, RejectsInvalidParameters) {
  EXPECT_HYST_ERROR(MaxwellSlip({.stiffness = {}}), "stiffness k is empty");
  EXPECT_HYST_ERROR(MaxwellSlip({.stiffness = {1, 0}, .break_away = {1, 1}}),
                    "stiffness k[1] = 0 must be finite and > 0");
  EXPECT_HYST_ERROR(MaxwellSlip({.stiffness = {1, 1}, .break_away = {1, 0.5}}),
                    "slip displacement f[1]/k[1] = 0.5 must be > f[0]/k[0] = 1");
  EXPECT_HYST_ERROR(MaxwellSlip({.stiffness = {1}, .break_away = {1}, .linear_stiffness = -1}),
                    "linear_stiffness = -1");
  const MaxwellSlip model({.stiffness = {1}, .break_away = {1}});
  EXPECT_HYST_ERROR(model.make_state({2.0}, 0.0), "deflection[0] = 2");
  EXPECT_HYST_ERROR(fit_maxwell_slip(test::random_walk(100, 1), test::random_walk(100, 2),
                                     {.slip_displacements = {0.2, 0.1}}),
                    "slip displacement D[1] = 0.1");
}

}  // namespace
}  // namespace hyst
