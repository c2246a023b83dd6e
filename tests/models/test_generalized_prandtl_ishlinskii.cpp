#include "hyst/models/generalized_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/gpi_reference.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {
namespace {

using TanhGpi = GeneralizedPrandtlIshlinskii<TanhEnvelope>;

// The "play on h" variant of pi_check.py (Al Janaideh 2022 tutorial code): classical plays on
// h = gamma_l(v) if v rises (or repeats), else gamma_r(v). Kept here only to show it is wrong.
std::vector<double> play_on_h(const TanhGpi& model, const std::vector<double>& v) {
  std::vector<double> z(model.size(), 0.0);
  std::vector<double> y(v.size());
  double previous = v.front();
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double h = v[k] >= previous ? model.ascending(v[k]) : model.descending(v[k]);
    previous = v[k];
    double sum = 0;
    for (std::size_t j = 0; j < z.size(); ++j) {
      z[j] = play_step(h, model.thresholds()[j], z[j]);
      sum += model.weights()[j] * z[j];
    }
    y[k] = sum;
  }
  return y;
}

// pi_check.py on v = 2 sin(2 pi k/1000)(0.6 + 0.4 cos(2 pi k/2300)), all states 0:
// max |max/min form - play on h| = 1.9685120284231594; samples with the output moving against
// the input: play on h 8, max/min form 0.
TEST(GeneralizedPrandtlIshlinskii, PiCheckMaxMinFormAgainstPlayOnH) {
  const TanhGpi model(test::pi_check_params());
  auto state = model.make_state(std::vector<double>(model.size(), 0.0));
  const auto v = test::pi_check_gpi_input();
  const auto y = simulate(model, state, v);
  const auto y_h = play_on_h(model, v);
  EXPECT_NEAR(test::max_abs_difference(y, y_h), 1.9685120284231594, 1e-12);
  EXPECT_EQ(test::against_input_moves(v, y_h), 8);
  EXPECT_EQ(test::against_input_moves(v, y), 0);
}

// msma_synth.py, ASSUMED MSMA set: sum p = 1.0025; for
// i = 4 - 4 cos(2 pi k/1000)(1 or 0.5) from rest at 0 A: F range 0.13 .. 76.04 N, no
// against-input moves, major loop at 4 A ascending 36.07 N, descending 59.37 N (2 decimals).
TEST(GeneralizedPrandtlIshlinskii, MsmaSynthReferenceNumbers) {
  const TanhGpi model(test::msma_params());
  EXPECT_NEAR(model.weight_sum(), 1.0025, 5e-5);
  auto state = model.initial_state();  // msma_synth's z0_j = gamma_l(0)
  for (double z : state.play)
    EXPECT_EQ(z, model.ascending(0.0));
  const auto i = test::msma_current();
  const auto f = simulate(model, state, i);
  EXPECT_NEAR(*std::min_element(f.begin(), f.end()), 0.13, 0.005);
  EXPECT_NEAR(*std::max_element(f.begin(), f.end()), 76.04, 0.005);
  EXPECT_EQ(test::against_input_moves(i, f), 0);
  double up = 0, down = 0;
  int n_up = 0, n_down = 0;
  for (std::size_t k = 1000; k < 2000; ++k) {
    if (std::abs(i[k] - 4.0) >= 0.02) continue;
    if (k < 1500) {
      up += f[k];
      ++n_up;
    } else {
      down += f[k];
      ++n_down;
    }
  }
  ASSERT_GT(n_up, 0);
  ASSERT_GT(n_down, 0);
  EXPECT_NEAR(up / n_up, 36.07, 0.005);
  EXPECT_NEAR(down / n_down, 59.37, 0.005);
}

