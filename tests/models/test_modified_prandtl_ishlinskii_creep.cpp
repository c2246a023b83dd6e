// Modified PI with creep: its step response against the closed form of the lags through a
// piecewise-linear dead-zone map, the PI with creep when the map is the identity and the modified
// PI when there are no creep weights (second algorithms), the exact inverse, and validation.

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "hyst/models/modified_prandtl_ishlinskii_creep.hpp"

namespace hyst {
namespace {

// Two plays and two lags (q = 0.25), then S(x) = x - 0.5 max(x - 1, 0) + 0.5 min(x + 1, 0):
// slope 1 in [-1, 1], 0.5 outside.
ModifiedPrandtlIshlinskiiCreep::Params two_plays_two_lags_saturating() {
  ModifiedPrandtlIshlinskiiCreep::Params params;
  params.pi_creep = {.thresholds = {0.0, 0.5},
                     .weights = {1.0, 0.5},
                     .time_constants = {0.05, 0.5},
                     .creep_weights = {0.2, 0.1, 0.05, 0.3},
                     .sample_time = 0.01,
                     .offset = 0.25};
  params.dead_zone = {{-1.0, 0.0, 1.0}, {-0.5, 1.0, -0.5}};
  params.offset = -0.1;
  return params;
}

TEST(ModifiedPrandtlIshlinskiiCreep, StepResponseIsTheLagsClosedFormThroughTheMap) {
  const ModifiedPrandtlIshlinskiiCreep model(two_plays_two_lags_saturating());
  auto state = model.initial_state();
  // A step to 0.6: w_0 = 0.6, w_1 = 0.1. The PI with creep answers 0.25 + 0.65 at once and creeps
  // across x = 1, where the map's slope halves.
  for (int k = 1; k <= 300; ++k) {
    const double t = k * 0.01;
    const double lag_fast = 1.0 - std::exp(-t / 0.05);
    const double lag_slow = 1.0 - std::exp(-t / 0.5);
    const double x = 0.25 + 1.0 * 0.6 + 0.5 * 0.1 + 0.2 * 0.6 * lag_fast + 0.1 * 0.1 * lag_fast +
                     0.05 * 0.6 * lag_slow + 0.3 * 0.1 * lag_slow;
    const double shaped = x <= 1.0 ? x : 1.0 + 0.5 * (x - 1.0);
    const double y = model.step(state, 0.6);
    ASSERT_NEAR(y, -0.1 + shaped, 1e-13) << "sample " << k;
    EXPECT_NEAR(model.output(state), y, 1e-14);
  }
}

TEST(ModifiedPrandtlIshlinskiiCreep, IdentityMapIsThePiWithCreep) {
  auto params = two_plays_two_lags_saturating();
  params.dead_zone = {{0.0}, {1.0}};
  params.offset = 0.0;
  const ModifiedPrandtlIshlinskiiCreep model(params);
  const PrandtlIshlinskiiCreep creep(params.pi_creep);
  const auto input = test::pi_check_signal();
  auto state = model.initial_state();
  auto creep_state = creep.initial_state();
  const auto y = simulate(model, state, input);
  const auto y_creep = simulate(creep, creep_state, input);
  for (std::size_t k = 0; k < input.size(); ++k)
    ASSERT_EQ(y[k], y_creep[k]) << "sample " << k;
}

TEST(ModifiedPrandtlIshlinskiiCreep, WithoutCreepWeightsItIsTheModifiedPi) {
  auto params = two_plays_two_lags_saturating();
  params.pi_creep.creep_weights.assign(4, 0.0);
  params.output_min = -0.8;
  params.output_max = 1.2;
  const ModifiedPrandtlIshlinskiiCreep model(params);
  const ModifiedPrandtlIshlinskii modified(
      {{params.pi_creep.thresholds, params.pi_creep.weights, params.pi_creep.offset},
       params.dead_zone,
       params.offset,
       params.output_min,
       params.output_max});
  const auto input = test::random_walk(2000, 3, 2.0);
  auto state = model.initial_state();
  auto modified_state = modified.initial_state();
  const auto y = simulate(model, state, input);
  const auto y_modified = simulate(modified, modified_state, input);
  bool clamped = false;
  for (std::size_t k = 0; k < input.size(); ++k) {
    ASSERT_NEAR(y[k], y_modified[k], 1e-13) << "sample " << k;
    clamped = clamped || y[k] == -0.8 || y[k] == 1.2;
  }
  EXPECT_TRUE(clamped) << "the limits should act on this input";
}

TEST(ModifiedPrandtlIshlinskiiCreep, OtherSampleTimeAndPeriodicState) {
  const ModifiedPrandtlIshlinskiiCreep model(two_plays_two_lags_saturating());
  const auto slower = model.at_sample_time(0.1);
  EXPECT_EQ(slower.params().pi_creep.sample_time, 0.1);
  EXPECT_NEAR(slower.hysteresis_creep().decay()[0], std::exp(-0.1 / 0.05), 1e-15);
  // The periodic state returns to itself after one period.
  std::vector<double> period;
  for (int k = 0; k < 200; ++k)
    period.push_back(1.5 * std::sin(2.0 * 3.141592653589793 * k / 200.0));
  auto state = model.periodic_state(period);
  const auto start = state;
  simulate(model, state, period);
  for (std::size_t i = 0; i < state.creep.size(); ++i)
    EXPECT_NEAR(state.creep[i], start.creep[i], 1e-12) << "lag " << i;
}

TEST(ModifiedPrandtlIshlinskiiCreep, InverseReproducesTargetsExactly) {
  const ModifiedPrandtlIshlinskiiCreep model(two_plays_two_lags_saturating());
  ASSERT_TRUE(model.is_invertible());
  const InverseModifiedPrandtlIshlinskiiCreep inverse(model);
  auto inverse_state = inverse.initial_state();
  auto check_state = model.initial_state();
  const auto input = test::random_walk(3000, 11, 2.0);
  auto probe = model.initial_state();
  const auto targets = simulate(model, probe, input);
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const auto sample = inverse.solve(inverse_state, targets[k]);
    ASSERT_EQ(sample.status, InverseStatus::ok);
    ASSERT_NEAR(sample.input, input[k], 1e-9) << "sample " << k;
    ASSERT_NEAR(model.step(check_state, sample.input), targets[k], 1e-10);
  }
}

TEST(ModifiedPrandtlIshlinskiiCreep, LimitedInverseReportsAndKeepsTracking) {
  const ModifiedPrandtlIshlinskiiCreep model(two_plays_two_lags_saturating());
  const InverseModifiedPrandtlIshlinskiiCreep inverse(model, {.input_min = -1.0, .input_max = 1.0});
  auto state = inverse.initial_state();
  auto forward = model.initial_state();
  const auto high = inverse.solve(state, 10.0);
  EXPECT_EQ(high.status, InverseStatus::above_range);
  EXPECT_EQ(high.input, 1.0);
  model.step(forward, high.input);
  auto probe = forward;
  const double reachable = model.step(probe, 0.3);
  const auto next = inverse.solve(state, reachable);
  EXPECT_EQ(next.status, InverseStatus::ok);
  EXPECT_NEAR(next.input, 0.3, 1e-12);
}

TEST(ModifiedPrandtlIshlinskiiCreep, ValidationNamesThePartAndTheParameter) {
  auto params = two_plays_two_lags_saturating();
  params.pi_creep.creep_weights[3] = -0.1;
  EXPECT_HYST_ERROR(ModifiedPrandtlIshlinskiiCreep{params},
                    "modified PI with creep pi_creep: PI with creep creep weight c[3] = -0.1");
  try {
    ModifiedPrandtlIshlinskiiCreep{params};
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "pi_creep.creep_weights[3]");
  }
  params = two_plays_two_lags_saturating();
  params.dead_zone.thresholds = {-1.0, 0.5, 1.0};
  EXPECT_HYST_ERROR(ModifiedPrandtlIshlinskiiCreep{params}, "modified PI with creep dead_zone:");
  params = two_plays_two_lags_saturating();
  params.output_min = 1.0;
  params.output_max = 0.0;
  EXPECT_HYST_ERROR(ModifiedPrandtlIshlinskiiCreep{params},
                    "modified PI with creep output_min = 1 must be < output_max = 0");
  params = two_plays_two_lags_saturating();
  params.offset = std::nan("");
  EXPECT_HYST_ERROR(ModifiedPrandtlIshlinskiiCreep{params}, "offset = nan is not finite");
  params = two_plays_two_lags_saturating();
  params.pi_creep.leakage_current = 0.1;  // a drift would pass through the dead zones
  EXPECT_HYST_ERROR(ModifiedPrandtlIshlinskiiCreep{params}, "use pi_creep");
  // A map that turns back is not invertible, and the inverse says which partial sum.
  params = two_plays_two_lags_saturating();
  params.dead_zone.weights = {-0.5, 1.0, -1.5};
  const ModifiedPrandtlIshlinskiiCreep folding(params);
  EXPECT_FALSE(folding.is_invertible());
  EXPECT_HYST_ERROR(InverseModifiedPrandtlIshlinskiiCreep{folding}, "partial sum");
}

}  // namespace
}  // namespace hyst
