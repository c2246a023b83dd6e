#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/registry/model_file.hpp"

namespace hyst {
namespace {

// The parameter set of pi_check.py and pi_init_check.py.
PrandtlIshlinskii reference_model() {
  return PrandtlIshlinskii(
      {.thresholds = {0, 0.3, 0.7, 1.0, 1.6, 2.2}, .weights = {0.8, 0.5, 0.3, 0.2, 0.1, 0.05}});
}

double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    worst = std::max(worst, std::abs(a[k] - b[k]));
  return worst;
}

// pi_check.py prints r_hat = [0, 0.24, 0.76, 1.24, 2.32, 3.46] and
// p_hat = [1.25, -0.4808, -0.1442, -0.0694, -0.0292, -0.0135] (4 decimals).
TEST(InversePrandtlIshlinskii, ParametersMatchThePythonCheck) {
  const InversePrandtlIshlinskii inverse(reference_model());
  const auto& params = inverse.inverse_operator().params();
  const std::vector<double> r_hat{0, 0.24, 0.76, 1.24, 2.32, 3.46};
  const std::vector<double> p_hat{1.25, -0.4808, -0.1442, -0.0694, -0.0292, -0.0135};
  for (std::size_t j = 0; j < r_hat.size(); ++j) {
    EXPECT_NEAR(params.thresholds[j], r_hat[j], 1e-12) << "j = " << j;
    EXPECT_NEAR(params.weights[j], p_hat[j], 5e-5) << "j = " << j;
  }
  // Exact by hand: p_hat_1 = -p_1 / (S_1 S_0) = -0.5 / (1.3 * 0.8).
  EXPECT_NEAR(params.weights[1], -0.5 / 1.04, 1e-15);
  EXPECT_EQ(params.offset, 0.0);
}

// The inverse of the inverse is the model again (the formulas are an involution).
TEST(InversePrandtlIshlinskii, InvertingTwiceGivesTheModelBack) {
  const auto model = reference_model();
  const InversePrandtlIshlinskii inverse(model);
  const InversePrandtlIshlinskii twice(inverse.inverse_operator());
  for (std::size_t j = 0; j < model.size(); ++j) {
    EXPECT_NEAR(twice.inverse_operator().params().thresholds[j], model.params().thresholds[j],
                1e-14);
    EXPECT_NEAR(twice.inverse_operator().params().weights[j], model.params().weights[j], 1e-14);
  }
}

// pi_check.py: max |P[P^-1[y_d]] - y_d| = 1.78e-15 and max |P^-1[P[v]] - v| = 2.22e-15.
TEST(InversePrandtlIshlinskii, RoundTripsOnTheReferenceSignal) {
  const auto model = reference_model();
  const InversePrandtlIshlinskii inverse(model);
  const auto signal = test::pi_check_signal();

  auto inverse_state = inverse.initial_state();
  auto model_state = model.initial_state();
  std::vector<double> input(signal.size());
  EXPECT_TRUE(invert(inverse, inverse_state, signal, input).ok());
  EXPECT_LE(max_abs_difference(simulate(model, model_state, input), signal), 1e-12);

  inverse_state = inverse.initial_state();
  model_state = model.initial_state();
  const auto output = simulate(model, model_state, signal);
  EXPECT_LE(max_abs_difference(simulate(inverse, inverse_state, output), signal), 1e-12);
}

TEST(InversePrandtlIshlinskii, RoundTripsWithOffsetAndNegativeWeightsOnRandomModels) {
  std::mt19937_64 rng(77);
  for (int trial = 0; trial < 25; ++trial) {
    const std::uint64_t seed = rng();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 draw(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PrandtlIshlinskii::Params params{{0.0}, {0.2 + unit(draw)}, 4 * unit(draw) - 2};
    double partial_sum = params.weights[0];
    const std::size_t n = 2 + draw() % 30;
    for (std::size_t j = 1; j < n; ++j) {
      params.thresholds.push_back(params.thresholds.back() + 0.02 + 0.15 * unit(draw));
      // Signed weights that keep every partial sum >= 10% of the running total.
      const double weight = (unit(draw) - 0.4) * partial_sum;
      params.weights.push_back(weight);
      partial_sum += weight;
    }
    const PrandtlIshlinskii model(params);
    const InversePrandtlIshlinskii inverse(model);
    const auto v = test::random_walk(3000, seed, 3.0, 0.25);
    auto z = model.initial_state();
    auto zh = inverse.initial_state();
    const auto y = simulate(model, z, v);
    const auto v_back = simulate(inverse, zh, y);
    ASSERT_LE(max_abs_difference(v_back, v), 1e-11);
  }
}

// pi_init_check.py: after an arbitrary history, the inverse started from
// wh_j = S_j z_j + sum_{i>j} p_i z_i reproduces the input (2.2e-15); the naive "all wh_j = y"
// and the transposed rule leave errors of 0.045 and 0.030 on that check's data.
TEST(InversePrandtlIshlinskii, ConsistentInitialStateAfterAnArbitraryHistory) {
  const auto model = reference_model();
  const InversePrandtlIshlinskii inverse(model);
  for (std::uint64_t seed : {5u, 6u, 7u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    auto z = model.initial_state();
    const auto history = test::random_walk(300, seed, 3.0, 0.3);
    simulate(model, z, history);
    std::vector<double> v(3000);
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double t = static_cast<double>(k);
      v[k] = history.back() + 1.5 * std::sin(2 * std::numbers::pi * t / 700) * std::exp(-t / 2500) +
             0.3 * std::sin(2 * std::numbers::pi * t / 90);
    }
    const auto run_inverse_from = [&](PrandtlIshlinskii::State start) {
      auto forward_state = z;
      auto inverse_state = std::move(start);
      const auto y = simulate(model, forward_state, v);
      return max_abs_difference(simulate(inverse, inverse_state, y), v);
    };
    EXPECT_LE(run_inverse_from(inverse.state_consistent_with(z)), 1e-12);

    const double y0 = model.output(z);
    const double naive_error = run_inverse_from({std::vector<double>(model.size(), y0)});
    std::vector<double> transposed(model.size());
    for (std::size_t j = 0; j < model.size(); ++j) {
      double below = 0, above = 0;
      for (std::size_t i = 0; i <= j; ++i)
        below += model.params().weights[i] * z.play[i];
      for (std::size_t i = j + 1; i < model.size(); ++i)
        above += model.params().weights[i];
      transposed[j] = below + above * z.play[j];
    }
    const double transposed_error = run_inverse_from({transposed});
    // The pitfall documented by the reference: both wrong rules fail visibly.
    if (naive_error < 1e-6 || transposed_error < 1e-6) {
      ADD_FAILURE() << "wrong initial-state rules should fail on this history: naive "
                    << naive_error << ", transposed " << transposed_error;
    }
  }
}

TEST(InversePrandtlIshlinskii, StateMapsAreInversesOfEachOther) {
  const auto model = reference_model();
  const InversePrandtlIshlinskii inverse(model);
  auto z = model.initial_state();
  simulate(model, z, test::random_walk(400, 9, 3.0, 0.3));
  const auto back = inverse.forward_state_consistent_with(inverse.state_consistent_with(z));
  for (std::size_t j = 0; j < model.size(); ++j)
    EXPECT_NEAR(back.play[j], z.play[j], 1e-13);
  // At rest: all forward plays at u0 correspond to all inverse plays at y0 = S_n u0.
  const auto rest = inverse.state_consistent_with(model.state_at_rest(0.5));
  for (double w : rest.play)
    EXPECT_NEAR(w, model.output(model.state_at_rest(0.5)), 1e-15);
}

TEST(InversePrandtlIshlinskii, ReportsSaturationInsteadOfThrowing) {
  const auto model = reference_model();
  const InversePrandtlIshlinskii inverse(model, {.input_min = -1.0, .input_max = 1.0});
  auto state = inverse.initial_state();
  const std::vector<double> targets{0.0, 0.5, 5.0, 0.0, -5.0, 0.0};
  std::vector<double> inputs(targets.size());
  const auto report = invert(inverse, state, targets, inputs);
  EXPECT_EQ(report.saturated_samples, 2u);
  EXPECT_EQ(report.first_saturated, 2u);
  EXPECT_EQ(inputs[2], 1.0);
  EXPECT_EQ(inputs[4], -1.0);
  auto fresh = inverse.initial_state();
  EXPECT_EQ(inverse.solve(fresh, 5.0).status, InverseStatus::above_range);
  EXPECT_EQ(inverse.solve(fresh, -5.0).status, InverseStatus::below_range);
  EXPECT_EQ(inverse.solve(fresh, 0.0).status, InverseStatus::ok);
  EXPECT_EQ(to_string(InverseStatus::above_range), "above_range");
}

// A NaN target holds the last input and leaves the state as it was; +-inf and 1e308 (where the
// inverse operator's sum would overflow) are answered as the target bound, then limited.
TEST(InversePrandtlIshlinskii, NonFiniteAndOverflowingTargetsNeverGiveNaN) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const auto model = reference_model();
  for (const double limit : {1.0, kInf}) {
    const InversePrandtlIshlinskii inverse(model, {-limit, limit});
    auto state = inverse.initial_state();
    const InverseSample first = inverse.solve(state, 0.3);
    ASSERT_EQ(first.status, InverseStatus::ok);
    const auto before = state.play;
    const InverseSample held = inverse.solve(state, NAN);
    EXPECT_EQ(held.status, InverseStatus::not_invertible);
    EXPECT_EQ(held.input, first.input);
    EXPECT_EQ(state.play, before);
    for (const double target : {1e308, kInf, -1e308, -kInf}) {
      auto from = state;
      const InverseSample answer = inverse.solve(from, target);
      EXPECT_TRUE(std::isfinite(answer.input)) << limit << " " << target;
      EXPECT_EQ(answer.status,
                target > 0 ? InverseStatus::above_range : InverseStatus::below_range);
      if (std::isfinite(limit)) {
        EXPECT_EQ(answer.input, target > 0 ? limit : -limit);
      }
      // Rising to the bound moves every play to bound -+ rh_j: v = sum_j ph_j (bound - rh_j).
      if (!std::isfinite(limit) && target > 0) {
        const auto& p = inverse.inverse_operator().params();
        double expected = 0.0;
        for (std::size_t j = 0; j < p.weights.size(); ++j)
          expected += p.weights[j] * (inverse.target_bound() - p.thresholds[j]);
        EXPECT_NEAR(answer.input, expected, 1e-12 * std::abs(expected));
      }
      EXPECT_TRUE(std::isfinite(inverse.solve(from, 0.5).input));
    }
  }
  // The batch inverse of `hyst invert` gives the same answers.
  const nlohmann::json document = {
      {"model", "pi"},
      {"version", 1},
      {"params", {{"thresholds", model.params().thresholds}, {"weights", model.params().weights}}}};
  const auto batch = model_from_json(document, "test")->inverse({-INFINITY, INFINITY});
  const std::vector<double> targets{0.3, 1e308, -1e308, 0.5};
  std::vector<double> inputs(targets.size()), expected(targets.size());
  const InversePrandtlIshlinskii inverse(model);
  auto state = inverse.initial_state();
  const auto expected_report = invert(inverse, state, targets, expected);
  const auto report = batch->invert(targets, inputs);
  EXPECT_EQ(report.limited_samples, 2u);
  EXPECT_EQ(expected_report.limited_samples, 2u);
  for (std::size_t k = 0; k < targets.size(); ++k)
    EXPECT_NEAR(inputs[k], expected[k], 1e-12 * std::abs(expected[k])) << k;
}

// Equal weights c on equally spaced thresholds r_j = j h: S_j = c (j + 1), so in closed form
// rh_j = c h j (j + 1) / 2 and ph_j = -1 / (c j (j + 1)) for j > 0. 10^5 operators: the inverse is
// built in linear time (the nested sums took seconds).
TEST(InversePrandtlIshlinskii, ClosedFormParametersForManyEqualOperators) {
  constexpr std::size_t m = 100000;
  constexpr double c = 0.25;
  constexpr double h = 1e-3;
  std::vector<double> r(m);
  for (std::size_t j = 0; j < m; ++j)
    r[j] = static_cast<double>(j) * h;
  const InversePrandtlIshlinskii inverse(PrandtlIshlinskii({r, std::vector<double>(m, c)}));
  const auto& rh = inverse.inverse_operator().params().thresholds;
  const auto& ph = inverse.inverse_operator().params().weights;
  EXPECT_EQ(ph[0], 4.0);
  for (const std::size_t j : {std::size_t{1}, std::size_t{2}, std::size_t{777}, m / 2, m - 1}) {
    const double jd = static_cast<double>(j);
    EXPECT_NEAR(rh[j], c * h * jd * (jd + 1.0) / 2.0, 1e-12 * c * h * jd * (jd + 1.0)) << j;
    EXPECT_NEAR(ph[j], -1.0 / (c * jd * (jd + 1.0)), 1e-12 / (c * jd * (jd + 1.0))) << j;
  }
}

// A subnormal weight p_0 = 1e-320 is a valid forward model, but 1/p_0 overflows: the inverse is
// refused, naming the weight as written, not its overflowed inverse ("p[0] = inf").
TEST(InversePrandtlIshlinskii, RefusesWeightsWhoseInverseOverflows) {
  const PrandtlIshlinskii tiny({{0, 1}, {1e-320, 1.0}});
  EXPECT_TRUE(tiny.is_invertible());
  EXPECT_HYST_ERROR(InversePrandtlIshlinskii{tiny},
                    "PI weight p[0] = 1e-320 is too small for the inverse: its inverse weight "
                    "1/p[0] overflows");
  try {
    static_cast<void>(InversePrandtlIshlinskii(tiny));
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "weights[0]");
    EXPECT_EQ(std::string(error.what()).find("inf"), std::string::npos) << error.what();
  }
  // The smallest normal weight still has a finite inverse 1/p_0 = 4.49e307.
  const InversePrandtlIshlinskii smallest(
      PrandtlIshlinskii({{0, 1}, {2.2250738585072014e-308, 1}}));
  EXPECT_EQ(smallest.inverse_operator().params().weights[0], 1.0 / 2.2250738585072014e-308);
}

