// Numerical inverse of monotone differential models: round trip (the model driven by the
// inverse's inputs gives the targets back) and saturation at the input limits.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/inverse/monotone_inverse.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "hyst/models/jiles_atherton.hpp"

namespace hyst {
namespace {

template <class Model>
void expect_round_trip(const Model& model, const std::vector<double>& input, double tolerance) {
  auto state = model.initial_state();
  std::vector<double> targets;
  for (double v : input)
    targets.push_back(model.step(state, v));
  const MonotoneInverse<Model> inverse(model, -1e9, 1e9);
  typename MonotoneInverse<Model>::State inverse_state{model.initial_state(), 0.0};
  std::vector<double> recovered(targets.size());
  const auto report = invert(inverse, inverse_state, targets, recovered);
  EXPECT_TRUE(report.ok());
  for (std::size_t k = 0; k < input.size(); ++k)
    EXPECT_NEAR(recovered[k], input[k], tolerance) << k;
}

std::vector<double> loops(double amplitude) {
  std::vector<double> v;
  for (int k = 1; k <= 600; ++k)
    v.push_back(amplitude * std::sin(2 * std::numbers::pi * k / 200.0) * (1.0 - k / 900.0));
  return v;
}

TEST(MonotoneInverse, JilesAthertonFieldFromFluxDensity) {
  expect_round_trip(JilesAtherton(JilesAtherton::Params{}), loops(4000.0), 1e-6);
}

TEST(MonotoneInverse, BoucWenDisplacementFromForce) {
  expect_round_trip(BoucWen(BoucWen::Params{}), loops(2.0), 1e-9);
}

TEST(MonotoneInverse, SaturatesAtTheInputLimits) {
  const BoucWen model(BoucWen::Params{});
  const MonotoneInverse<BoucWen> inverse(model, -1.0, 1.0);
  MonotoneInverse<BoucWen>::State state{model.initial_state(), 0.0};
  const auto high = inverse.solve(state, 100.0);
  EXPECT_EQ(high.status, InverseStatus::above_range);
  EXPECT_EQ(high.input, 1.0);
  const auto low = inverse.solve(state, -100.0);
  EXPECT_EQ(low.status, InverseStatus::below_range);
  EXPECT_EQ(low.input, -1.0);
}

TEST(MonotoneInverse, NonFiniteTargetsNeverGiveNaN) {
  const BoucWen model(BoucWen::Params{});
  const MonotoneInverse<BoucWen> inverse(model, -1.0, 1.0);
  MonotoneInverse<BoucWen>::State state{model.initial_state(), 0.0};
  const auto first = inverse.solve(state, 0.2);
  ASSERT_EQ(first.status, InverseStatus::ok);
  const auto held = inverse.solve(state, NAN);
  EXPECT_EQ(held.status, InverseStatus::not_invertible);
  EXPECT_EQ(held.input, first.input);
  EXPECT_EQ(inverse.solve(state, INFINITY).input, 1.0);
  EXPECT_EQ(inverse.solve(state, -INFINITY).input, -1.0);
}

TEST(MonotoneInverse, UnboundedRangeByDefaultInRegistryUse) {
  // Infinite limits (the registry's default): the bracket grows until it holds the target.
  const BoucWen model(BoucWen::Params{});
  const MonotoneInverse<BoucWen> inverse(model, -INFINITY, INFINITY);
  MonotoneInverse<BoucWen>::State state{model.initial_state(), 0.0};
  auto probe = model.initial_state();
  const double target = model.step(probe, 250.0);
  const auto sample = inverse.solve(state, target);
  EXPECT_EQ(sample.status, InverseStatus::ok);
  EXPECT_NEAR(sample.input, 250.0, 1e-9);
}

TEST(MonotoneInverse, BoucWenExactInverseForNEqualsOne) {
  // n = 1, A = 1, beta = gamma = 1/2, k = 1, alpha_k = 1/2: from the virgin state a rising x
  // gives z = 1 - exp(-x) (dz/dx = 1 - z), so F(x) = x / 2 + (1 - exp(-x)) / 2 in closed form.
  const BoucWen model(
      {.a = 1.0, .beta = 0.5, .gamma = 0.5, .n = 1.0, .stiffness = 1.0, .alpha_k = 0.5});
  const MonotoneInverse<BoucWen> inverse(model, -INFINITY, INFINITY);
  for (const double x : {0.25, 2.0, 40.0, 3.0e6}) {
    MonotoneInverse<BoucWen>::State state{model.initial_state(), 0.0};
    const double target = 0.5 * x + 0.5 * -std::expm1(-x);
    const auto sample = inverse.solve(state, target);
    EXPECT_EQ(sample.status, InverseStatus::ok) << x;
    EXPECT_NEAR(sample.input, x, 1e-12 * std::max(1.0, x)) << x;
  }
}

// A Bouc-Wen model without linear spring (alpha_k = 0) has |F| < k z0: a target beyond that is
// out of reach. The answer is the reachable extreme: an input where z has saturated, F = k z0.
TEST(MonotoneInverse, BoucWenTargetsBeyondTheForceBoundAreOutOfReach) {
  for (const double n : {1.0, 1.5}) {
    // z0 = (A / (beta + gamma))^(1/n) = 1 for A = 1, beta + gamma = 1; F = k z = 2 z.
    const BoucWen model(
        {.a = 1.0, .beta = 0.6, .gamma = 0.4, .n = n, .stiffness = 2.0, .alpha_k = 0.0});
    const MonotoneInverse<BoucWen> inverse(model, -INFINITY, INFINITY);
    MonotoneInverse<BoucWen>::State state{model.initial_state(), 0.0};
    for (const double target : {1e6, 1e300, -1e6, -1e300}) {
      const auto sample = inverse.solve(state, target);
      EXPECT_EQ(sample.status, target > 0 ? InverseStatus::above_range : InverseStatus::below_range)
          << n << " " << target;
      ASSERT_TRUE(std::isfinite(sample.input)) << n << " " << target;
      EXPECT_LT(std::abs(sample.input), 1e3) << n << " " << target;
      EXPECT_NEAR(model.output(state.model), std::copysign(2.0, target), 1e-9)
          << n << " " << target;
    }
  }
}

// With a linear spring the force is unbounded, but the search is not. n = 1 (exact per sample):
// 1e6 is reached at x = (1e6 - 0.7 k z0) / (0.3 k) (z saturated at z0 = A / (beta + gamma) = 1),
// 1e300 needs about 3e300, beyond the search span of about 1e12 max(1, |v|): out of reach,
// answered with the span's end. n = 1.5 (RK4): one sample integrates faithfully only up to
// 10^6 max_input_step = 10^6 z0 / (4 n A) (max_input_jump()); both targets need more.
TEST(MonotoneInverse, BoucWenSearchIsBoundedForHugeTargets) {
  const BoucWen exact(
      {.a = 1.0, .beta = 0.6, .gamma = 0.4, .n = 1.0, .stiffness = 1.0, .alpha_k = 0.3});
  const MonotoneInverse<BoucWen> exact_inverse(exact, -INFINITY, INFINITY);
  MonotoneInverse<BoucWen>::State state{exact.initial_state(), 0.0};
  const auto near = exact_inverse.solve(state, 1e6);
  EXPECT_EQ(near.status, InverseStatus::ok);
  EXPECT_NEAR(near.input, (1e6 - 0.7) / 0.3, 1e-9 * 1e6 / 0.3);
  MonotoneInverse<BoucWen>::State fresh{exact.initial_state(), 0.0};
  const auto far = exact_inverse.solve(fresh, 1e300);
  EXPECT_EQ(far.status, InverseStatus::above_range);
  EXPECT_GT(far.input, 1e11);
  EXPECT_LT(far.input, 1e13);
  EXPECT_NEAR(exact.output(fresh.model), 0.3 * far.input + 0.7, 1e-3);

  const BoucWen rk4(
      {.a = 1.0, .beta = 0.6, .gamma = 0.2, .n = 1.5, .stiffness = 1.0, .alpha_k = 0.3});
  const double z0 = std::pow(1.0 / 0.8, 1.0 / 1.5);
  EXPECT_DOUBLE_EQ(rk4.max_input_jump(), 1e6 * z0 / 6.0);
  const MonotoneInverse<BoucWen> rk4_inverse(rk4, -INFINITY, INFINITY);
  for (const double target : {1e6, 1e300}) {
    MonotoneInverse<BoucWen>::State rk4_state{rk4.initial_state(), 0.0};
    const auto sample = rk4_inverse.solve(rk4_state, target);
    EXPECT_EQ(sample.status, InverseStatus::above_range) << target;
    EXPECT_EQ(sample.input, rk4.max_input_jump()) << target;
    // Saturated z: F = 0.3 x + 0.7 z0, finite and the largest force one sample reaches.
    EXPECT_NEAR(rk4.output(rk4_state.model), 0.3 * sample.input + 0.7 * z0, 1e-6) << target;
  }
}

TEST(MonotoneInverse, RejectsAnEmptyOrNanRange) {
  const BoucWen model(BoucWen::Params{});
  EXPECT_HYST_ERROR(static_cast<void>(MonotoneInverse<BoucWen>(model, 1.0, 1.0)),
                    "input_min = 1 must be < input_max");
  EXPECT_HYST_ERROR(static_cast<void>(MonotoneInverse<BoucWen>(model, NAN, 1.0)),
                    "input_min = nan");
}

}  // namespace
}  // namespace hyst
