#include "hyst/operators/play.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"

namespace hyst {
namespace {

// operators_check.py: r = 0.3, w0 = 0.
TEST(Play, MatchesReferenceSequence) {
  Stateful play{Play(0.3)};
  const std::vector<double> v{0, 0.5, 1, 0.8, 0.4, 0.1, 0.6, -1};
  const std::vector<double> expected{0, 0.2, 0.7, 0.7, 0.7, 0.4, 0.4, -0.7};
  const auto y = play.simulate(v);
  for (std::size_t k = 0; k < v.size(); ++k)
    EXPECT_NEAR(y[k], expected[k], 1e-15) << k;
}

TEST(Play, ZeroWidthIsTheIdentity) {
  Stateful play{Play(0.0)};
  const auto v = test::random_walk(1000, 3);
  EXPECT_EQ(play.simulate(v), v);
}

TEST(Play, InitialStateIsClippedIntoTheBandAtTheFirstStep) {
  const Play play(0.5);
  auto state = play.make_state(10.0);
  EXPECT_DOUBLE_EQ(play.step(state, 0.0), 0.5);
  state = play.make_state(-10.0);
  EXPECT_DOUBLE_EQ(play.step(state, 1.0), 0.5);
  state = play.make_state(0.2);
  EXPECT_DOUBLE_EQ(play.step(state, 0.0), 0.2);
}

TEST(Play, StaysWithinHalfWidthOfTheInputAndNeverMovesAgainstIt) {
  const double r = 0.25;
  for (std::uint64_t seed : {11u, 12u, 13u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const auto v = test::random_walk(5000, seed);
    Stateful play{Play(r)};
    const auto w = play.simulate(v);
    for (std::size_t k = 0; k < v.size(); ++k) {
      ASSERT_LE(std::abs(v[k] - w[k]), r + 1e-15) << "k = " << k;
      if (k > 0) {
        ASSERT_GE((w[k] - w[k - 1]) * (v[k] - v[k - 1]), 0.0) << "k = " << k;
      }
    }
  }
}

// operators_check.py: 8x linear up-sampling changes nothing at the original samples.
TEST(Play, RateIndependentUnderUpsamplingAndRepeatedSamples) {
  const auto v = test::random_walk(5000, 11);
  Stateful coarse{Play(0.25)};
  Stateful fine{Play(0.25)};
  const auto y = coarse.simulate(v);
  const auto y_fine = fine.simulate(test::upsample_linear(v, 8));
  std::vector<double> repeated;
  for (double x : v)
    repeated.insert(repeated.end(), 3, x);
  Stateful slow{Play(0.25)};
  const auto y_slow = slow.simulate(repeated);
  for (std::size_t k = 0; k < v.size(); ++k) {
    ASSERT_EQ(y[k], y_fine[8 * k]) << "k = " << k;
    ASSERT_EQ(y[k], y_slow[3 * k + 2]) << "k = " << k;
  }
}

TEST(Play, IsLipschitzWithConstantOne) {
  const auto v1 = test::random_walk(3000, 21);
  auto v2 = v1;
  for (std::size_t k = 0; k < v2.size(); ++k)
    v2[k] += 0.05 * std::sin(0.01 * k);
  Stateful a{Play(0.3)};
  Stateful b{Play(0.3)};
  const auto w1 = a.simulate(v1);
  const auto w2 = b.simulate(v2);
  double input_gap = 0, output_gap = 0;
  for (std::size_t k = 0; k < v1.size(); ++k) {
    input_gap = std::max(input_gap, std::abs(v1[k] - v2[k]));
    output_gap = std::max(output_gap, std::abs(w1[k] - w2[k]));
  }
  EXPECT_LE(output_gap, input_gap);
}

TEST(Play, RejectsBadParametersAndInput) {
  EXPECT_HYST_ERROR(Play(-0.2), "play half-width r = -0.2 must be >= 0");
  EXPECT_HYST_ERROR(Play(std::nan("")), "play half-width r = nan is not finite");
  EXPECT_HYST_ERROR(Play(0.1).make_state(INFINITY), "play state w = inf is not finite");
  Stateful play{Play(0.1)};
  const std::vector<double> bad{0.0, 1.0, std::nan("")};
  EXPECT_HYST_ERROR(play.simulate(bad), "input[2] = nan is not finite");
  std::vector<double> out(2);
  EXPECT_HYST_ERROR(play.simulate(bad, out), "input has 3 values but output has 2");
}

}  // namespace
}  // namespace hyst
