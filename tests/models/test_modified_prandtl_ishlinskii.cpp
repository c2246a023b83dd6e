// Modified PI (Kuhnen): the dead-zone superposition and its inverse against misc_check.py, the
// analytic inverse of the whole model (round trips to 1e-12) and the constrained least-squares
// fit.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_modified_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {
namespace {

// misc_check.py, section 3.
const std::vector<double> kD{-1.5, -0.8, -0.3, 0.0, 0.4, 0.9, 1.6};
const std::vector<double> kG{0.05, 0.1, 0.2, 1.0, -0.15, -0.2, -0.1};

ModifiedPrandtlIshlinskii reference_modified_pi() {
  return ModifiedPrandtlIshlinskii({.pi = {.thresholds = {0, 0.3, 0.7, 1.0, 1.6, 2.2},
                                           .weights = {0.8, 0.5, 0.3, 0.2, 0.1, 0.05},
                                           .offset = 0.15},
                                    .dead_zone = {kD, kG},
                                    .offset = -0.4});
}

TEST(DeadZoneSuperposition, InverseMatchesMiscCheck) {
  const DeadZoneSuperposition map({kD, kG});
  const auto inverse = map.inverse();
  // Printed (rounded to 4 decimals) by misc_check.py.
  const std::vector<double> d_inv{-1.81, -0.9, -0.3, 0.0, 0.4, 0.825, 1.28};
  const std::vector<double> g_inv{-0.0285, -0.0641, -0.1667, 1.0, 0.1765, 0.362, 0.2797};
  for (std::size_t i = 0; i < kD.size(); ++i) {
    EXPECT_NEAR(inverse.params().thresholds[i], d_inv[i], 5e-5) << "i = " << i;
    EXPECT_NEAR(inverse.params().weights[i], g_inv[i], 5e-5) << "i = " << i;
  }
  double worst = 0.0;  // misc_check.py: 8.9e-16 on y in [-3, 3], 1001 points
  for (int k = 0; k <= 1000; ++k) {
    const double y = -3.0 + 6.0 * k / 1000.0;
    worst = std::max(worst, std::abs(inverse(map(y)) - y));
  }
  EXPECT_LT(worst, 1e-12);
  // The inverse of the inverse is the map itself.
  const auto back = inverse.inverse();
  for (std::size_t i = 0; i < kD.size(); ++i) {
    EXPECT_NEAR(back.params().thresholds[i], kD[i], 1e-13);
    EXPECT_NEAR(back.params().weights[i], kG[i], 1e-13);
  }
}

TEST(DeadZoneSuperposition, ValuesByHandAndValidation) {
  const DeadZoneSuperposition map({kD, kG});
  // S(1) = 1 - 0.15 (1 - 0.4) - 0.2 (1 - 0.9); S(-1) = -1 + 0.2 (-1 + 0.3) + 0.1 (-1 + 0.8).
  EXPECT_NEAR(map(1.0), 0.89, 1e-15);
  EXPECT_NEAR(map(-1.0), -1.16, 1e-15);
  EXPECT_NEAR(map(0.2), 0.2, 1e-15);
  EXPECT_TRUE(map.is_invertible());
  const DeadZoneSuperposition falling({{0, 1}, {1, -1.5}});
  EXPECT_FALSE(falling.is_invertible());
  EXPECT_HYST_ERROR(falling.inverse(), "partial sum g[0] + ... + g[1] = -0.5 must be > 0");
  EXPECT_HYST_ERROR(DeadZoneSuperposition({{-1, 1}, {1, 1}}), "must contain 0");
  EXPECT_HYST_ERROR(DeadZoneSuperposition({{0, 1, 0.5}, {1, 1, 1}}),
                    "dead-zone threshold d[2] = 0.5 must be > d[1] = 1");
}

TEST(ModifiedPrandtlIshlinskii, IsTheDeadZoneMapOfThePiOutput) {
  const auto model = reference_modified_pi();
  const PrandtlIshlinskii pi(model.params().pi);
  const DeadZoneSuperposition map(model.params().dead_zone);
  auto state = model.initial_state();
  auto pi_state = pi.initial_state();
  for (double v : test::pi_check_signal())
    ASSERT_EQ(model.step(state, v), -0.4 + map(pi.step(pi_state, v)));
}

TEST(ModifiedPrandtlIshlinskii, InverseRoundTripsTo1e12) {
  const auto model = reference_modified_pi();
  const InverseModifiedPrandtlIshlinskii inverse(model);
  // P^-1[P[v]] = v after an arbitrary history, with the consistent inverse state.
  auto forward = model.initial_state();
  for (double v : test::random_walk(700, 23, 2.0, 0.3))
    model.step(forward, v);
  auto inverse_state = inverse.state_consistent_with(forward);
  double worst = 0.0;
  for (double v : test::pi_check_signal())
    worst = std::max(worst, std::abs(inverse.step(inverse_state, model.step(forward, v)) - v));
  EXPECT_LT(worst, 1e-12);
  // P[P^-1[y]] = y from the virgin states.
  auto plant = model.initial_state();
  auto compensator = inverse.initial_state();
  worst = 0.0;
  for (double y : test::pi_check_signal())
    worst = std::max(worst, std::abs(model.step(plant, inverse.step(compensator, y)) - y));
  EXPECT_LT(worst, 1e-12);
}

TEST(ModifiedPrandtlIshlinskii, InverseReportsLimitsAndRejectsNonInvertibleModels) {
  const auto model = reference_modified_pi();
  const InverseModifiedPrandtlIshlinskii limited(model, {.input_min = -1, .input_max = 1});
  auto state = limited.initial_state();
  const auto sample = limited.solve(state, 50.0);
  EXPECT_EQ(sample.status, InverseStatus::above_range);
  EXPECT_EQ(sample.input, 1.0);
  auto params = model.params();
  params.dead_zone.weights[4] = -1.2;  // slope 1 - 1.2 < 0 above d = 0.4
  const ModifiedPrandtlIshlinskii bad(params);
  EXPECT_FALSE(bad.is_invertible());
  EXPECT_HYST_ERROR(InverseModifiedPrandtlIshlinskii{bad}, "must be > 0 for the inverse to exist");
  params = model.params();
  params.pi.thresholds[0] = 0.1;
  try {
    ModifiedPrandtlIshlinskii{params};
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "pi.thresholds[0]");
  }
}

