// The discrete PID controller: each term against its hand-computed sequence, anti-windup modes.

#include <cmath>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/control/pid.hpp"

namespace {

using hyst::control::AntiWindup;
using hyst::control::Pid;

constexpr double kH = 1e-3;

TEST(Pid, ProportionalAndIntegralTermsFollowTheRecurrence) {
  const Pid pid({.kp = 2.0, .ki = 50.0}, kH);
  auto state = pid.initial_state();
  // Constant error 0.5: u[n] = kp e + n ki h e.
  for (int n = 0; n < 100; ++n) {
    EXPECT_NEAR(pid.step(state, 1.5, 1.0), 2.0 * 0.5 + n * 50.0 * kH * 0.5, 1e-12) << n;
  }
}

TEST(Pid, FilteredDerivativeOfARampApproachesKdTimesTheSlope) {
  // y = c t: D[n] = -kd c (1 - a^n), a = Tf/(Tf + h) (no kick on the first step).
  const double kd = 0.3;
  const double tf = 5e-3;
  const double c = 2.0;
  const Pid pid({.kd = kd, .derivative_filter = tf}, kH);
  auto state = pid.initial_state();
  const double a = tf / (tf + kH);
  for (int n = 0; n < 200; ++n) {
    const double y = c * n * kH;
    EXPECT_NEAR(pid.step(state, 0.0, y), -kd * c * (1.0 - std::pow(a, n)), 1e-12) << n;
  }
}

TEST(Pid, FeedforwardAddsBeforeTheLimits) {
  const Pid pid({.kp = 1.0, .output_min = 0.0, .output_max = 2.0}, kH);
  auto state = pid.initial_state();
  EXPECT_EQ(pid.step(state, 1.0, 0.5, 0.25), 0.75);
  EXPECT_EQ(pid.step(state, 1.0, 0.5, 5.0), 2.0);
  EXPECT_EQ(pid.step(state, 0.0, 0.5, -5.0), 0.0);
}

// A pure integrator held at saturation for 100 samples, then the error reverses: how many
// samples the output stays saturated measures the windup.
int samples_saturated_after_reversal(AntiWindup mode) {
  const Pid pid(
      {.kp = 1.0, .ki = 100.0, .output_min = -1.0, .output_max = 1.0, .anti_windup = mode}, kH);
  auto state = pid.initial_state();
  for (int n = 0; n < 100; ++n)
    pid.step(state, 5.0, 0.0);
  int saturated = 0;
  while (pid.step(state, -0.1, 0.0) >= 1.0 && saturated < 100000)
    ++saturated;
  return saturated;
}

TEST(Pid, AntiWindupReleasesTheSaturationAtOnce) {
  // Without anti-windup the integral reached 100 * 100 * 1e-3 * 5 = 50 and needs
  // 50 / (100 * 1e-3 * 0.1) = 5000 samples to unwind; clamping froze it at the first sample
  // (kp e + I = 5 + 0.5 > 1 from then on), back-calculation bleeds it towards the limit.
  EXPECT_GT(samples_saturated_after_reversal(AntiWindup::none), 4000);
  EXPECT_LT(samples_saturated_after_reversal(AntiWindup::clamping), 5);
  EXPECT_LT(samples_saturated_after_reversal(AntiWindup::back_calculation), 50);
}

TEST(Pid, StartIsBumpless) {
  const Pid pid({.kp = 3.0, .ki = 10.0, .kd = 0.1, .derivative_filter = 1e-3}, kH);
  auto state = pid.start(0.7, 1.0, 0.9);
  EXPECT_NEAR(pid.step(state, 1.0, 0.9), 0.7, 1e-15);
}

TEST(Pid, DefaultTrackingTimeFollowsTheReference) {
  EXPECT_NEAR(Pid({.kp = 2.0, .ki = 4.0}, kH).tracking_time(), 0.5, 1e-15);  // Ti
  EXPECT_NEAR(Pid({.kp = 2.0, .ki = 4.0, .kd = 0.02}, kH).tracking_time(), std::sqrt(0.5 * 0.01),
              1e-15);  // sqrt(Ti Td)
}

TEST(Pid, RejectsInvalidParameters) {
  EXPECT_HYST_ERROR(Pid({.kp = -1.0}, kH), "kp");
  EXPECT_HYST_ERROR(Pid({.ki = NAN}, kH), "ki");
  EXPECT_HYST_ERROR(Pid({.output_min = 1.0, .output_max = 0.0}, kH), "output_min");
  EXPECT_HYST_ERROR(Pid({.tracking_time = -1.0}, kH), "tracking_time");
  EXPECT_HYST_ERROR(Pid({.kp = 1.0}, 0.0), "period");
  EXPECT_HYST_ERROR(hyst::control::anti_windup_from_string("windup"), "back_calculation");
}

}  // namespace
