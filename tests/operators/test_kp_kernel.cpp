// KP kernel: the max/min form against the reference's direction-switched form (operators_check.py,
// max diff 0.0), the ramps at hand-computed points, the relay limit and validation.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/operators/kp_kernel.hpp"
#include "hyst/operators/relay.hpp"

namespace hyst {
namespace {

TEST(KpKernel, EqualsTheDirectionSwitchedForm) {
  // operators_check.py: s1 = -0.3, s2 = 0.4, a = 0.5, v = sin(0.01 k)(1.2 - 1e-4 k), k < 8000.
  const KpKernel kernel(-0.3, 0.4, 0.5);
  const auto ridge = [](double x) { return x < 0 ? -1.0 : (x > 0.5 ? 1.0 : -1.0 + 2.0 * x / 0.5); };
  auto state = kernel.initial_state();
  double switched = -1.0;
  double previous = 0.0;  // v[0], as in the check script
  double worst = 0.0;
  for (int k = 0; k < 8000; ++k) {
    const double v = std::sin(0.01 * k) * (1.2 - 0.0001 * k);
    if (v > previous) switched = std::max(switched, ridge(v - 0.4));
    if (v < previous) switched = std::min(switched, ridge(v + 0.3));
    previous = v;
    worst = std::max(worst, std::abs(kernel.step(state, v) - switched));
  }
  EXPECT_EQ(worst, 0.0);
}

TEST(KpKernel, RampsByHand) {
  const KpKernel kernel(-0.3, 0.4, 0.5);
  auto state = kernel.initial_state();
  EXPECT_EQ(kernel.step(state, 0.4), -1.0);
  EXPECT_NEAR(kernel.step(state, 0.65), 0.0, 1e-15);   // half way up the ascending ramp
  EXPECT_NEAR(kernel.step(state, 0.5), 0.0, 1e-15);    // falling above s1 + a: held
  EXPECT_NEAR(kernel.step(state, -0.2), -0.6, 1e-15);  // -1 + 2 (0.1 / 0.5)
  EXPECT_EQ(kernel.step(state, 1.0), 1.0);
}

TEST(KpKernel, NarrowRampIsARelay) {
  const KpKernel kernel(-0.5, 0.5, 1e-12);
  const Relay relay(0.5, -0.5);
  auto kernel_state = kernel.initial_state();
  auto relay_state = relay.initial_state();
  for (double v : {0.0, 0.4, 0.51, 0.2, -0.4, -0.51, 0.0, 0.7, -0.6})
    EXPECT_EQ(kernel.step(kernel_state, v), relay.step(relay_state, v)) << "v = " << v;
}

TEST(KpKernel, RejectsInvalidParameters) {
  EXPECT_HYST_ERROR(KpKernel(0.5, 0.4, 0.1), "s1 = 0.5 and s2 = 0.4");
  EXPECT_HYST_ERROR(KpKernel(0, 0.4, 0), "ramp width a = 0");
}

}  // namespace
}  // namespace hyst
