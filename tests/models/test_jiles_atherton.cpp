// Jiles-Atherton model: Langevin function, both variants, non-negative susceptibility, no blow-up
// at high drive, minor loops, initial states, tangent, convergence and rate independence.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/models/jiles_atherton.hpp"

namespace hyst {
namespace {

JilesAtherton::Params params(JilesAthertonVariant variant) {
  JilesAtherton::Params p;  // M_s = 1.6e6, a = 1100, k = 400, c = 0.2, alpha = 1.6e-3
  p.variant = variant;
  return p;
}

// A major-loop sweep with asymmetric minor loops: any H(t), not only symmetric sweeps.
std::vector<double> field_history() {
  std::vector<double> h;
  auto ramp = [&](double to, int n) {
    const double from = h.empty() ? 0.0 : h.back();
    for (int i = 1; i <= n; ++i)
      h.push_back(from + (to - from) * i / n);
  };
  ramp(5000, 200);
  ramp(-5000, 400);
  ramp(5000, 400);
  ramp(1000, 100);
  ramp(2500, 60);
  ramp(1000, 60);
  ramp(-300, 80);
  ramp(700, 60);
  ramp(-5000, 300);
  return h;
}

const JilesAthertonVariant kVariants[] = {JilesAthertonVariant::original,
                                          JilesAthertonVariant::venkataraman};

TEST(JilesAtherton, LangevinSeriesJoinsTheClosedForm) {
  for (double x : {1e-3, 1e-2}) {
    const double closed = 1.0 / std::tanh(x) - 1.0 / x;
    EXPECT_NEAR(detail::langevin(x * (1 - 1e-12)), closed, 1e-12);  // cancellation in closed
    const double closed_derivative = 1.0 / (x * x) - 1.0 / (std::sinh(x) * std::sinh(x));
    EXPECT_NEAR(detail::langevin_derivative(x * (1 - 1e-12)), closed_derivative, 1e-8);
  }
  EXPECT_EQ(detail::langevin(0.0), 0.0);
  EXPECT_NEAR(detail::langevin(50.0), 1.0 - 1.0 / 50.0, 1e-15);
}

TEST(JilesAtherton, MajorLoopSaturatesAndSusceptibilityStaysNonNegative) {
  for (auto variant : kVariants) {
    const JilesAtherton model(params(variant));
    auto state = model.initial_state();
    double previous_b = model.flux_density(state), previous_h = 0.0;
    double b_max = 0.0;
    for (double h : field_history()) {
      const double b = model.step(state, h);
      // dB/dH >= mu0 everywhere: no negative differential susceptibility after reversals.
      EXPECT_GE((b - previous_b) / (h - previous_h), kMu0 * (1.0 - 1e-9)) << to_string(variant);
      EXPECT_GE(model.susceptibility(state, 1.0), 0.0);
      EXPECT_GE(model.susceptibility(state, -1.0), 0.0);
      b_max = std::max(b_max, b);
      previous_b = b;
      previous_h = h;
    }
    EXPECT_LT(state.magnetisation, 0.0);  // ends at -5000 A/m
    EXPECT_LT(b_max, kMu0 * (5000 + 1.6e6));
    EXPECT_GT(b_max, 1.0) << to_string(variant);
  }
}

TEST(JilesAtherton, NoBlowUpAtHighDrive) {
  for (auto variant : kVariants) {
    auto p = params(variant);
    p.alpha = 1.9e-3;  // alpha M_s / (3 a) = 0.92: close to the limit
    const JilesAtherton model(p);
    auto state = model.initial_state();
    for (double h : {1e6, -1e6, 1e6, 0.0}) {
      const double b = model.step(state, h);
      EXPECT_TRUE(std::isfinite(b));
      EXPECT_LE(std::abs(state.magnetisation), p.ms * (1 + 1e-9)) << to_string(variant);
    }
  }
}

TEST(JilesAtherton, ConvergesToFineStepReferenceAndIsRateIndependent) {
  for (auto variant : kVariants) {
    auto p = params(variant);
    const JilesAtherton model(p);  // the default integration (RK4 under error control)
    p.max_field_step = 0.5;
    const JilesAtherton fine(p);
    auto s = model.initial_state(), sf = fine.initial_state(), slow = model.initial_state();
    double max_err = 0.0, previous = 0.0;
    for (double h : field_history()) {
      const double b = model.step(s, h);
      max_err = std::max(max_err, std::abs(b - fine.step(sf, h)));
      // The same field path sampled 5 times as densely (a slower drive): the same B.
      double b_slow = 0.0;
      for (int i = 1; i <= 5; ++i)
        b_slow = model.step(slow, previous + (h - previous) * i / 5.0);
      EXPECT_NEAR(b_slow, b, 2e-3) << to_string(variant);
      previous = h;
    }
    EXPECT_LT(max_err, 2e-3) << to_string(variant);
  }
}

TEST(JilesAtherton, MinorLoopStaysInsideTheMajorLoop) {
  const JilesAtherton model(params(JilesAthertonVariant::original));
  auto state = model.initial_state();
  const auto h = field_history();
  std::vector<double> b;
  for (double x : h)
    b.push_back(model.step(state, x));
  // Falling major branch at H = 1000 (sample 200 + 400 + 400 + 100 - 1 = 1099) is above every
  // point of the minor loop at H = 1000 afterwards.
  const double upper = b[1099];
  EXPECT_NEAR(h[1099], 1000.0, 1e-9);
  for (std::size_t k = 1100; k < 1100 + 200; ++k) {
    if (std::abs(h[k] - 1000.0) < 1e-9) {
      EXPECT_LE(b[k], upper + 1e-6);
    }
  }
}

TEST(JilesAtherton, TangentMatchesFiniteDifference) {
  for (auto variant : kVariants) {
    auto p = params(variant);
    p.max_field_step = 0.01;
    const JilesAtherton model(p);
    auto state = model.initial_state();
    for (double h : {3000.0, -2000.0, 500.0})
      model.step(state, h);
    auto probe = state;
    const double b0 = model.flux_density(state);
    const double b1 = model.step(probe, 500.0 + 0.01);
    EXPECT_NEAR(model.tangent(state, 1.0), (b1 - b0) / 0.01, 1e-4 * (b1 - b0) / 0.01)
        << to_string(variant);
  }
}

TEST(JilesAtherton, ExplicitInitialStates) {
  for (auto variant : kVariants) {
    const JilesAtherton model(params(variant));
    const auto demagnetised = model.initial_state();
    EXPECT_EQ(model.flux_density(demagnetised), 0.0);
    const auto given = model.state_at(100.0, 5e5);
    EXPECT_NEAR(model.flux_density(given), kMu0 * (100.0 + 5e5), 1e-15);
    auto moved = given;
    model.step(moved, 100.0);  // no field change: the state is kept
    EXPECT_EQ(moved.magnetisation, 5e5);
    EXPECT_HYST_ERROR(model.state_at(0.0, 2e6), "|magnetisation M| = 2000000 must be < M_s");
    const auto whole = model.state_at(100.0, 5e5, 4e5, -1.0);
    EXPECT_EQ(whole.irreversible, 4e5);
    EXPECT_EQ(whole.direction, -1.0);
    EXPECT_HYST_ERROR(model.state_at(100.0, 5e5, std::nan(""), 1.0),
                      "irreversible magnetisation M_irr = nan is not finite");
    EXPECT_HYST_ERROR(model.state_at(100.0, 5e5, 4e5, 0.0), "direction = 0 must be 1 or -1");
  }
}

TEST(JilesAtherton, RejectsInvalidParameters) {
  auto p = params(JilesAthertonVariant::original);
  p.c = 1.0;
  EXPECT_HYST_ERROR(JilesAtherton{p}, "Jiles-Atherton reversibility c = 1 must be < 1");
  p = params(JilesAthertonVariant::original);
  p.alpha = 0.01;
  EXPECT_HYST_ERROR(JilesAtherton{p}, "alpha M_s / (3 a) = 4.84");
  p = params(JilesAthertonVariant::original);
  p.k = 0.0;
  EXPECT_HYST_ERROR(JilesAtherton{p}, "pinning k = 0 must be > 0");
  EXPECT_HYST_ERROR(jiles_atherton_variant_from_string("comsol"),
                    "unknown Jiles-Atherton variant 'comsol'");
}

}  // namespace
}  // namespace hyst
