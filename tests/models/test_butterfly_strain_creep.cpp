// Butterfly strain model with creep: the model without creep is the butterfly model, a step
// response by hand (one lag's exponential through the map), the same physical response at another
// sample time, the leakage charge that strains nothing, preview, the periodic state, validation
// and the inverse on a monotone branch.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_butterfly_strain_creep.hpp"
#include "hyst/models/butterfly_strain_creep.hpp"

namespace hyst {
namespace {

// Three levels on [-1, 1] (thresholds -2/3, 0, 2/3), y = 0.1 v + P + 0.3 P^2 (no vertex for
// |P| <= 1.4: monotone), one lag of 0.5 s on the play of threshold 0 (v itself).
ButterflyStrainCreep::Params one_lag() {
  ButterflyStrainCreep::Params p;
  p.butterfly.polarisation.everett = {
      .levels = 3, .lower = -1.0, .upper = 1.0, .weights = {0.1, 0.0, 0.1, 0.7, 0.0, 0.1}};
  p.butterfly.field_coefficient = 0.1;
  p.butterfly.polarisation_coefficients = {1.0, 0.3};
  p.creep_thresholds = {0.0};
  p.time_constants = {0.5};
  p.creep_weights = {0.2};
  p.sample_time = 0.01;
  return p;
}

TEST(ButterflyStrainCreep, WithoutCreepIsTheButterflyModel) {
  auto p = one_lag();
  p.creep_weights = {0.0};
  const ButterflyStrainCreep model(p);
  const ButterflyStrain butterfly(p.butterfly);
  auto state = model.initial_state();
  auto reference = butterfly.initial_state();
  for (double v : test::random_walk(2000, 3, 1.2))
    ASSERT_EQ(model.step(state, v), butterfly.step(reference, v)) << "v = " << v;
}

TEST(ButterflyStrainCreep, StepResponseByHand) {
  const ButterflyStrainCreep model(one_lag());
  auto state = model.initial_state();
  // A step to v = 1 (positive saturation, P_s = 1) at sample 1: the lag of v reaches
  // 1 - exp(-k Ts / tau) after k samples, P = 1 + 0.2 (1 - exp(-k 0.01 / 0.5)).
  for (int k = 1; k <= 300; ++k) {
    const double y = model.step(state, 1.0);
    const double P = 1.0 + 0.2 * (1.0 - std::exp(-k * 0.01 / 0.5));
    ASSERT_NEAR(y, 0.1 + P + 0.3 * P * P, 1e-13) << "sample " << k;
    ASSERT_NEAR(model.polarisation(state), P, 1e-13);
  }
}

TEST(ButterflyStrainCreep, TheSameResponseAtAnotherSampleTime) {
  const ButterflyStrainCreep coarse(one_lag());
  const ButterflyStrainCreep fine = coarse.at_sample_time(0.0025);
  auto coarse_state = coarse.initial_state();
  auto fine_state = fine.initial_state();
  // A staircase held for 0.2 s per level: the lags are discretised exactly, so the two agree at
  // every coarse sample.
  for (int level = 0; level < 12; ++level) {
    const double v = std::sin(0.9 * level);
    for (int k = 0; k < 20; ++k) {
      double y_fine = 0.0;
      for (int f = 0; f < 4; ++f)
        y_fine = fine.step(fine_state, v);
      ASSERT_NEAR(coarse.step(coarse_state, v), y_fine, 1e-12) << "level " << level;
    }
  }
}

TEST(ButterflyStrainCreep, TheLeakageChargeIsMeasuredButStrainsNothing) {
  auto p = one_lag();
  p.leakage_conductance = 0.03;
  p.leakage_current = -0.01;
  const ButterflyStrainCreep leaky(p);
  const ButterflyStrainCreep tight(one_lag());
  auto leaky_state = leaky.initial_state();
  auto tight_state = tight.initial_state();
  double charge = 0.0;
  for (double v : test::random_walk(1500, 5, 1.2)) {
    ASSERT_DOUBLE_EQ(leaky.step(leaky_state, v), tight.step(tight_state, v));
    charge += 0.01 * (0.03 * v - 0.01);
    ASSERT_NEAR(leaky.measured_polarisation(leaky_state) - leaky.polarisation(leaky_state), charge,
                1e-12);
  }
}

TEST(ButterflyStrainCreep, PreviewIsTheNextStep) {
  auto p = one_lag();
  p.creep_thresholds = {0.0, 0.4};
  p.time_constants = {0.05, 0.5};
  p.creep_weights = {0.1, 0.05, 0.2, 0.02};
  p.leakage_current = 0.2;
  const ButterflyStrainCreep model(p);
  auto state = model.initial_state();
  for (double v : test::random_walk(1000, 9, 1.3)) {
    const double previewed = model.preview(state, v);
    const double previewed_P = model.preview_polarisation(state, v);
    ASSERT_NEAR(previewed, model.step(state, v), 1e-12);  // the same sums in another order
    ASSERT_NEAR(previewed_P, model.polarisation(state), 1e-12);
  }
}

TEST(ButterflyStrainCreep, PeriodicStateRepeatsItself) {
  const ButterflyStrainCreep model(one_lag());
  std::vector<double> period;
  for (int k = 0; k < 400; ++k)
    period.push_back(1.2 * std::sin(2.0 * std::numbers::pi * k / 400.0));
  auto state = model.periodic_state(period);
  const auto first = simulate(model, state, period);
  const auto second = simulate(model, state, period);
  for (std::size_t k = 0; k < period.size(); ++k)
    ASSERT_NEAR(first[k], second[k], 1e-12) << "sample " << k;
}

TEST(ButterflyStrainCreep, InvalidParametersNameTheirField) {
  auto p = one_lag();
  p.creep_thresholds = {0.1};
  try {
    ButterflyStrainCreep{p};
    FAIL() << "a first creep threshold other than 0 was accepted";
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "creep_thresholds[0]");
    EXPECT_NE(std::string(error.what()).find("creep_thresholds[0]"), std::string::npos)
        << error.what();
  }
  p = one_lag();
  p.creep_weights = {-0.1};
  try {
    ButterflyStrainCreep{p};
    FAIL() << "a negative creep weight was accepted";
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "creep_weights[0]");
  }
  p = one_lag();
  p.sample_time = 0.0;
  EXPECT_HYST_ERROR(ButterflyStrainCreep{p}, "sample time");
  p = one_lag();
  p.butterfly.polarisation_coefficients = {};
  EXPECT_HYST_ERROR(ButterflyStrainCreep{p}, "polarisation coefficients");
}

