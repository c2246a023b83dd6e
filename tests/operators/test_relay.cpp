#include "hyst/operators/relay.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"

namespace hyst {
namespace {

std::vector<double> run(const Relay& relay, Relay::State state, const std::vector<double>& v) {
  std::vector<double> out;
  for (double x : v)
    out.push_back(relay.step(state, x));
  return out;
}

// operators_check.py: relay(0.5, -0.5), s = -1.
TEST(Relay, MatchesReferenceSequence) {
  const Relay relay(0.5, -0.5);
  const std::vector<double> v{0, 0.4, 0.5, 0.2, -0.4, -0.5, 0, 0.7, -0.6};
  EXPECT_EQ(run(relay, relay.initial_state(), v),
            (std::vector<double>{-1, -1, 1, 1, 1, -1, -1, 1, -1}));
}

TEST(Relay, InitialStateIsKeptInsideTheBandAndOverwrittenOutside) {
  const Relay relay(0.5, -0.5);
  EXPECT_EQ(run(relay, relay.make_state(1.0), {0.0, 0.3}), (std::vector<double>{1, 1}));
  EXPECT_EQ(run(relay, relay.make_state(1.0), {-0.5}), (std::vector<double>{-1}));
  EXPECT_EQ(run(relay, relay.make_state(-1.0), {0.5}), (std::vector<double>{1}));
}

TEST(Relay, EqualThresholdsResolveTheTieUpwards) {
  const Relay relay(0.2, 0.2);
  EXPECT_EQ(run(relay, relay.initial_state(), {0.2, 0.1, 0.2}), (std::vector<double>{1, -1, 1}));
}

TEST(Relay, RateIndependentUnderLinearUpsampling) {
  const Relay relay(0.3, -0.4);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const auto v = test::random_walk(3000, seed, 1.0, 0.15);
    const auto dense = test::upsample_linear(v, 8);
    const auto y = run(relay, relay.initial_state(), v);
    const auto y_dense = run(relay, relay.initial_state(), dense);
    for (std::size_t k = 0; k < v.size(); ++k)
      ASSERT_EQ(y[k], y_dense[8 * k]) << "k = " << k;
  }
}

TEST(Relay, OutputIsAlwaysPlusOrMinusOne) {
  const Relay relay(0.1, -0.1);
  for (double y : run(relay, relay.initial_state(), test::random_walk(2000, 7, 1.0, 0.1))) {
    EXPECT_TRUE(y == 1.0 || y == -1.0);
  }
}

TEST(Relay, RejectsBadParameters) {
  EXPECT_HYST_ERROR(Relay(-0.5, 0.5), "alpha = -0.5 and beta = 0.5 must satisfy alpha >= beta");
  EXPECT_HYST_ERROR(Relay(std::nan(""), 0.0), "relay alpha = nan is not finite");
  EXPECT_HYST_ERROR(Relay(0.0, -std::numeric_limits<double>::infinity()),
                    "relay beta = -inf is not finite");
  EXPECT_HYST_ERROR(Relay(1, 0).make_state(0.5), "relay state = 0.5 must be -1 or +1");
}

}  // namespace
}  // namespace hyst