TEST(InversePrandtlIshlinskii, RejectsModelsWithoutInverse) {
  EXPECT_HYST_ERROR(InversePrandtlIshlinskii(PrandtlIshlinskii({{0, 1}, {-0.5, 1.0}})),
                    "PI weight p[0] = -0.5 must be > 0 for the inverse to exist");
  EXPECT_HYST_ERROR(InversePrandtlIshlinskii(PrandtlIshlinskii({{0, 1}, {0.0, 1.0}})),
                    "PI weight p[0] = 0 must be > 0");
  EXPECT_HYST_ERROR(
      InversePrandtlIshlinskii(PrandtlIshlinskii({{0, 1, 2, 3}, {1.0, 0.5, -1.0, -0.75}})),
      "PI partial sum S[3] = p[0] + ... + p[3] = -0.25 must be > 0");
  EXPECT_HYST_ERROR(InversePrandtlIshlinskii(reference_model(), {.input_min = 1, .input_max = 0}),
                    "v_min = 1 and v_max = 0 must satisfy v_min <= v_max");
  const InversePrandtlIshlinskii inverse(reference_model());
  auto state = inverse.initial_state();
  std::vector<double> targets{0.0, NAN};
  std::vector<double> inputs(2);
  EXPECT_HYST_ERROR(invert(inverse, state, targets, inputs), "targets[1] = nan is not finite");
}

