#include "hyst/operators/backlash.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {
namespace {

// The seed's eqs. 3.1-3.2 and the threshold form K * F_h[u] are the same operator
// (operators_check.py: K = 2.5, h = 0.3, max diff 0.0 over 5000 random steps).
TEST(Backlash, SeedFormEqualsGainTimesPlay) {
  const double gain = 2.5, h = 0.3;
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const auto u = test::random_walk(5000, seed, 3.0, 0.2);
    Stateful seed_form{Backlash({.gain = gain, .half_width = h})};
    Stateful play{Play(h)};
    const auto y = seed_form.simulate(u);
    const auto w = play.simulate(u);
    for (std::size_t k = 0; k < u.size(); ++k) {
      ASSERT_NEAR(y[k], gain * w[k], 1e-12 * (1 + std::abs(y[k]))) << "k = " << k;
    }
  }
}

TEST(Backlash, HandCalculatedSequence) {
  // K = 2, h = 0.5, y(-1) = 0: the band is u in [-0.5, 0.5] until the output moves.
  Stateful backlash{Backlash({.gain = 2.0, .half_width = 0.5})};
  const auto y = backlash.simulate(std::vector<double>{0.4, 1.0, 1.5, 1.2, 0.5, -1.0});
  const std::vector<double> expected{0.0, 1.0, 2.0, 2.0, 2.0, -1.0};
  for (std::size_t k = 0; k < y.size(); ++k)
    EXPECT_DOUBLE_EQ(y[k], expected[k]) << k;
}

TEST(Backlash, SaturationClipsTheOutput) {
  Stateful backlash{
      Backlash({.gain = 1.0, .half_width = 0.1, .output_min = -0.5, .output_max = 0.8})};
  const auto y = backlash.simulate(test::random_walk(3000, 5, 2.0, 0.1));
  EXPECT_DOUBLE_EQ(*std::max_element(y.begin(), y.end()), 0.8);
  EXPECT_DOUBLE_EQ(*std::min_element(y.begin(), y.end()), -0.5);
}

TEST(Backlash, RejectsBadParameters) {
  EXPECT_HYST_ERROR(Backlash({.gain = -1.0}), "backlash gain K = -1 must be > 0");
  EXPECT_HYST_ERROR(Backlash({.gain = 0.0}), "backlash gain K = 0 must be > 0");
  EXPECT_HYST_ERROR(Backlash({.gain = 1.0, .half_width = -0.3}),
                    "backlash half-width h = -0.3 must be >= 0");
  EXPECT_HYST_ERROR(Backlash({.output_min = 1.0, .output_max = 0.0}),
                    "y_min = 1 and y_max = 0 must satisfy y_min <= y_max");
  EXPECT_HYST_ERROR(Backlash({.gain = NAN}), "backlash gain K = nan is not finite");
}

}  // namespace
}  // namespace hyst
