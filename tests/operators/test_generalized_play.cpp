#include "hyst/operators/generalized_play.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {
namespace {

using TanhPlay = GeneralizedPlay<TanhEnvelope>;

// gpi_forms_check.py: a = (1, 1, -0.3, 0), b = (1, 1, 0.3, 0).
TanhPlay::Params forms_check_params(double threshold) {
  return {.ascending = {1.0, 1.0, -0.3, 0.0},
          .descending = {1.0, 1.0, 0.3, 0.0},
          .threshold = threshold,
          .input_min = -2.5,
          .input_max = 2.5};
}

// operators.md section 2 reference (r = 0.3, w0 = 0): with identity envelopes G_r is F_r.
TEST(GeneralizedPlay, IdentityEnvelopesGiveTheClassicalPlay) {
  const GeneralizedPlay<LinearEnvelope> play({.ascending = {1.0, 0.0},
                                              .descending = {1.0, 0.0},
                                              .threshold = 0.3,
                                              .input_min = -1,
                                              .input_max = 1});
  Stateful g{play};
  const auto y = g.simulate(std::vector<double>{0, 0.5, 1, 0.8, 0.4, 0.1, 0.6, -1});
  const std::vector<double> expected{0, 0.2, 0.7, 0.7, 0.7, 0.4, 0.4, -0.7};
  for (std::size_t k = 0; k < y.size(); ++k)
    EXPECT_NEAR(y[k], expected[k], 1e-15) << k;
  // Bit for bit the same as play_step on a random walk.
  const Play classical(0.3);
  auto w = classical.initial_state();
  g.reset();
  for (double v : test::random_walk(2000, 4))
    ASSERT_EQ(g.step(v), classical.step(w, v));
}

// By hand with gamma_l = tanh(v - 0.3), gamma_r = tanh(v + 0.3), r = 0.1, z0 = 0:
// v = 0.3:  z = max(tanh(0) - 0.1, min(tanh(0.6) + 0.1, 0)) = 0;
// v = 1.3:  z = max(tanh(1) - 0.1, ...) = tanh(1) - 0.1 = 0.6616;
// v = 0.3:  z = min(tanh(0.6) + 0.1, 0.6616) = tanh(0.6) + 0.1 = 0.6370 (falling branch);
// v = 0.8:  z stays 0.6370 (tanh(0.5) - 0.1 = 0.362 < 0.637 < tanh(1.1) + 0.1);
// v = -1:   z = min(tanh(-0.7) + 0.1, 0.6370) = tanh(-0.7) + 0.1.
TEST(GeneralizedPlay, HandCalculatedTanhSequence) {
  Stateful g{TanhPlay(forms_check_params(0.1))};
  EXPECT_NEAR(g.step(0.3), 0.0, 1e-15);
  EXPECT_NEAR(g.step(1.3), std::tanh(1.0) - 0.1, 1e-15);
  EXPECT_NEAR(g.step(0.3), std::tanh(0.6) + 0.1, 1e-15);
  EXPECT_NEAR(g.step(0.8), std::tanh(0.6) + 0.1, 1e-15);
  EXPECT_NEAR(g.step(-1.0), std::tanh(-0.7) + 0.1, 1e-15);
}

// gpi_forms_check.py: under gamma_l <= gamma_r the max/min form equals the direction-switched
// form of the MSMA paper (max diff 0.0). Ported as a property on seeded random walks.
TEST(GeneralizedPlay, EqualsTheDirectionSwitchedForm) {
  for (std::uint64_t seed : {7u, 8u, 9u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const auto v = test::random_walk(3000, seed, 2.5, 0.08);
    for (double r : {0.0, 0.05, 0.2, 0.4}) {
      const TanhPlay play(forms_check_params(r));
      auto state = play.initial_state();
      // Direction-switched: step 0 uses the max/min rule on z = 0, then by direction.
      double z = 0;
      for (std::size_t k = 0; k < v.size(); ++k) {
        if (k == 0) {
          z = std::max(play.ascending(v[0]) - r, std::min(play.descending(v[0]) + r, 0.0));
        } else if (v[k] > v[k - 1]) {
          z = std::max(play.ascending(v[k]) - r, z);
        } else if (v[k] < v[k - 1]) {
          z = std::min(play.descending(v[k]) + r, z);
        }
        ASSERT_EQ(play.step(state, v[k]), z) << "k = " << k << ", r = " << r;
      }
    }
  }
}

TEST(GeneralizedPlay, MonotoneBoundedAndRateIndependent) {
  std::mt19937_64 rng(99);
  for (int trial = 0; trial < 10; ++trial) {
    const std::uint64_t seed = rng();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 draw(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double a0 = 1.0 + unit(draw);
    const double a1 = 0.3 + unit(draw);
    const double shift = unit(draw);  // equal a0, a1, a3 and b2 - a2 >= 0: gamma_l <= gamma_r
    const TanhPlay play({.ascending = {a0, a1, -shift / 2, 0.1},
                         .descending = {a0, a1, shift / 2, 0.1},
                         .threshold = 0.3 * unit(draw),
                         .input_min = -3,
                         .input_max = 3});
    const auto v = test::random_walk(3000, seed, 3.0, 0.3);
    auto state = play.initial_state();
    const auto y = simulate(play, state, v);
    const double r = play.params().threshold;
    for (std::size_t k = 1; k < v.size(); ++k) {
      ASSERT_GE((y[k] - y[k - 1]) * (v[k] - v[k - 1]), 0.0) << "k = " << k;
      ASSERT_GE(y[k], play.ascending(v[k]) - r) << "k = " << k;
      ASSERT_LE(y[k], play.descending(v[k]) + r) << "k = " << k;
    }
    auto fine_state = play.initial_state();
    const auto y_fine = simulate(play, fine_state, test::upsample_linear(v, 6));
    for (std::size_t k = 0; k < v.size(); ++k)
      ASSERT_EQ(y[k], y_fine[6 * k]) << "k = " << k;
  }
}

TEST(GeneralizedPlay, RepeatedSamplesLeaveTheStateUnchanged) {
  const TanhPlay play(forms_check_params(0.2));
  auto state = play.make_state(0.1);
  const double first = play.step(state, 0.7);
  for (int k = 0; k < 5; ++k)
    EXPECT_EQ(play.step(state, 0.7), first);
}

TEST(GeneralizedPlay, RejectsBadParameters) {
  auto params = forms_check_params(-0.1);
  EXPECT_HYST_ERROR(TanhPlay{params}, "generalized play threshold r = -0.1 must be >= 0");
  params = forms_check_params(NAN);
  EXPECT_HYST_ERROR(TanhPlay{params}, "generalized play threshold r = nan is not finite");
  params = forms_check_params(0.1);
  std::swap(params.ascending, params.descending);
  EXPECT_HYST_ERROR(TanhPlay{params},
                    "generalized play envelopes violate the ordering gamma_l(v) <= gamma_r(v)");
  params = forms_check_params(0.1);
  params.descending = {1.0, 1.0};
  EXPECT_HYST_ERROR(TanhPlay{params}, "generalized play descending envelope has 2 coefficients");
  params = forms_check_params(0.1);
  params.input_max = NAN;
  EXPECT_HYST_ERROR(TanhPlay{params}, "generalized play operating range input_max = nan");
  const TanhPlay play(forms_check_params(0.1));
  EXPECT_HYST_ERROR(play.make_state(INFINITY), "generalized play state z = inf is not finite");
}

}  // namespace
}  // namespace hyst
