// The linear blocks of the actuator against their analytic responses and the reference check
// msma_plant_check.py (actuator_msma.md section 3).

#include <cmath>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/actuator/actuator.hpp"
#include "hyst/actuator/coil.hpp"
#include "hyst/actuator/linearised_plant.hpp"
#include "hyst/actuator/mechanics.hpp"
#include "hyst/actuator/sensor_noise.hpp"
#include "hyst/actuator/transport_delay.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace {

// The [ASSUMED] MSMA set of actuator_msma.md section 2.
constexpr double kR = 2.0, kL = 0.015, kForceGain = 9.5, kMass = 0.05, kDamping = 40.0,
                 kStiffness = 7.6e4, kDelay = 1e-3, kPeriod = 1e-4;

hyst::LinearisedPlant msma_plant() {
  return hyst::LinearisedPlant({kR, kL, kForceGain, kMass, kDamping, kStiffness, kDelay});
}

TEST(Coil, MatchesTheReferenceZeroOrderHold) {
  const hyst::Coil coil({kR, kL}, kPeriod);
  // msma_plant_check.py: i[k+1] = 0.9867551618 i[k] + 0.006622419096 u[k]
  EXPECT_NEAR(coil.pole(), 0.9867551618, 1e-10);
  EXPECT_NEAR(coil.input_gain(), 0.006622419096, 1e-12);
}

TEST(Coil, StepResponseIsTheAnalyticOne) {
  const hyst::Coil coil({kR, kL}, kPeriod);
  auto state = coil.initial_state();
  for (int k = 1; k <= 2000; ++k) {
    const double current = coil.step(state, 3.0);
    const double t = k * kPeriod;
    EXPECT_NEAR(current, 3.0 / kR * (1.0 - std::exp(-kR * t / kL)), 1e-9) << "k = " << k;
  }
}

TEST(Coil, ImpulseResponseDecaysWithTheTimeConstant) {
  // After one period at u0, the free response is i(t) = i(h) exp(-R (t - h)/L).
  const hyst::Coil coil({kR, kL}, kPeriod);
  auto state = coil.initial_state();
  const double first = coil.step(state, 10.0);
  for (int k = 1; k <= 1000; ++k) {
    EXPECT_NEAR(coil.step(state, 0.0), first * std::exp(-kR * k * kPeriod / kL), 1e-9);
  }
}

TEST(Coil, CurrentLimitClampsTheState) {
  const hyst::Coil coil({kR, kL, 0.0, 8.0}, kPeriod);
  auto state = coil.initial_state();
  for (int k = 0; k < 5000; ++k)
    coil.step(state, 100.0);  // would settle at 50 A
  EXPECT_EQ(state.current, 8.0);
  for (int k = 0; k < 5000; ++k)
    coil.step(state, -100.0);
  EXPECT_EQ(state.current, 0.0);
}

TEST(Coil, RejectsInvalidParameters) {
  EXPECT_HYST_ERROR(hyst::Coil({-2.0, kL}, kPeriod), "resistance");
  EXPECT_HYST_ERROR(hyst::Coil({kR, 0.0}, kPeriod), "inductance");
  EXPECT_HYST_ERROR(hyst::Coil({kR, kL, 8.0, 0.0}, kPeriod), "current_min");
  EXPECT_HYST_ERROR(hyst::Coil({kR, kL, 0.0, 8.0, 9.0}, kPeriod), "initial_current");
  EXPECT_HYST_ERROR(hyst::Coil({kR, kL}, 0.0), "period");
}

// Underdamped step response of m x'' + b x' + k x = F (closed form).
double mechanics_step(double force, double t) {
  const double sigma = kDamping / (2.0 * kMass);
  const double omega_d = std::sqrt(kStiffness / kMass - sigma * sigma);
  return force / kStiffness *
         (1.0 -
          std::exp(-sigma * t) * (std::cos(omega_d * t) + sigma / omega_d * std::sin(omega_d * t)));
}

TEST(Mechanics, StepResponseIsTheAnalyticOne) {
  const hyst::Mechanics mechanics({kMass, kDamping, kStiffness}, kPeriod);
  EXPECT_NEAR(mechanics.natural_frequency(), 1232.8828, 1e-4);  // msma_plant_check.py
  EXPECT_NEAR(mechanics.damping_ratio(), 0.3244, 1e-4);
  auto state = mechanics.initial_state();
  for (int k = 1; k <= 400; ++k) {
    const double x = mechanics.step(state, 76.0);
    EXPECT_NEAR(x, mechanics_step(76.0, k * kPeriod), 1e-9 * 76.0 / kStiffness) << "k = " << k;
  }
}

