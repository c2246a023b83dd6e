#include "hyst/operators/stop.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {
namespace {

// E_r[v] = v - F_r[v] with the same initial history (misc_check.py: 4.4e-16).
TEST(Stop, EqualsInputMinusPlay) {
  for (std::uint64_t seed : {31u, 32u, 33u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const auto v = test::random_walk(5000, seed);
    Stateful stop{Stop(0.4)};
    Stateful play{Play(0.4)};
    const auto e = stop.simulate(v);
    const auto w = play.simulate(v);
    for (std::size_t k = 0; k < v.size(); ++k) {
      ASSERT_NEAR(e[k], v[k] - w[k], 1e-12) << "k = " << k;
      ASSERT_LE(std::abs(e[k]), 0.4) << "k = " << k;
    }
  }
}

TEST(Stop, StateFromPlayContinuesTheSameHistory) {
  const Stop stop(0.3);
  const Play play(0.3);
  auto play_state = play.make_state(0.9);
  play.step(play_state, 1.0);  // w = 0.9
  auto stop_state = stop.state_from_play(play_state.output, 1.0);
  for (double x : {1.5, 1.1, 0.2, 0.4}) {
    EXPECT_NEAR(stop.step(stop_state, x), x - play.step(play_state, x), 1e-15) << x;
  }
}

TEST(Stop, HandCalculatedSequence) {
  Stateful stop{Stop(0.5)};
  const auto e = stop.simulate(std::vector<double>{0.2, 1.0, 0.8, 0.1, -0.3});
  const std::vector<double> expected{0.2, 0.5, 0.3, -0.4, -0.5};
  for (std::size_t k = 0; k < e.size(); ++k)
    EXPECT_NEAR(e[k], expected[k], 1e-15) << k;
}

TEST(Stop, RejectsBadParameters) {
  EXPECT_HYST_ERROR(Stop(-1.0), "stop half-width r = -1 must be >= 0");
  EXPECT_HYST_ERROR(Stop(0.1).state_from_play(0.0, 0.5),
                    "stop state e = v - w = 0.5 must lie in [-r, r] = [-0.1, 0.1]");
}

}  // namespace
}  // namespace hyst
