// Krasnosel'skii-Pokrovskii model: one kernel against the reference's direction-switched form,
// the a -> 0 limit against the Preisach relay grid, saturation, closed minor loops, monotonicity,
// rate independence and the NNLS fit.

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_krasnoselskii_pokrovskii.hpp"
#include "hyst/models/krasnoselskii_pokrovskii.hpp"
#include "hyst/models/preisach_relay_grid.hpp"

namespace hyst {
namespace {

std::vector<double> varied_weights(std::size_t levels) {
  std::vector<double> mu(levels * (levels + 1) / 2);
  for (std::size_t r = 0; r < mu.size(); ++r)
    mu[r] = 0.1 + 0.05 * static_cast<double>((r * 7) % 5);
  return mu;
}

TEST(KrasnoselskiiPokrovskii, OneKernelMatchesTheDirectionSwitchedForm) {
  // N = 4 on [-1, 1]: s_k = -1 + 0.5 k, a = 0.5. Only kernel (i, j) = (3, 1) weighted:
  // s2 = 0.5, s1 = -0.5. operators.md sec. 6: rising max(kappa, rho(v - s2)), falling
  // min(kappa, rho(v - s1)).
  std::vector<double> mu(10, 0.0);
  mu[3 * 4 / 2 + 1] = 1.0;
  const KrasnoselskiiPokrovskii model({.levels = 4, .lower = -1, .upper = 1, .weights = mu});
  const auto ridge = [](double x) { return std::clamp(-1.0 + 2.0 * x / 0.5, -1.0, 1.0); };
  const auto v = test::random_walk(5000, 3, 1.3, 0.1);
  auto state = model.initial_state();
  double kappa = -1.0;
  double previous = 0.0;
  for (double x : v) {
    if (x > previous) kappa = std::max(kappa, ridge(x - 0.5));
    if (x < previous) kappa = std::min(kappa, ridge(x + 0.5));
    previous = x;
    ASSERT_NEAR(model.step(state, x), kappa, 1e-15);
  }
}

TEST(KrasnoselskiiPokrovskii, NarrowRampsGiveThePreisachRelayGrid) {
  // Relay thresholds at the cell centres of [lower - D/2, upper - D/2] are the KP thresholds
  // s_k = lower + k D; with a -> 0 every kernel is that relay.
  const std::size_t n = 8;
  const auto mu = varied_weights(n);
  const KrasnoselskiiPokrovskii kp(
      {.levels = n, .lower = -1, .upper = 1, .weights = mu, .ramp_cells = 1e-9});
  const double cell = 2.0 / n;
  const PreisachRelayGrid relays(
      {.everett = {.levels = n, .lower = -1 - cell / 2, .upper = 1 - cell / 2, .weights = mu}});
  // Started off the thresholds: an input exactly on one ties differently (relay: +1 at v = alpha;
  // kernel: +1 only from alpha + a on).
  const auto v = signals::generate(
      signals::TimeGrid{4000, 1.0},
      signals::RandomWalk{.max_step = 0.13, .lower = -1.2, .upper = 1.2, .start = 0.1, .seed = 5});
  auto kp_state = kp.initial_state();
  auto relay_state = relays.initial_state();
  for (double x : v)
    ASSERT_NEAR(kp.step(kp_state, x), relays.step(relay_state, x), 1e-12);
}

TEST(KrasnoselskiiPokrovskii, SaturatesClosesMinorLoopsAndIsMonotone) {
  const auto mu = varied_weights(10);
  const KrasnoselskiiPokrovskii model(
      {.levels = 10, .lower = -1, .upper = 1, .weights = mu, .offset = 0.5});
  auto state = model.initial_state();
  EXPECT_NEAR(model.step(state, 1.0), 0.5 + model.total_weight(), 1e-12);
  EXPECT_NEAR(model.step(state, -1.0), 0.5 - model.total_weight(), 1e-12);
  // A minor loop between -0.3 and 0.45, twice: the second pass repeats the first exactly.
  model.step(state, 0.8);
  std::vector<double> loop;
  for (int k = 0; k <= 40; ++k)
    loop.push_back(0.45 - 0.75 * std::abs(1.0 - k / 20.0));
  std::vector<double> first, second;
  for (double x : loop)
    first.push_back(model.step(state, x));
  for (double x : loop)
    second.push_back(model.step(state, x));
  for (std::size_t k = 0; k < loop.size(); ++k)
    EXPECT_EQ(first[k], second[k]) << "k = " << k;

  const auto v = test::random_walk(10000, 9, 1.1, 0.07);
  auto walk = model.initial_state();
  const auto y = simulate(model, walk, v);
  for (std::size_t k = 1; k < v.size(); ++k)
    ASSERT_GE((y[k] - y[k - 1]) * (v[k] - v[k - 1]), -1e-13) << "k = " << k;
  auto fine_state = model.initial_state();
  const auto fine = simulate(model, fine_state, test::upsample_linear(v, 3));
  for (std::size_t k = 0; k < v.size(); ++k)
    ASSERT_NEAR(fine[3 * k], y[k], 1e-12);
}

TEST(KrasnoselskiiPokrovskii, FitRecoversAModelOnTheSameGrid) {
  const KrasnoselskiiPokrovskii truth(
      {.levels = 6, .lower = -1, .upper = 1, .weights = varied_weights(6), .offset = 0.2});
  // A decaying oscillation from beyond the grid moves every kernel (reversals at every
  // amplitude); the random walk after it is the held-out part.
  auto v = signals::generate(
      signals::TimeGrid{2400, 1e-3},
      signals::DecayingSine{.amplitude = 1.3, .frequency = 10, .time_constant = 0.8});
  const auto walk = test::random_walk(600, 11, 1.0, 0.08);
  v.insert(v.end(), walk.begin(), walk.end());
  auto state = truth.initial_state();
  const auto y = simulate(truth, state, v);
  const auto fit = fit_krasnoselskii_pokrovskii(
      v, y, {.levels = 6, .lower = -1, .upper = 1, .validate_fraction = 0.2});
  EXPECT_EQ(fit.report.model, "kp");
  EXPECT_LT(fit.report.fit.rmse, 1e-9);
  ASSERT_TRUE(fit.report.validation.has_value());
  EXPECT_LT(fit.report.validation->rmse, 1e-9);
  EXPECT_NEAR(fit.model.params().offset, 0.2, 1e-8);
}

TEST(KrasnoselskiiPokrovskii, RejectsInvalidParametersAndData) {
  EXPECT_HYST_ERROR(KrasnoselskiiPokrovskii({.levels = 0}), "KP levels N = 0");
  EXPECT_HYST_ERROR(KrasnoselskiiPokrovskii({.levels = 2, .lower = 1, .upper = 1}),
                    "KP upper = 1 must be finite and > lower = 1");
  EXPECT_HYST_ERROR(KrasnoselskiiPokrovskii({.levels = 2, .weights = {1, 1}}),
                    "KP has 2 weights but N = 2 levels need N(N+1)/2 = 3");
  EXPECT_HYST_ERROR(KrasnoselskiiPokrovskii({.levels = 2, .weights = {1, -1, 1}}),
                    "KP weight mu[1] = -1 must be finite and >= 0");
  EXPECT_HYST_ERROR(KrasnoselskiiPokrovskii({.levels = 1, .weights = {1}, .ramp_cells = 0}),
                    "KP ramp_cells = 0");
  const KrasnoselskiiPokrovskii model({.levels = 1, .weights = {1}});
  EXPECT_HYST_ERROR(model.make_state({2.0}), "kernel[0] = 2 must be in [-1, 1]");
  const std::vector<double> flat(50, 1.0);
  const auto v = test::random_walk(50, 1);
  EXPECT_HYST_ERROR(fit_krasnoselskii_pokrovskii(flat, v, {.levels = 2}),
                    "input of the fit part is constant");
  EXPECT_HYST_ERROR(fit_krasnoselskii_pokrovskii(v, v, {.levels = 12}), "fewer than unknowns");
}

}  // namespace
}  // namespace hyst
