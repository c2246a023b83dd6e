// Rate-dependent PI: the classical PI at zero rate (beta = 0, and as the frequency goes to 0,
// within the analytic bound), loops that widen with frequency, the rate filter and validation.

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_rate_dependent_prandtl_ishlinskii.hpp"
#include "hyst/models/rate_dependent_prandtl_ishlinskii.hpp"

namespace hyst {
namespace {

constexpr double kTs = 1e-4;

std::vector<double> sine(double frequency, int periods) {
  const auto samples = static_cast<std::size_t>(periods / (frequency * kTs)) + 1;
  std::vector<double> v(samples);
  for (std::size_t k = 0; k < samples; ++k)
    v[k] = std::sin(2 * std::numbers::pi * frequency * static_cast<double>(k) * kTs);
  return v;
}

// Area enclosed by the (v, y) loop of the last period (shoelace formula).
double last_loop_area(const std::vector<double>& v, const std::vector<double>& y,
                      std::size_t period) {
  double area = 0.0;
  for (std::size_t k = v.size() - period; k < v.size(); ++k)
    area += v[k - 1] * y[k] - v[k] * y[k - 1];
  return std::abs(area) / 2.0;
}

TEST(RateDependentPrandtlIshlinskii, WithoutRateGainItIsTheClassicalPi) {
  auto params = rate_dependent_pi_exponential(0.1, 1.0, 0.5, 8, 0.0, kTs);
  params.offset = 0.3;
  const RateDependentPrandtlIshlinskii model(params);
  auto state = model.initial_state();
  auto pi_state = model.classical().initial_state();
  for (double v : test::random_walk(5000, 31, 1.5, 0.2))
    ASSERT_NEAR(model.step(state, v), model.classical().step(pi_state, v), 1e-12);
}

TEST(RateDependentPrandtlIshlinskii, TendsToTheClassicalPiAtZeroRate) {
  // |F_r - F_r'| <= |r - r'| for plays with the same history, so |y - y_PI| <= beta max|vdot|
  // sum_{j>=1} |p_j|; for a unit sine max|vdot| = 2 pi f -> 0 with f.
  const auto params = rate_dependent_pi_exponential(0.1, 1.0, 0.5, 8, 0.02, kTs);
  const RateDependentPrandtlIshlinskii model(params);
  double weights = 0.0;
  for (std::size_t j = 1; j < params.weights.size(); ++j)
    weights += params.weights[j];
  double previous = INFINITY;
  for (double f : {5.0, 1.0, 0.2, 0.01}) {
    const auto v = sine(f, 2);
    auto state = model.initial_state();
    auto pi_state = model.classical().initial_state();
    double worst = 0.0;
    for (double x : v)
      worst = std::max(worst, std::abs(model.step(state, x) - model.classical().step(pi_state, x)));
    const double bound = params.rate_gain * 2 * std::numbers::pi * f * weights;
    EXPECT_LE(worst, bound * (1 + 1e-6)) << "f = " << f;
    EXPECT_LT(worst, previous);
    previous = worst;
  }
  EXPECT_LT(previous, 0.01);  // bound at 0.01 Hz: 0.02 * 2 pi * 0.01 * 7.1 = 0.0089
}

TEST(RateDependentPrandtlIshlinskii, LoopsWidenWithFrequency) {
  const RateDependentPrandtlIshlinskii model(
      rate_dependent_pi_exponential(0.1, 1.0, 0.5, 8, 0.02, kTs));
  auto pi_state = model.classical().initial_state();
  const auto slow = sine(1.0, 3);
  const auto pi_output = simulate(model.classical(), pi_state, slow);
  double area = last_loop_area(slow, pi_output, static_cast<std::size_t>(1 / kTs));
  for (double f : {1.0, 5.0, 20.0}) {
    const auto v = sine(f, 3);
    auto state = model.initial_state();
    const auto y = simulate(model, state, v);
    const double wider = last_loop_area(v, y, static_cast<std::size_t>(1 / (f * kTs)));
    EXPECT_GT(wider, area * 1.01) << "f = " << f;
    area = wider;
  }
}

TEST(RateDependentPrandtlIshlinskii, RateFilterDelaysTheThresholds) {
  auto params = rate_dependent_pi_exponential(0.1, 1.0, 0.0, 4, 0.05, kTs);
  params.rate_filter = 10 * kTs;
  const RateDependentPrandtlIshlinskii model(params);
  auto state = model.initial_state();
  model.step(state, 1e-3);  // raw rate 10: the filtered rate moves Ts / (T_f + Ts) of the way
  EXPECT_NEAR(state.rate, 10.0 / 11.0, 1e-12);
  model.step(state, 1e-3);
  EXPECT_NEAR(state.rate, 10.0 / 11.0 * (10.0 / 11.0), 1e-12);
}

TEST(RateDependentPrandtlIshlinskii, FitRecoversWeightsForAKnownRateGain) {
  auto params = rate_dependent_pi_exponential(0.1, 1.0, 0.5, 6, 0.02, kTs);
  params.offset = -0.3;
  const RateDependentPrandtlIshlinskii truth(params);
  // Sines of three frequencies one after the other: the thresholds move with the rate.
  std::vector<double> v;
  for (double f : {2.0, 10.0, 30.0}) {
    const auto part = sine(f, 3);
    v.insert(v.end(), part.begin(), part.end());
  }
  auto state = truth.initial_state();
  const auto y = simulate(truth, state, v);
  const auto fit = fit_rate_dependent_prandtl_ishlinskii(v, y,
                                                         {.thresholds = params.thresholds,
                                                          .rate_gain = 0.02,
                                                          .sample_time = kTs,
                                                          .min_linear_weight = 1e-12,
                                                          .validate_fraction = 0.2});
  EXPECT_LT(fit.report.fit.rmse, 1e-9);
  EXPECT_LT(fit.report.validation->rmse, 1e-9);
  for (std::size_t j = 0; j < params.weights.size(); ++j)
    EXPECT_NEAR(fit.model.params().weights[j], params.weights[j], 1e-8) << "j = " << j;
  // The classical PI (beta = 0) cannot follow the frequency-dependent loops as well.
  const auto classical = fit_rate_dependent_prandtl_ishlinskii(
      v, y, {.thresholds = params.thresholds, .sample_time = kTs});
  EXPECT_GT(classical.report.fit.rmse, 100 * fit.report.fit.rmse);
}

TEST(RateDependentPrandtlIshlinskii, RejectsInvalidParameters) {
  auto params = rate_dependent_pi_exponential(0.1, 1.0, 0.5, 3, 0.01, kTs);
  params.sample_time = 0;
  EXPECT_HYST_ERROR(RateDependentPrandtlIshlinskii{params},
                    "sample_time = 0 must be finite and > 0");
  params.sample_time = kTs;
  params.rate_gain = -1;
  EXPECT_HYST_ERROR(RateDependentPrandtlIshlinskii{params}, "rate_gain = -1");
  params.rate_gain = 0;
  params.thresholds[0] = 0.1;
  EXPECT_HYST_ERROR(RateDependentPrandtlIshlinskii{params}, "must be 0");
  EXPECT_HYST_ERROR(rate_dependent_pi_exponential(0, 1, 0, 3, 0, kTs), "alpha = 0");
  const RateDependentPrandtlIshlinskii model(
      rate_dependent_pi_exponential(0.1, 1, 0, 2, 0.01, kTs));
  EXPECT_HYST_ERROR(model.make_state({0, 0, 1.0}, 0, 0), "no input history reaches this state");
  EXPECT_NO_THROW(model.make_state({0, 0, 1.0}, 0, 100));  // threshold 0.2 + 0.01 * 100 = 1.2
}

}  // namespace
}  // namespace hyst