TEST(ButterflyStrainCreep, InverseReproducesTargetsOnAMonotoneBranch) {
  const ButterflyStrainCreep model(one_lag());
  const InverseButterflyStrainCreep inverse(model, {-1.2, 1.2});
  auto forward = model.initial_state();
  auto inverse_state = model.initial_state();
  for (double v : test::random_walk(2000, 11, 1.1, 0.05)) {
    const double target = model.step(forward, v);
    const auto solved = inverse.solve(inverse_state, target);
    ASSERT_EQ(solved.status, InverseStatus::ok);
    ASSERT_NEAR(model.polarisation(inverse_state), model.polarisation(forward), 1e-6);
  }
}

TEST(ButterflyStrainCreep, InverseRefusesAcrossTheVertex) {
  auto p = one_lag();
  p.butterfly.field_coefficient = 0.0;
  p.butterfly.polarisation_coefficients = {0.0, 1.0};  // y = P^2: the vertex at P = 0
  const ButterflyStrainCreep model(p);
  const InverseButterflyStrainCreep inverse(model, {-1.2, 1.2});
  auto state = model.initial_state();
  const auto solved = inverse.solve(state, 0.5);
  EXPECT_EQ(solved.status, InverseStatus::not_invertible);
  EXPECT_FALSE(inverse.invertible_from(model.initial_state()));
}

}  // namespace
}  // namespace hyst