// The registry's inverse (`hyst invert`, Python) runs batches by segments and binary search
// (src/registry/pi_batch_inverse.hpp) from 40 plays on (the step inverse below, which is faster
// there; most trials below have more); it must agree with solve() sample by sample: same inputs and
// statuses up to rounding, same final state. Random models, a history before the inversion (a
// non-trivial start state), a random walk with reversals at every scale, input limits.
TEST(InversePrandtlIshlinskii, RegistryBatchInverseAgreesWithSolve) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t m = 1 + static_cast<std::size_t>(random() % 400);
    std::uniform_real_distribution<double> gap(0.001, 0.05);
    std::uniform_real_distribution<double> weight(-0.01, 0.1);
    PrandtlIshlinskii::Params params;
    double r = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
      params.thresholds.push_back(r);
      r += gap(random);
      params.weights.push_back(j == 0 ? 1.0 : weight(random));
    }
    params.offset = 0.3;
    const PrandtlIshlinskii model(params);
    if (!model.is_invertible()) continue;
    std::uniform_real_distribution<double> step(-0.3, 0.3);
    std::vector<double> history(50), targets(3000);
    double v = 0.0;
    for (auto& x : history)
      x = v += step(random);
    for (auto& y : targets)
      y = v += step(random) * (trial % 2 == 0 ? 1.0 : 0.1);
    auto model_state = model.initial_state();
    static_cast<void>(simulate(model, model_state, history));

    const double limit = trial % 3 == 0 ? 2.0 : INFINITY;
    const InversePrandtlIshlinskii inverse(model, {-limit, limit});
    auto state = inverse.state_consistent_with(model_state);
    std::vector<double> expected(targets.size());
    const auto expected_report = invert(inverse, state, targets, expected);

    const nlohmann::json document = {
        {"model", "pi"},
        {"version", 1},
        {"params",
         {{"thresholds", params.thresholds}, {"weights", params.weights}, {"offset", 0.3}}},
        {"state", {{"play", model_state.play}}}};
    const auto dynamic = model_from_json(document, "test");
    const auto batch = dynamic->inverse({-limit, limit});
    std::vector<double> inputs(targets.size());
    const auto report = batch->invert(targets, inputs);
    EXPECT_EQ(report.saturated_samples, expected_report.saturated_samples) << trial;
    EXPECT_EQ(report.first_saturated, expected_report.first_saturated) << trial;
    for (std::size_t k = 0; k < targets.size(); ++k)
      ASSERT_NEAR(inputs[k], expected[k], 1e-10 * (1.0 + std::abs(expected[k])))
          << "trial " << trial << ", m " << m << ", sample " << k;
    const auto play = batch->state()["play"].get<std::vector<double>>();
    ASSERT_EQ(play.size(), m);
    for (std::size_t j = 0; j < m; ++j)
      ASSERT_NEAR(play[j], state.play[j], 1e-12 * (1.0 + std::abs(state.play[j])))
          << "trial " << trial << ", play " << j;
  }
}

}  // namespace
}  // namespace hyst