TEST(ModifiedPrandtlIshlinskii, FitRecoversAModelWithTheSameGrids) {
  // Truth: S' with g'_0 = 1 and positive slopes on a chosen grid, S = S'^-1; fitted with the
  // same thresholds and offset the equation-error problem is exact.
  const DeadZoneSuperposition inverse_map({{-0.9, -0.4, 0.0, 0.5, 1.0}, {0.4, 0.3, 1.0, 0.5, 1.5}});
  const std::vector<double> r{0, 0.2, 0.4, 0.6, 0.8};
  const ModifiedPrandtlIshlinskii truth(
      {.pi = {.thresholds = r, .weights = {0.6, 0.3, 0.2, 0.1, 0.05}, .offset = 0.05},
       .dead_zone = inverse_map.inverse().params(),
       .offset = 0.3});
  const auto v = test::random_walk(4000, 29, 2.0, 0.15);
  auto state = truth.initial_state();
  const auto y = simulate(truth, state, v);
  const auto fit =
      fit_modified_prandtl_ishlinskii(v, y,
                                      {.thresholds = r,
                                       .dead_zone_thresholds = inverse_map.params().thresholds,
                                       .output_offset = 0.3,
                                       .min_weight = 1e-9,
                                       .validate_fraction = 0.25});
  EXPECT_EQ(fit.report.model, "modified_pi");
  EXPECT_LT(fit.report.fit.rmse, 1e-7);
  EXPECT_LT(fit.report.validation->rmse, 1e-7);
  EXPECT_TRUE(fit.model.is_invertible());

  // Default grids on an asymmetric loop: the fit is invertible by construction and explains it.
  const auto generic = fit_modified_prandtl_ishlinskii(v, y, {.operators = 8, .dead_zones = 4});
  EXPECT_TRUE(generic.model.is_invertible());
  EXPECT_LT(generic.report.fit.nrmse_percent, 2);
}

TEST(ModifiedPrandtlIshlinskii, OutputLimitsClampByHand) {
  // Identity PI (y = v) and identity dead zone, offset 0.1: y = clamp(v + 0.1, -0.5, 0.7).
  const ModifiedPrandtlIshlinskii model({.pi = {.thresholds = {0}, .weights = {1}},
                                         .dead_zone = {{0}, {1}},
                                         .offset = 0.1,
                                         .output_min = -0.5,
                                         .output_max = 0.7});
  auto state = model.initial_state();
  EXPECT_NEAR(model.step(state, 0.2), 0.3, 1e-15);
  EXPECT_EQ(model.step(state, 2.0), 0.7);
  EXPECT_EQ(model.step(state, -3.0), -0.5);
  EXPECT_HYST_ERROR(ModifiedPrandtlIshlinskii({.pi = {.thresholds = {0}, .weights = {1}},
                                               .dead_zone = {{0}, {1}},
                                               .output_min = 1,
                                               .output_max = 1}),
                    "output_min = 1 must be < output_max = 1");
}

TEST(ModifiedPrandtlIshlinskii, FitOnHalfTheRangeStaysBoundedOnTheFullRange) {
  // A saturating record, y = tanh(2 PI[v]) (a PI model with positive weights followed by tanh,
  // not a modified PI model), fitted on the first half of a sweep whose amplitude grows from 0.1
  // to 0.55 and predicted over the whole sweep (amplitude up to 1, twice the fitted input range).
  // The prediction must stay within 3x the record's output range, and the fitted limits are the
  // fit part's output extremes.
  const PrandtlIshlinskii pi({.thresholds = {0, 0.2, 0.4, 0.6}, .weights = {0.8, 0.4, 0.3, 0.2}});
  std::vector<double> v(4000);
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double t = static_cast<double>(k);
    v[k] = (0.1 + 0.9 * t / 4000.0) * std::sin(2.0 * std::numbers::pi * t / 200.0);
  }
  auto pi_state = pi.initial_state();
  std::vector<double> y = simulate(pi, pi_state, v);
  for (double& value : y)
    value = std::tanh(2.0 * value);
  const std::span<const double> fit_v(v.data(), 2000), fit_y(y.data(), 2000);
  const auto [fit_min, fit_max] = std::minmax_element(fit_y.begin(), fit_y.end());
  const auto fit = fit_modified_prandtl_ishlinskii(fit_v, fit_y);
  EXPECT_EQ(fit.model.params().output_min, *fit_min);
  EXPECT_EQ(fit.model.params().output_max, *fit_max);
  auto state = fit.initial_state;
  const auto predicted = simulate(fit.model, state, v);
  const auto [y_min, y_max] = std::minmax_element(y.begin(), y.end());
  double worst = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k)
    worst = std::max(worst, std::abs(predicted[k] - y[k]));
  EXPECT_LT(worst, 3.0 * (*y_max - *y_min));
}

}  // namespace
}  // namespace hyst
