#include "hyst/models/prandtl_ishlinskii.hpp"

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

PrandtlIshlinskii reference_model() {
  return PrandtlIshlinskii(
      {.thresholds = {0, 0.3, 0.7, 1.0, 1.6, 2.2}, .weights = {0.8, 0.5, 0.3, 0.2, 0.1, 0.05}});
}

// Initial loading curve from the virgin state: phi(v) = sum_{r_j <= v} p_j (v - r_j).
double loading_curve(const PrandtlIshlinskii::Params& params, double v) {
  double y = 0;
  for (std::size_t j = 0; j < params.thresholds.size(); ++j) {
    if (params.thresholds[j] <= v) y += params.weights[j] * (v - params.thresholds[j]);
  }
  return y;
}

std::vector<double> ramp(double from, double to, std::size_t samples) {
  std::vector<double> v(samples);
  for (std::size_t k = 0; k < samples; ++k) {
    v[k] = from + (to - from) * static_cast<double>(k) / static_cast<double>(samples - 1);
  }
  return v;
}

TEST(PrandtlIshlinskii, HandCalculatedSequence) {
  // r = {0, 0.3}, p = {1, 0.5}, offset 0.1: y = 0.1 + v + 0.5 w_1.
  Stateful pi{PrandtlIshlinskii({.thresholds = {0, 0.3}, .weights = {1, 0.5}, .offset = 0.1})};
  const auto y = pi.simulate(std::vector<double>{0.5, 1.0, 0.6, 0.2, -1.0});
  const std::vector<double> expected{0.7, 1.45, 1.05, 0.55, -1.25};
  for (std::size_t k = 0; k < y.size(); ++k)
    EXPECT_NEAR(y[k], expected[k], 1e-15) << k;
}

// Closed forms: the initial loading curve phi and Masing's rule for the branch after a
// reversal, y(V - d) = phi(V) - 2 phi(d / 2).
TEST(PrandtlIshlinskii, FollowsLoadingCurveAndMasingRule) {
  const auto model = reference_model();
  auto state = model.initial_state();
  for (double v : ramp(0.0, 3.0, 301)) {
    EXPECT_NEAR(model.step(state, v), loading_curve(model.params(), v), 1e-13) << "v = " << v;
  }
  const double peak = loading_curve(model.params(), 3.0);
  for (double v : ramp(3.0, -3.0, 601)) {
    const double d = 3.0 - v;
    EXPECT_NEAR(model.step(state, v), peak - 2 * loading_curve(model.params(), d / 2), 1e-13)
        << "v = " << v;
  }
}