TEST(Mechanics, TransitionIsTheClosedFormOfTheReference) {
  const hyst::Mechanics mechanics({kMass, kDamping, kStiffness}, kPeriod);
  const double sigma = kDamping / (2.0 * kMass);
  const double wn2 = kStiffness / kMass;
  const double wd = std::sqrt(wn2 - sigma * sigma);
  const double e = std::exp(-sigma * kPeriod);
  const double c = std::cos(wd * kPeriod);
  const double s = std::sin(wd * kPeriod);
  const auto& phi = mechanics.transition();
  EXPECT_NEAR(phi(0, 0), e * (c + sigma / wd * s), 1e-12);
  EXPECT_NEAR(phi(0, 1), e * s / wd, 1e-10 * phi(0, 1));
  EXPECT_NEAR(phi(1, 0), -e * wn2 / wd * s, 1e-9);
  EXPECT_NEAR(phi(1, 1), e * (c - sigma / wd * s), 1e-12);
  const auto& gamma = mechanics.input_matrix();
  EXPECT_NEAR(gamma(0), (1.0 - phi(1, 1) - kDamping / kMass * phi(0, 1)) / kStiffness,
              1e-9 * gamma(0));
  EXPECT_NEAR(gamma(1), phi(0, 1) / kMass, 1e-10 * gamma(1));
}

TEST(Mechanics, ImpulseResponseIsTheAnalyticOne) {
  // A force F0 over one period, then free motion: from the state after the first period, the
  // free response is x(t) = e^{-sigma t} (x0 cos wd t + (v0 + sigma x0)/wd sin wd t).
  const hyst::Mechanics mechanics({kMass, kDamping, kStiffness}, kPeriod);
  auto state = mechanics.initial_state();
  mechanics.step(state, 100.0);
  const double x0 = state.position;
  const double v0 = state.velocity;
  const double sigma = kDamping / (2.0 * kMass);
  const double wd = std::sqrt(kStiffness / kMass - sigma * sigma);
  for (int k = 1; k <= 400; ++k) {
    const double t = k * kPeriod;
    const double expected =
        std::exp(-sigma * t) * (x0 * std::cos(wd * t) + (v0 + sigma * x0) / wd * std::sin(wd * t));
    EXPECT_NEAR(mechanics.step(state, 0.0), expected, 1e-9 * std::abs(x0) + 1e-18);
  }
}

TEST(Mechanics, RejectsInvalidParameters) {
  EXPECT_HYST_ERROR(hyst::Mechanics({0.0, kDamping, kStiffness}, kPeriod), "mass");
  EXPECT_HYST_ERROR(hyst::Mechanics({kMass, -1.0, kStiffness}, kPeriod), "damping");
  EXPECT_HYST_ERROR(hyst::Mechanics({kMass, kDamping, NAN}, kPeriod), "stiffness");
}

TEST(TransportDelay, WholeSampleDelayIsExact) {
  const hyst::TransportDelay delay(kDelay, kPeriod);
  EXPECT_EQ(delay.whole_samples(), 10u);
  EXPECT_EQ(delay.fraction(), 0.0);
  auto state = delay.initial_state(-1.0);
  for (int k = 0; k < 100; ++k) {
    const double out = delay.step(state, 0.5 * k * k);
    EXPECT_EQ(out, k < 10 ? -1.0 : 0.5 * (k - 10) * (k - 10)) << "k = " << k;
  }
}

TEST(TransportDelay, ZeroDelayPassesThrough) {
  const hyst::TransportDelay delay(0.0, kPeriod);
  auto state = delay.initial_state();
  EXPECT_EQ(delay.step(state, 3.25), 3.25);
}

TEST(TransportDelay, FractionalDelayIsExactOnARamp) {
  // T = 2.25 h: linear interpolation between x[k-2] and x[k-3] is exact for a ramp.
  const hyst::TransportDelay delay(2.25e-4, kPeriod);
  EXPECT_EQ(delay.whole_samples(), 2u);
  EXPECT_NEAR(delay.fraction(), 0.25, 1e-12);
  auto state = delay.initial_state(0.0);
  for (int k = 0; k < 50; ++k) {
    const double out = delay.step(state, 2.0 * k);
    if (k >= 3) {
      EXPECT_NEAR(out, 2.0 * (k - 2.25), 1e-12) << "k = " << k;
    }
  }
}

TEST(TransportDelay, RejectsInvalidParameters) {
  EXPECT_HYST_ERROR(hyst::TransportDelay(-1e-3, kPeriod), "delay");
  EXPECT_HYST_ERROR(hyst::TransportDelay(1e-3, -1.0), "period");
}

TEST(SensorNoise, IsReproducibleAndHasTheRequestedSpread) {
  const hyst::SensorNoise noise({2.0, 42});
  auto a = noise.initial_state();
  auto b = noise.initial_state();
  double sum = 0.0;
  double squares = 0.0;
  constexpr int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double value = noise.step(a, 1.0);
    EXPECT_EQ(value, noise.step(b, 1.0));
    sum += value - 1.0;
    squares += (value - 1.0) * (value - 1.0);
  }
  EXPECT_NEAR(sum / n, 0.0, 0.05);                 // 4 standard errors of the mean
  EXPECT_NEAR(std::sqrt(squares / n), 2.0, 0.05);  // ~4 standard errors of sigma
  const hyst::SensorNoise off({0.0, 1});
  auto state = off.initial_state();
  EXPECT_EQ(off.step(state, 1.5), 1.5);
  EXPECT_HYST_ERROR(hyst::SensorNoise({-1.0, 1}), "standard_deviation");
}

