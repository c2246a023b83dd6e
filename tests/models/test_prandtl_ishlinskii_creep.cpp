// PI with creep: the creep elements against the closed-form step response of a first-order lag,
// the PI when the creep weights are 0, the logarithmic creep law against log10(t / t0), rest
// states, the exact inverse, and validation.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"

namespace hyst {
namespace {

PrandtlIshlinskiiCreep::Params two_plays_two_lags() {
  return {.thresholds = {0.0, 0.5},
          .weights = {1.0, 0.5},
          .time_constants = {0.05, 0.5},
          .creep_weights = {0.2, 0.1, 0.05, 0.3},  // c_00, c_01 (tau 0.05), c_10, c_11 (tau 0.5)
          .sample_time = 0.01,
          .offset = 0.25};
}

TEST(PrandtlIshlinskiiCreep, StepResponseIsTheLagsClosedForm) {
  const PrandtlIshlinskiiCreep model(two_plays_two_lags());
  auto state = model.initial_state();
  const double v = 2.0;
  // After the step the plays sit at w_0 = 2 and w_1 = 2 - 0.5; each lag approaches its play as
  // 1 - exp(-t / tau) with t = k Ts (the input of sample k acts from t_{k-1} on).
  for (int k = 1; k <= 400; ++k) {
    const double t = k * 0.01;
    const double lag_fast = 1.0 - std::exp(-t / 0.05);
    const double lag_slow = 1.0 - std::exp(-t / 0.5);
    const double expected = 0.25 + 1.0 * 2.0 + 0.5 * 1.5 + 0.2 * 2.0 * lag_fast +
                            0.1 * 1.5 * lag_fast + 0.05 * 2.0 * lag_slow + 0.3 * 1.5 * lag_slow;
    const double y = model.step(state, v);
    ASSERT_NEAR(y, expected, 1e-13) << "sample " << k;
    EXPECT_NEAR(model.output(state), y, 1e-14);
  }
}

TEST(PrandtlIshlinskiiCreep, WithoutCreepWeightsItIsThePi) {
  auto params = two_plays_two_lags();
  params.creep_weights.assign(4, 0.0);
  const PrandtlIshlinskiiCreep model(params);
  const PrandtlIshlinskii pi({params.thresholds, params.weights, params.offset});
  const auto input = test::pi_check_signal();
  auto state = model.initial_state();
  auto pi_state = pi.initial_state();
  const auto y = simulate(model, state, input);
  const auto y_pi = simulate(pi, pi_state, input);
  for (std::size_t k = 0; k < input.size(); ++k)
    ASSERT_NEAR(y[k], y_pi[k], 1e-13) << "sample " << k;
}

TEST(PrandtlIshlinskiiCreep, RestStateStaysAtRestAndAStepSettlesAtTheFullGain) {
  const PrandtlIshlinskiiCreep model(two_plays_two_lags());
  auto state = model.state_at_rest(1.5);
  const double at_rest = model.output(state);
  // At rest every element sits at 1.5: 0.25 + (1 + 0.5 + 0.2 + 0.1 + 0.05 + 0.3) 1.5.
  EXPECT_NEAR(at_rest, 0.25 + 2.15 * 1.5, 1e-14);
  for (int k = 0; k < 100; ++k)
    ASSERT_NEAR(model.step(state, 1.5), at_rest, 1e-14);
  // From rest at 0, a step to 1 settles at y_off + sum_j (p_j + sum_i c_ij) P_rj[1].
  state = model.initial_state();
  double y = 0.0;
  for (int k = 0; k < 20000; ++k)
    y = model.step(state, 1.0);
  EXPECT_NEAR(y, 0.25 + (1.0 + 0.2 + 0.05) * 1.0 + (0.5 + 0.1 + 0.3) * 0.5, 1e-12);
}

TEST(PrandtlIshlinskiiCreep, PeriodicStateIsWhereManyPeriodsConverge) {
  const PrandtlIshlinskiiCreep model(two_plays_two_lags());
  std::vector<double> period(150);
  for (std::size_t k = 0; k < period.size(); ++k)
    period[k] = 0.3 + 1.2 * std::sin(2 * std::numbers::pi * static_cast<double>(k + 1) / 150.0) +
                0.4 * std::sin(6 * std::numbers::pi * static_cast<double>(k + 1) / 150.0);
  const auto periodic = model.periodic_state(period);
  // One period returns to it.
  auto state = periodic;
  simulate(model, state, period);
  for (std::size_t ij = 0; ij < state.creep.size(); ++ij)
    EXPECT_NEAR(state.creep[ij], periodic.creep[ij], 1e-13);
  EXPECT_EQ(state.play, periodic.play);
  // A second algorithm: run 400 periods (1.5 s each, 3 time constants of the slow lag per 1.5 s).
  auto run_in = model.initial_state();
  for (int p = 0; p < 400; ++p)
    simulate(model, run_in, period);
  for (std::size_t ij = 0; ij < state.creep.size(); ++ij)
    EXPECT_NEAR(run_in.creep[ij], periodic.creep[ij], 1e-12);
  EXPECT_HYST_ERROR(model.periodic_state({}), "PI with creep periodic input");
}

TEST(PrandtlIshlinskiiCreep, LogarithmicCreepLawFollowsLog10OfTime) {
  const double gamma = 0.02;
  const double t0 = 0.1;
  const double ts = 1e-3;
  const PrandtlIshlinskii::Params pi{{0.0, 0.5}, {2.0, 1.0}, 0.0};
  for (std::size_t per_decade : {2U, 4U}) {
    const PrandtlIshlinskiiCreep model(pi_logarithmic_creep(pi, gamma, t0, 4, per_decade, ts));
    EXPECT_EQ(model.lags(), 4 * per_decade + 1);
    auto state = model.initial_state();
    // The instantaneous response to a step to 2 from rest: the PI's 2 * 2 + 1 * 1.5 = 5.5.
    const double y0 = 5.5;
    for (std::size_t k = 1; k <= 1000000; ++k) {
      const double y = model.step(state, 2.0);
      const double t = static_cast<double>(k) * ts;
      if (t >= 3 * t0 && t <= t0 * 1000 && k % 97 == 0) {
        const double law = y0 * (1.0 + gamma * std::log10(t / t0));
        ASSERT_NEAR(y, law, 0.05 * gamma * y0) << "t = " << t << ", " << per_decade << "/decade";
      }
    }
  }
}

TEST(PrandtlIshlinskiiCreep, LogSpacedTimeConstants) {
  const auto tau = log_spaced_time_constants(0.01, 10.0, 4);
  ASSERT_EQ(tau.size(), 4U);
  EXPECT_NEAR(tau[0], 0.01, 1e-15);
  EXPECT_NEAR(tau[1], 0.1, 1e-14);
  EXPECT_NEAR(tau[2], 1.0, 1e-13);
  EXPECT_EQ(tau[3], 10.0);
  EXPECT_EQ(log_spaced_time_constants(0.5, 0.5, 1), std::vector<double>{0.5});
  EXPECT_HYST_ERROR(log_spaced_time_constants(0.0, 1.0, 3), "0 < shortest <= longest");
  EXPECT_HYST_ERROR(log_spaced_time_constants(1.0, 1.0, 2), "count = 2");
}

// The inverse gives back the input of a random walk from the model's output, sample by sample.
void expect_inverse_reproduces_a_random_walk(const PrandtlIshlinskiiCreep& model,
                                             std::uint64_t seed) {
  const InversePrandtlIshlinskiiCreep inverse(model);
  auto inverse_state = inverse.initial_state();
  auto check_state = model.initial_state();
  const auto input = test::random_walk(3000, seed, 2.0);
  auto probe = model.initial_state();
  const auto targets = simulate(model, probe, input);
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const auto sample = inverse.solve(inverse_state, targets[k]);
    ASSERT_EQ(sample.status, InverseStatus::ok);
    ASSERT_NEAR(sample.input, input[k], 1e-9) << "sample " << k;
    ASSERT_NEAR(model.step(check_state, sample.input), targets[k], 1e-10);
  }
}

TEST(PrandtlIshlinskiiCreep, InverseReproducesTargetsExactly) {
  expect_inverse_reproduces_a_random_walk(PrandtlIshlinskiiCreep(two_plays_two_lags()), 7);
}

// Hand calculation: after k samples of a held input v from the virgin state, the leakage is
// k Ts (g v + i0) on top of the model without leakage.
TEST(PrandtlIshlinskiiCreep, LeakageIsTheIntegratedConductionAndOffsetCurrent) {
  auto params = two_plays_two_lags();
  const PrandtlIshlinskiiCreep without(params);
  params.leakage_conductance = 0.02;
  params.leakage_current = -0.005;
  const PrandtlIshlinskiiCreep with(params);
  EXPECT_TRUE(with.has_leakage());
  EXPECT_FALSE(without.has_leakage());
  auto state = with.initial_state();
  auto reference = without.initial_state();
  for (int k = 1; k <= 500; ++k) {
    const double y = with.step(state, 1.5);
    const double y0 = without.step(reference, 1.5);
    ASSERT_NEAR(y - y0, k * 0.01 * (0.02 * 1.5 - 0.005), 1e-12) << "sample " << k;
  }
  EXPECT_NEAR(with.output(state) - without.output(reference), 500 * 0.01 * 0.025, 1e-12);
  // The periodic state counts the drift from the start of the period.
  EXPECT_EQ(with.periodic_state(test::random_walk(200, 3, 1.0)).leakage, 0.0);
  // At another sample time the rates per second stay: the same drift after the same time.
  const auto coarse = with.at_sample_time(0.05);
  auto coarse_state = coarse.initial_state();
  for (int k = 0; k < 100; ++k)
    coarse.step(coarse_state, 1.5);
  EXPECT_NEAR(coarse_state.leakage, state.leakage, 1e-12);
}

TEST(PrandtlIshlinskiiCreep, InverseWithLeakageReproducesTargets) {
  auto params = two_plays_two_lags();
  params.leakage_conductance = 0.05;
  params.leakage_current = 0.01;
  expect_inverse_reproduces_a_random_walk(PrandtlIshlinskiiCreep(params), 11);
}

TEST(PrandtlIshlinskiiCreep, LimitedInverseReportsAndKeepsTracking) {
  const PrandtlIshlinskiiCreep model(two_plays_two_lags());
  const InversePrandtlIshlinskiiCreep inverse(model, {.input_min = -1.0, .input_max = 1.0});
  auto state = inverse.initial_state();
  auto forward = model.initial_state();
  const auto high = inverse.solve(state, 10.0);
  EXPECT_EQ(high.status, InverseStatus::above_range);
  EXPECT_EQ(high.input, 1.0);
  model.step(forward, high.input);
  // After the limited sample the inverse continues from the limited history: reachable targets
  // are met exactly.
  auto probe = forward;
  const double reachable = model.step(probe, 0.3);
  const auto next = inverse.solve(state, reachable);
  EXPECT_EQ(next.status, InverseStatus::ok);
  EXPECT_NEAR(next.input, 0.3, 1e-12);
}

TEST(PrandtlIshlinskiiCreep, ValidationNamesTheParameter) {
  auto params = two_plays_two_lags();
  params.creep_weights[3] = -0.1;
  EXPECT_HYST_ERROR(PrandtlIshlinskiiCreep{params}, "PI with creep creep weight c[3] = -0.1");
  params = two_plays_two_lags();
  params.time_constants = {0.5, 0.05};
  EXPECT_HYST_ERROR(PrandtlIshlinskiiCreep{params}, "tau[1] = 0.05 must be > tau[0] = 0.5");
  params = two_plays_two_lags();
  params.creep_weights.pop_back();
  EXPECT_HYST_ERROR(PrandtlIshlinskiiCreep{params}, "has 3 creep weights but needs 4");
  params = two_plays_two_lags();
  params.sample_time = 0.0;
  EXPECT_HYST_ERROR(PrandtlIshlinskiiCreep{params}, "sample time Ts = 0 must be > 0");
  params = two_plays_two_lags();
  params.thresholds = {0.1, 0.5};
  EXPECT_HYST_ERROR(PrandtlIshlinskiiCreep{params}, "PI with creep: PI threshold");
  const PrandtlIshlinskiiCreep model(two_plays_two_lags());
  EXPECT_HYST_ERROR(model.make_state({0.0, 0.0}, {0.0}), "PI with creep state z");
  EXPECT_HYST_ERROR(pi_logarithmic_creep({{0.0}, {1.0}, 0.0}, -0.1, 1.0, 3, 2, 0.01),
                    "logarithmic creep gamma = -0.1 must be >= 0");
  auto leaky = two_plays_two_lags();
  leaky.leakage_current = std::nan("");
  EXPECT_HYST_ERROR(PrandtlIshlinskiiCreep{leaky}, "leakage current");
}

}  // namespace
}  // namespace hyst