TEST(PrandtlIshlinskii, EqualsTheWeightedSumOfItsPlays) {
  std::mt19937_64 rng(2024);
  for (int trial = 0; trial < 20; ++trial) {
    const std::uint64_t seed = rng();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 draw(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::size_t n = 1 + draw() % 40;
    PrandtlIshlinskii::Params params{{0.0}, {unit(draw) + 0.1}, unit(draw) - 0.5};
    for (std::size_t j = 1; j < n; ++j) {
      params.thresholds.push_back(params.thresholds.back() + 0.01 + 0.2 * unit(draw));
      params.weights.push_back(2 * unit(draw) - 1);
    }
    const PrandtlIshlinskii model(params);
    auto state = model.initial_state();
    std::vector<Play::State> plays(n);
    const auto v = test::random_walk(2000, seed);
    for (double x : v) {
      double expected = params.offset;
      for (std::size_t j = 0; j < n; ++j) {
        expected += params.weights[j] * Play(params.thresholds[j]).step(plays[j], x);
      }
      ASSERT_NEAR(model.step(state, x), expected, 1e-12 * (1 + std::abs(expected)));
    }
  }
}

TEST(PrandtlIshlinskii, RateIndependentUnderUpsampling) {
  const auto model = reference_model();
  const auto v = test::pi_check_signal();
  auto coarse = model.initial_state();
  auto fine = model.initial_state();
  const auto y = simulate(model, coarse, v);
  const auto y_fine = simulate(model, fine, test::upsample_linear(v, 5));
  for (std::size_t k = 0; k < v.size(); ++k)
    ASSERT_EQ(y[k], y_fine[5 * k]) << "k = " << k;
}

// A new maximum wipes out every smaller maximum and the minima between them.
TEST(PrandtlIshlinskii, WipesOutDominatedExtrema) {
  const auto model = reference_model();
  auto with_history = model.initial_state();
  auto direct = model.initial_state();
  simulate(model, with_history, std::vector<double>{0.0, 1.5, -1.0, 0.7, 0.2, 1.6});
  simulate(model, direct, std::vector<double>{0.0, 1.6});
  for (std::size_t j = 0; j < model.size(); ++j) {
    EXPECT_DOUBLE_EQ(with_history.play[j], direct.play[j]) << "j = " << j;
  }
  // The same after a descent: minima wipe out larger minima.
  simulate(model, with_history, std::vector<double>{-0.5, 0.9, -0.2, 0.3, -1.8});
  simulate(model, direct, std::vector<double>{-1.8});
  for (std::size_t j = 0; j < model.size(); ++j) {
    EXPECT_DOUBLE_EQ(with_history.play[j], direct.play[j]) << "j = " << j;
  }
}

TEST(PrandtlIshlinskii, InvertibleWeightsGiveAMonotoneBoundedOutput) {
  // Negative weights are allowed while every partial sum stays positive.
  const PrandtlIshlinskii model(
      {.thresholds = {0, 0.2, 0.5, 0.9}, .weights = {1.0, 0.6, -0.5, -0.4}, .offset = 2.0});
  ASSERT_TRUE(model.is_invertible());
  for (std::uint64_t seed : {41u, 42u, 43u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const auto v = test::random_walk(5000, seed, 2.0, 0.2);
    auto state = model.initial_state();
    const auto y = simulate(model, state, v);
    double bound = 0;
    for (double p : model.params().weights)
      bound += std::abs(p) * 2.0;
    for (std::size_t k = 1; k < v.size(); ++k) {
      ASSERT_GE((y[k] - y[k - 1]) * (v[k] - v[k - 1]), -1e-15) << "k = " << k;
      ASSERT_LE(std::abs(y[k] - 2.0), bound + 1e-12) << "k = " << k;
    }
  }
}

TEST(PrandtlIshlinskii, InvertibilityFollowsThePartialSums) {
  EXPECT_TRUE(reference_model().is_invertible());
  EXPECT_FALSE(PrandtlIshlinskii({.thresholds = {0, 1}, .weights = {0.0, 1.0}}).is_invertible());
  EXPECT_FALSE(
      PrandtlIshlinskii({.thresholds = {0, 1, 2}, .weights = {1.0, -0.5, -0.6}}).is_invertible());
}

TEST(PrandtlIshlinskii, StatesAtRestAndFromAHistory) {
  const auto model = reference_model();
  const auto rest = model.state_at_rest(0.4);
  double sum = 0;
  for (double p : model.params().weights)
    sum += p;
  EXPECT_NEAR(model.output(rest), sum * 0.4, 1e-15);

  auto state = model.initial_state();
  double last = 0;
  for (double v : test::random_walk(500, 8))
    last = model.step(state, v);
  EXPECT_EQ(model.output(state), last);
  EXPECT_NO_THROW(model.make_state(state.play));
}

TEST(PrandtlIshlinskii, RejectsBadParameters) {
  using P = PrandtlIshlinskii;
  EXPECT_HYST_ERROR(P({.thresholds = {}, .weights = {}}), "PI thresholds r is empty");
  EXPECT_HYST_ERROR(P({.thresholds = {0, 1, 2}, .weights = {1, 1}}),
                    "PI has 3 thresholds r but 2 weights p");
  EXPECT_HYST_ERROR(P({.thresholds = {0.1, 1}, .weights = {1, 1}}),
                    "PI threshold r[0] = 0.1 must be 0");
  EXPECT_HYST_ERROR(P({.thresholds = {0, 0.5, 1, 0.9, 2}, .weights = {1, 1, 1, 1, 1}}),
                    "PI threshold r[3] = 0.9 must be > r[2] = 1");
  EXPECT_HYST_ERROR(P({.thresholds = {0, 0.5, 1, -0.2}, .weights = {1, 1, 1, 1}}),
                    "PI threshold r[3] = -0.2 must be > r[2] = 1");
  EXPECT_HYST_ERROR(P({.thresholds = {0, 0.5}, .weights = {1, NAN}}),
                    "PI weight p[1] = nan is not finite");
  EXPECT_HYST_ERROR(P({.thresholds = {0, INFINITY}, .weights = {1, 1}}),
                    "PI threshold r[1] = inf is not finite");
  EXPECT_HYST_ERROR(P({.thresholds = {0}, .weights = {1}, .offset = NAN}),
                    "PI offset = nan is not finite");
  EXPECT_HYST_ERROR(uniform_thresholds(4, -1.0), "spacing = -1 must be > 0");
}

TEST(PrandtlIshlinskii, ErrorsNameTheOffendingField) {
  const auto field_of = [](PrandtlIshlinskii::Params params) -> std::string {
    try {
      PrandtlIshlinskii model(std::move(params));
    } catch (const Error& error) {
      return error.field();
    }
    return "no error";
  };
  EXPECT_EQ(field_of({.thresholds = {0, 0.5, 1, -0.2}, .weights = {1, 1, 1, 1}}), "thresholds[3]");
  EXPECT_EQ(field_of({.thresholds = {0, 0.5}, .weights = {1, NAN}}), "weights[1]");
  EXPECT_EQ(field_of({.thresholds = {0}, .weights = {1}, .offset = INFINITY}), "offset");
  EXPECT_EQ(field_of({.thresholds = {0, 1}, .weights = {1}}), "weights");
}

TEST(PrandtlIshlinskii, RejectsUnreachableStates) {
  const auto model = reference_model();
  EXPECT_HYST_ERROR(model.make_state({0, 0}), "PI state w has 2 values but PI thresholds r has 6");
  EXPECT_HYST_ERROR(model.make_state({0, 0, 1.5, 0, 0, 0}),
                    "PI state w[2] = 1.5 and w[1] = 0 differ by 1.5, more than r[2] - r[1]");
  EXPECT_HYST_ERROR(model.make_state({0, 0, NAN, 0, 0, 0}), "PI state w[2] = nan is not finite");
  EXPECT_HYST_ERROR(model.state_at_rest(INFINITY), "PI rest input v0 = inf is not finite");
}

}  // namespace
}  // namespace hyst