// Linear envelopes gamma_l = gamma_r = v: the GPI is the classical PI, bit for bit.
TEST(GeneralizedPrandtlIshlinskii, IdentityEnvelopesReduceToTheClassicalPi) {
  std::mt19937_64 rng(2026);
  for (int trial = 0; trial < 20; ++trial) {
    const std::uint64_t seed = rng();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 draw(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    GpiParams params{.envelope = EnvelopeKind::linear,
                     .ascending = {1.0, 0.0},
                     .descending = {1.0, 0.0},
                     .input_min = -3,
                     .input_max = 3};
    if (trial % 2 == 0) {
      params.density = GpiDensity::exponential;
      params.rho = 0.1 + unit(draw);
      params.tau = 3 * unit(draw) - 0.5;
      params.alpha = 0.01 + 0.3 * unit(draw);
      params.m = draw() % 60;
    } else {
      params.density = GpiDensity::free;
      params.thresholds = {0.0};
      params.weights = {0.2 + unit(draw)};
      for (std::size_t j = 1; j < 1 + draw() % 40; ++j) {
        params.thresholds.push_back(params.thresholds.back() + 0.01 + 0.2 * unit(draw));
        params.weights.push_back(unit(draw) - 0.2);  // signed, partial sums stay > 0
      }
    }
    const GeneralizedPrandtlIshlinskii<LinearEnvelope> gpi(params);
    const PrandtlIshlinskii pi({.thresholds = gpi.thresholds(), .weights = gpi.weights()});
    auto z = gpi.initial_state();
    auto w = pi.initial_state();
    for (double v : test::random_walk(3000, seed, 3.0, 0.25))
      ASSERT_EQ(gpi.step(z, v), pi.step(w, v));
    EXPECT_EQ(z.play, w.play);
    EXPECT_EQ(gpi.classical().params().weights, pi.params().weights);
  }
}

// The model equals the weighted sum of independent GeneralizedPlay operators, each evaluating
// its own envelopes; random tanh and arctan models.
template <class E>
void check_sum_of_operators(std::uint64_t seed) {
  std::mt19937_64 draw(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double c0 = 0.5 + 2 * unit(draw);
  const double c1 = 0.2 + unit(draw);
  const double c3 = unit(draw) - 0.5;
  const double a2 = unit(draw) - 0.5;
  GpiParams params{.envelope = E::kind,
                   .ascending = {c0, c1, a2, c3},
                   .descending = {c0, c1, a2 + unit(draw), c3},
                   .rho = 0.1 + unit(draw),
                   .tau = 2 * unit(draw),
                   .alpha = 0.02 + 0.2 * unit(draw),
                   .m = 1 + draw() % 20,
                   .input_min = -3,
                   .input_max = 3};
  const GeneralizedPrandtlIshlinskii<E> model(params);
  std::vector<GeneralizedPlay<E>> plays;
  std::vector<typename GeneralizedPlay<E>::State> states;
  const double z0 = model.ascending(0.0);
  for (double r : model.thresholds()) {
    plays.emplace_back(typename GeneralizedPlay<E>::Params{params.ascending, params.descending, r,
                                                           params.input_min, params.input_max});
    states.push_back(plays.back().make_state(z0));
  }
  auto state = model.initial_state();
  for (double v : test::random_walk(2000, seed, 3.0, 0.3)) {
    double expected = 0;
    for (std::size_t j = 0; j < plays.size(); ++j)
      expected += model.weights()[j] * plays[j].step(states[j], v);
    ASSERT_NEAR(model.step(state, v), expected, 1e-12 * (1 + std::abs(expected)));
  }
}

TEST(GeneralizedPrandtlIshlinskii, EqualsTheWeightedSumOfGeneralizedPlays) {
  std::mt19937_64 rng(404);
  for (int trial = 0; trial < 10; ++trial) {
    const std::uint64_t seed = rng();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    check_sum_of_operators<TanhEnvelope>(seed);
    check_sum_of_operators<ArctanEnvelope>(seed);
  }
}

// Rate independence, output never against the input, every z_j within
// [gamma_l(v) - r_j, gamma_r(v) + r_j], so y within the weighted envelope bands.
TEST(GeneralizedPrandtlIshlinskii, RateIndependentMonotoneAndBounded) {
  const TanhGpi model(test::msma_params());
  const auto& r = model.thresholds();
  // y = sum_j p_j z_j with z_j within (0 - r_j, 80 + r_j): the tanh ranges are (0, 80).
  double lowest = 0, highest = 0;
  for (std::size_t j = 0; j < model.size(); ++j) {
    lowest += model.weights()[j] * (0.0 - r[j]);
    highest += model.weights()[j] * (80.0 + r[j]);
  }
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    auto v = test::random_walk(4000, seed, 4.0, 0.4);
    for (double& x : v)
      x += 4.0;  // 0 .. 8 A
    auto state = model.initial_state();
    std::vector<double> y(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) {
      y[k] = model.step(state, v[k]);
      for (std::size_t j = 0; j < model.size(); ++j) {
        ASSERT_GE(state.play[j], model.ascending(v[k]) - r[j] - 1e-12);
        ASSERT_LE(state.play[j], model.descending(v[k]) + r[j] + 1e-12);
      }
      ASSERT_GT(y[k], lowest);
      ASSERT_LT(y[k], highest);
    }
    EXPECT_EQ(test::against_input_moves(v, y), 0);
    auto fine = model.initial_state();
    const auto y_fine = simulate(model, fine, test::upsample_linear(v, 4));
    for (std::size_t k = 0; k < v.size(); ++k)
      ASSERT_EQ(y[k], y_fine[4 * k]) << "k = " << k;
  }
}

// A new maximum wipes out the smaller maxima and the minima between them (the clamps of the
// generalized plays are ordered like those of the classical plays).
TEST(GeneralizedPrandtlIshlinskii, WipesOutDominatedExtrema) {
  const TanhGpi model(test::pi_check_params());
  auto with_history = model.initial_state();
  auto direct = model.initial_state();
  simulate(model, with_history, std::vector<double>{0.0, 1.5, -1.0, 0.7, 0.2, 1.6});
  simulate(model, direct, std::vector<double>{0.0, 1.6});
  for (std::size_t j = 0; j < model.size(); ++j)
    EXPECT_DOUBLE_EQ(with_history.play[j], direct.play[j]) << "j = " << j;
  simulate(model, with_history, std::vector<double>{-0.5, 0.9, -0.2, 0.3, -1.8});
  simulate(model, direct, std::vector<double>{-1.8});
  for (std::size_t j = 0; j < model.size(); ++j)
    EXPECT_DOUBLE_EQ(with_history.play[j], direct.play[j]) << "j = " << j;
}

// (rho, tau, alpha, a0, a3, b0, b3) -> (c rho, c tau, alpha/c, a0/c, a3/c, b0/c, b3/c) is an exact
// symmetry: the same output for every input.
TEST(GeneralizedPrandtlIshlinskii, DensityRescalingLeavesTheOutputUnchanged) {
  const auto params = test::msma_params();
  const TanhGpi model(params);
  auto v = test::random_walk(3000, 12, 4.0, 0.3);
  for (double& x : v)
    x += 4.0;
  for (double factor : {0.01, 0.5, 3.0, 250.0}) {
    SCOPED_TRACE(testing::Message() << "factor " << factor);
    const TanhGpi scaled(rescale_density(params, factor));
    EXPECT_NEAR(scaled.params().rho, 0.143 * factor, 1e-15 * factor);
    auto z = model.initial_state();
    auto z_scaled = scaled.initial_state();
    for (double x : v) {
      const double y = model.step(z, x);
      ASSERT_NEAR(scaled.step(z_scaled, x), y, 1e-12 * (1 + std::abs(y)));
    }
  }
  GpiParams free = params;
  free.density = GpiDensity::free;
  free.thresholds = model.thresholds();
  free.weights = model.weights();
  const GpiParams free_scaled = rescale_density(free, 2.0);
  EXPECT_DOUBLE_EQ(free_scaled.thresholds[3], model.thresholds()[3] / 2);
  EXPECT_DOUBLE_EQ(free_scaled.weights[3], model.weights()[3] * 2);
  EXPECT_DOUBLE_EQ(free_scaled.ascending[0], 20.0);
  EXPECT_HYST_ERROR(rescale_density(params, -1.0), "GPI rescaling factor = -1 must be");
}

TEST(GeneralizedPrandtlIshlinskii, StatesAtRestAndFromAHistory) {
  const TanhGpi model(test::pi_check_params());
  const auto up = model.state_at_rest(0.4);
  const auto down = model.state_at_rest(0.4, LoopBranch::descending);
  EXPECT_EQ(up.play.front(), model.ascending(0.4));
  EXPECT_EQ(down.play.back(), model.descending(0.4));
  EXPECT_NEAR(model.output(up), model.weight_sum() * model.ascending(0.4), 1e-15);
  // At rest, repeating the input changes nothing.
  auto state = up;
  EXPECT_NEAR(model.step(state, 0.4), model.output(up), 1e-15);
  EXPECT_EQ(state.play, up.play);

  state = model.initial_state();
  double last = 0;
  for (double v : test::random_walk(500, 8))
    last = model.step(state, v);
  EXPECT_EQ(model.output(state), last);
  EXPECT_NO_THROW(model.make_state(state.play));
  EXPECT_HYST_ERROR(model.make_state({0, 0}),
                    "GPI state z has 2 values but GPI thresholds r has 9");
  std::vector<double> far(model.size(), 0.0);
  far[3] = 0.5;
  EXPECT_HYST_ERROR(model.make_state(far),
                    "GPI state z[3] = 0.5 and z[2] = 0 differ by 0.5, more than r[3] - r[2]");
  far[3] = NAN;
  EXPECT_HYST_ERROR(model.make_state(far), "GPI state z[3] = nan is not finite");
  EXPECT_HYST_ERROR(model.state_at_rest(NAN), "GPI rest input v0 = nan is not finite");
}

TEST(GeneralizedPrandtlIshlinskii, DensityNamesRoundTrip) {
  EXPECT_EQ(gpi_density_from_string(to_string(GpiDensity::free)), GpiDensity::free);
  EXPECT_EQ(gpi_density_from_string("exponential"), GpiDensity::exponential);
  EXPECT_HYST_ERROR(gpi_density_from_string("gauss"),
                    "unknown GPI density 'gauss' (expected exponential or free)");
}

// Each rule: the message (naming parameter, value and rule) and Error::field().
TEST(GeneralizedPrandtlIshlinskii, RejectsBadParametersNamingThem) {
  struct Case {
    GpiParams params;
    std::string message;
    std::string field;
  };
  const auto base = test::pi_check_params();
  auto with = [&](auto change) {
    GpiParams p = base;
    change(p);
    return p;
  };
  const std::vector<Case> cases{
      {with([](GpiParams& p) { p.rho = -0.1; }), "GPI density rho = -0.1 must be > 0", "rho"},
      {with([](GpiParams& p) { p.rho = NAN; }), "GPI density rho = nan is not finite", "rho"},
      {with([](GpiParams& p) { p.alpha = 0; }), "GPI threshold spacing alpha = 0 must be > 0",
       "alpha"},
      {with([](GpiParams& p) { p.tau = INFINITY; }), "GPI density tau = inf is not finite", "tau"},
      {with([](GpiParams& p) { p.tau = -1e3; }), "tau * alpha * m is too large", "tau"},
      {with([](GpiParams& p) { p.m = 5'000'000; }), "GPI m = 5000000 must be <= 1000000", "m"},
      {with([](GpiParams& p) { p.ascending[1] = -0.8; }),
       "GPI ascending envelope (tanh) coefficient a1 = -0.8 must have the sign of a0 = 2",
       "ascending[1]"},
      {with([](GpiParams& p) { p.descending[0] = 0; }),
       "GPI descending envelope (tanh) coefficient b0 = 0 must be nonzero", "descending[0]"},
      {with([](GpiParams& p) { p.descending.pop_back(); }),
       "GPI descending envelope has 3 coefficients but a tanh envelope needs 4 (b0..b3)",
       "descending"},
      {with([](GpiParams& p) { std::swap(p.ascending, p.descending); }),
       "GPI envelopes violate the ordering gamma_l(v) <= gamma_r(v) at v = -3", "descending"},
      {with([](GpiParams& p) { p.input_min = NAN; }), "GPI operating range input_min = nan",
       "input_min"},
      {with([](GpiParams& p) { p.input_max = -4; }),
       "GPI operating range input_min = -3 must be < input_max = -4", "input_max"},
      {with([](GpiParams& p) { p.initial_input = 5; }),
       "GPI initial input i0 = 5 must lie in the operating range [-3, 3]", "initial_input"},
      {with([](GpiParams& p) { p.envelope = EnvelopeKind::arctan; }),
       "GPI envelope = arctan does not match the model type, whose envelope is tanh", "envelope"},
      {with([](GpiParams& p) {
         p.thresholds = {0, 1};
       }),
       "GPI thresholds are given (2 values) but density = exponential", "thresholds"},
      {with([](GpiParams& p) {
         p.density = GpiDensity::free;
         p.thresholds = {0, 0.2, 0.1};
         p.weights = {1, 1, 1};
       }),
       "GPI threshold r[2] = 0.1 must be > r[1] = 0.2", "thresholds[2]"},
      {with([](GpiParams& p) {
         p.density = GpiDensity::free;
         p.thresholds = {0.1, 0.2};
         p.weights = {1, 1};
       }),
       "GPI threshold r[0] = 0.1 must be 0", "thresholds[0]"},
      {with([](GpiParams& p) {
         p.density = GpiDensity::free;
         p.thresholds = {0, 0.2, 0.3};
         p.weights = {1, -0.5, -0.75};
       }),
       "GPI partial sum S[2] = p[0] + ... + p[2] = -0.25 must be > 0", "weights[2]"},
      {with([](GpiParams& p) {
         p.density = GpiDensity::free;
         p.thresholds = {0, 0.2};
         p.weights = {0, 1};
       }),
       "GPI weight p[0] = 0 must be > 0", "weights[0]"},
      {with([](GpiParams& p) {
         p.density = GpiDensity::free;
         p.thresholds = {0, 0.2};
         p.weights = {1};
       }),
       "GPI has 2 thresholds r but 1 weights p", "weights"},
      {with([](GpiParams& p) {
         p.density = GpiDensity::free;
         p.thresholds = {};
       }),
       "GPI thresholds r is empty (density = free)", "thresholds"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.message);
    EXPECT_HYST_ERROR(TanhGpi{c.params}, c.message);
    try {
      TanhGpi model(c.params);
    } catch (const Error& error) {
      EXPECT_EQ(error.field(), c.field);
    }
  }
}

}  // namespace
}  // namespace hyst
