// The numerical (bisection) inverse of the Preisach models: round trips, range limits, the
// iteration bound, options.

#include "hyst/inverse/inverse_preisach.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"

namespace hyst {
namespace {

GaussianPreisach gaussian_model() {
  return GaussianPreisach({.everett = {.lower = -1.0,
                                       .upper = 1.0,
                                       .saturation = 2.0,
                                       .alpha_centre = 0.3,
                                       .alpha_width = 0.25,
                                       .beta_centre = -0.2,
                                       .beta_width = 0.3},
                           .offset = 0.5});
}

Preisach grid_model(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.1, 1.0);
  std::vector<double> mu(preisach_relay_count(21));
  for (double& m : mu)
    m = unit(rng);
  return Preisach({.everett = {.levels = 21, .lower = -1, .upper = 1, .weights = mu}});
}

// model(inverse(y)) = y for reachable targets: the outputs of the model itself on a random input.
template <class Model>
void expect_round_trip(const Model& model, std::uint64_t seed, double tolerance) {
  SCOPED_TRACE(testing::Message() << "seed " << seed);
  const BasicInversePreisach inverse(model);
  auto forward_state = model.initial_state();
  const auto v = test::random_walk(3000, seed, 0.98, 0.2);
  const auto targets = simulate(model, forward_state, v);

  auto inverse_state = inverse.initial_state();
  std::vector<double> inputs(targets.size());
  const InverseReport report = invert(inverse, inverse_state, targets, inputs);
  EXPECT_TRUE(report.ok());
  auto check_state = model.initial_state();
  const auto achieved = simulate(model, check_state, inputs);
  double worst = 0;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    worst = std::max(worst, std::abs(achieved[k] - targets[k]));
    ASSERT_NEAR(achieved[k], targets[k], tolerance) << "k = " << k;
  }
  // The inverse's state is the forward model's state for the inputs it chose.
  EXPECT_EQ(inverse_state.size, check_state.size);
  EXPECT_EQ(model.output(inverse_state), model.output(check_state));
  testing::Test::RecordProperty("worst_round_trip_error", fmt::format("{:.2e}", worst));
}

TEST(InversePreisach, GaussianRoundTrip) {
  for (std::uint64_t seed : {1U, 2U, 3U})
    expect_round_trip(gaussian_model(), seed, 1e-10);
}

TEST(InversePreisach, TabulatedRoundTrip) {
  TabulatedEverett::Params table;
  const std::size_t k = 30;
  const auto gauss = gaussian_model();
  for (std::size_t a = 0; a <= k; ++a)
    table.levels.push_back(-1.0 + 2.0 * static_cast<double>(a) / k);
  for (std::size_t a = 1; a <= k; ++a) {
    for (std::size_t c = 0; c < a; ++c)
      table.values.push_back(gauss.everett()(table.levels[a], table.levels[c]));
  }
  expect_round_trip(TabulatedPreisach({.everett = table, .offset = -1.0}), 4, 1e-10);
}

// The relay grid's output moves in steps; every target it produced is reached exactly.
TEST(InversePreisach, RelayGridRoundTripIsExact) {
  for (std::uint64_t seed : {5U, 6U})
    expect_round_trip(grid_model(seed), seed, 1e-12);
}

// Between reachable steps the nearest reachable output is chosen.
TEST(InversePreisach, RelayGridAnswersWithTheNearestReachableOutput) {
  const Preisach model(
      {.everett = {
           .levels = 21, .lower = -1, .upper = 1, .weights = uniform_relay_weights(21, 1.0)}});
  const InversePreisach inverse(model);
  auto state = inverse.initial_state();
  EXPECT_EQ(inverse.solve(state, -231).input, -1.0);
  EXPECT_EQ(model.output(state), -231.0);
  // From negative saturation the ascending branch moves in steps of 2 (i + 1) relays ... the
  // first threshold reached adds 2: outputs -231, -229, -225, ...
  const InverseSample sample = inverse.solve(state, -228.2);
  EXPECT_EQ(sample.status, InverseStatus::ok);
  EXPECT_EQ(model.output(state), -229.0);
  EXPECT_GE(sample.input, model.everett().thresholds()[0]);
  EXPECT_LT(sample.input, model.everett().thresholds()[1]);
}