TEST(LinearisedPlant, PolesDcGainAndExactDiscretisationMatchTheReference) {
  const auto plant = msma_plant();
  EXPECT_DOUBLE_EQ(plant.dc_gain(), 6.25e-5);  // msma_plant_check.py: static gain x/u
  const auto poles = plant.poles();
  ASSERT_EQ(poles.size(), 3u);
  EXPECT_NEAR(poles[0].real(), -kR / kL, 1e-9);
  EXPECT_NEAR(std::abs(poles[1]), 1232.8828, 1e-4);  // |s| = omega_n
  EXPECT_NEAR(-poles[1].real() / std::abs(poles[1]), 0.3244, 1e-4);
  EXPECT_NEAR(std::abs(plant.frequency_response(0.0)), 6.25e-5, 1e-18);
  const auto discrete = plant.discretise(kPeriod);
  const double phi[3][3] = {{0.9867551618, 0.0, 0.0},
                            {9.198781579e-07, 0.9926079973, 9.586131302e-05},
                            {0.01809099905, -145.7091958, 0.9159189469}};
  const double gamma[3] = {0.006622419096, 2.061089745e-09, 6.132521052e-05};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(discrete.transition()(r, c), phi[r][c],
                  1e-9 * std::max(1.0, std::abs(phi[r][c])));
    }
    EXPECT_NEAR(discrete.input_matrix()(r), gamma[r], 1e-9 * std::abs(gamma[r]));
  }
}

TEST(LinearisedPlant, StepResponseMatchesTheReferenceAndTheDiscreteSystem) {
  const auto plant = msma_plant();
  // msma_plant_check.py: 1 V step, delay 10 samples, x[20], x[50], x[100], x[399].
  EXPECT_NEAR(plant.step_response(20 * kPeriod), 1.572397e-06, 5e-13);
  EXPECT_NEAR(plant.step_response(50 * kPeriod), 2.478200e-05, 5e-12);
  EXPECT_NEAR(plant.step_response(100 * kPeriod), 4.260536e-05, 5e-12);
  EXPECT_NEAR(plant.step_response(399 * kPeriod), 6.212888e-05, 5e-12);
  const auto discrete = plant.discretise(kPeriod);
  auto state = discrete.initial_state();
  for (int k = 1; k <= 400; ++k) {
    const double y = discrete.step(state, 1.0);
    EXPECT_NEAR(y, plant.step_response(k * kPeriod), 1e-9 * 6.25e-5) << "k = " << k;
  }
}

TEST(Actuator, WithALinearForceConvergesToTheExactLinearisedPlant) {
  // F = k_F i (a PI with one play of threshold 0): the actuator's per-block hold differs from the
  // exact 3-state hold by O(h / substeps).
  const hyst::PrandtlIshlinskii linear({{0.0}, {kForceGain}, 0.0});
  hyst::ActuatorParams params;
  params.sample_time = kPeriod;
  params.coil = {kR, kL};
  params.mechanics = {kMass, kDamping, kStiffness};
  params.delay = kDelay;
  const auto plant = msma_plant();
  const auto max_error = [&](std::size_t substeps) {
    params.substeps = substeps;
    const hyst::Actuator<hyst::PrandtlIshlinskii> actuator(linear, params);
    auto state = actuator.initial_state();
    double worst = 0.0;
    for (int k = 1; k <= 400; ++k) {
      const double y = actuator.step(state, 1.0).measured;
      worst = std::max(worst, std::abs(y - plant.step_response(k * kPeriod)));
    }
    return worst;
  };
  const double one = max_error(1);
  const double hundred = max_error(100);
  EXPECT_LT(one, 0.02 * plant.dc_gain());  // a few percent of the final value at h = tau_e/75
  EXPECT_LT(hundred, one / 50.0);          // first order in the sub-period
  EXPECT_GT(one, 0.0);
}

TEST(Actuator, RejectsInvalidTiming) {
  const hyst::PrandtlIshlinskii linear({{0.0}, {1.0}, 0.0});
  hyst::ActuatorParams params;
  params.substeps = 0;
  EXPECT_HYST_ERROR((hyst::Actuator<hyst::PrandtlIshlinskii>(linear, params)), "substeps");
  params.substeps = 1;
  params.sample_time = -1.0;
  EXPECT_HYST_ERROR((hyst::Actuator<hyst::PrandtlIshlinskii>(linear, params)), "sample_time");
}

}  // namespace