TEST(InversePreisach, ANaNTargetHoldsTheLastInput) {
  const auto model = gaussian_model();
  const InverseGaussianPreisach inverse(model, {.input_min = -0.5, .input_max = 0.6});
  auto state = inverse.initial_state();
  const InverseSample first = inverse.solve(state, 0.1);
  const double output = model.output(state);
  const InverseSample held = inverse.solve(state, NAN);
  EXPECT_EQ(held.status, InverseStatus::not_invertible);
  EXPECT_EQ(held.input, first.input);
  EXPECT_EQ(model.output(state), output);
  EXPECT_EQ(inverse.solve(state, INFINITY).input, 0.6);
  EXPECT_EQ(inverse.solve(state, -INFINITY).input, -0.5);
}

TEST(InversePreisach, TargetsOutOfReachAreLimitedWithAStatus) {
  const auto model = gaussian_model();
  const InverseGaussianPreisach inverse(model, {.input_min = -0.5, .input_max = 0.6});
  auto state = inverse.initial_state();
  InverseSample s = inverse.solve(state, 10.0);
  EXPECT_EQ(s.status, InverseStatus::above_range);
  EXPECT_EQ(s.input, 0.6);
  EXPECT_EQ(state.input, 0.6);  // the limit was applied
  s = inverse.solve(state, -10.0);
  EXPECT_EQ(s.status, InverseStatus::below_range);
  EXPECT_EQ(s.input, -0.5);
  // Exactly the saturated output of the whole range is reachable.
  const InverseGaussianPreisach full(model);
  auto other = full.initial_state();
  s = full.solve(other, model.output_max());
  EXPECT_EQ(s.status, InverseStatus::ok);
  EXPECT_NEAR(model.output(other), model.output_max(), 1e-12);
  s = full.solve(other, model.output_min() - 1e-3);
  EXPECT_EQ(s.status, InverseStatus::below_range);
  EXPECT_EQ(s.input, -1.0);
  // Batch inversion counts the limited samples.
  auto batch = inverse.initial_state();
  std::vector<double> targets{0.0, 5.0, 0.4, -5.0};
  std::vector<double> inputs(targets.size());
  const auto report = invert(inverse, batch, targets, inputs);
  EXPECT_EQ(report.saturated_samples, 2U);
  EXPECT_EQ(report.first_saturated, 1U);
}

TEST(InversePreisach, SearchIsBoundedAndTerminates) {
  const auto model = gaussian_model();
  const InverseGaussianPreisach inverse(model);
  EXPECT_EQ(inverse.max_iterations(), 164U);  // 4 ceil(log2(1e12)) + 4
  // A tolerance below the double spacing: the bisection stops when no double is left between.
  const InverseGaussianPreisach fine(model, {.input_tolerance = 1e-300});
  EXPECT_EQ(fine.max_iterations(), 600U);
  auto state = fine.initial_state();
  for (double y : test::random_walk(200, 9, 2.4, 0.5))
    fine.solve(state, y);
  // An output tolerance ends the search early with an output that close.
  const InverseGaussianPreisach coarse(model, {.output_tolerance = 1e-3});
  auto s1 = coarse.initial_state();
  for (double y : test::random_walk(200, 10, 2.0, 0.3)) {
    coarse.solve(s1, y);
    ASSERT_NEAR(model.output(s1), std::clamp(y, model.output_min(), model.output_max()), 1e-3);
  }
}

TEST(InversePreisach, RejectsBadOptions) {
  const auto model = gaussian_model();
  EXPECT_HYST_ERROR(InverseGaussianPreisach(model, {.input_min = 2.0, .input_max = 1.0}),
                    "inverse Preisach input_min = 2 must be < input_max = 1");
  EXPECT_HYST_ERROR(InverseGaussianPreisach(model, {.input_max = NAN}),
                    "inverse Preisach input_min = -1 must be < input_max = nan");
  EXPECT_HYST_ERROR(InverseGaussianPreisach(model, {.input_tolerance = 0.0}),
                    "inverse Preisach input_tolerance = 0 must be > 0");
  EXPECT_HYST_ERROR(InverseGaussianPreisach(model, {.output_tolerance = -1.0}),
                    "inverse Preisach output_tolerance = -1 must be >= 0");
}

}  // namespace
}  // namespace hyst
