// Bouc-Wen oscillator fit: known parameters recovered from simulated noisy data (short record);
// bad input named.

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/identify/fit_bouc_wen_oscillator.hpp"

namespace hyst {
namespace {

std::vector<double> force(std::size_t n) {
  std::vector<double> u(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) / 750.0;
    u[k] = 40.0 * std::sin(2 * M_PI * 12.0 * t) + 25.0 * std::sin(2 * M_PI * 31.0 * t + 1.0) +
           20.0 * std::sin(2 * M_PI * 47.0 * t + 2.0);
  }
  return u;
}

TEST(FitBoucWenOscillator, RecoversKnownParametersFromNoisyData) {
  const auto truth = BoucWenOscillator::benchmark();
  const auto u = force(1500);
  auto y = simulate_bouc_wen_oscillator(BoucWenOscillator(truth), u, 1);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 2e-6);  // ~0.5 % of the output RMS
  for (double& value : y)
    value += noise(rng);
  BoucWenOscillatorFitOptions options;
  options.substeps = truth.substeps;
  auto start = truth;  // perturbed by 10-25 %
  start.mass *= 1.2;
  start.damping *= 0.8;
  start.stiffness *= 0.85;
  start.alpha *= 1.15;
  start.gamma *= 1.25;
  start.delta *= 0.8;
  options.starts = {start};
  options.max_iterations = 30;
  const auto fit = fit_bouc_wen_oscillator(u, y, options);
  EXPECT_EQ(fit.report.termination, Termination::converged) << fit.report.message;
  const auto& p = fit.model.params();
  EXPECT_NEAR(p.mass, truth.mass, 0.01 * truth.mass);
  EXPECT_NEAR(p.damping, truth.damping, 0.05 * truth.damping);
  EXPECT_NEAR(p.stiffness, truth.stiffness, 0.01 * truth.stiffness);
  EXPECT_NEAR(p.alpha, truth.alpha, 0.01 * truth.alpha);
  EXPECT_NEAR(p.beta * p.gamma, truth.beta * truth.gamma, 0.03 * truth.beta * truth.gamma);
  EXPECT_NEAR(p.beta * p.delta, truth.beta * truth.delta, 0.03 * truth.beta * -truth.delta);
  EXPECT_NEAR(fit.report.fit.rmse, 2e-6, 0.3e-6);  // down to the noise
}

TEST(FitBoucWenOscillator, DataDerivedStartsFromALinearFit) {
  const auto truth = BoucWenOscillator::benchmark();
  const auto u = force(1500);
  const auto y = simulate_bouc_wen_oscillator(BoucWenOscillator(truth), u, 1);
  const auto starts = bouc_wen_oscillator_starts(u, y, truth.sample_time);
  ASSERT_EQ(starts.size(), 4u);
  // m within a factor 2 and total stiffness k + alpha within 30 % of the truth.
  EXPECT_NEAR(starts[0].mass, truth.mass, truth.mass);
  EXPECT_NEAR(starts[0].stiffness + starts[0].alpha, truth.stiffness + truth.alpha,
              0.3 * (truth.stiffness + truth.alpha));
}

TEST(FitBoucWenOscillator, RejectsBadRecords) {
  const std::vector<double> u(100, 1.0), y(99, 0.0);
  EXPECT_HYST_ERROR(fit_bouc_wen_oscillator(u, y, {}), "input");
  BoucWenOscillatorRecord record{u, std::span(u).first(50), 2, 49};
  EXPECT_HYST_ERROR(fit_bouc_wen_oscillator(std::span(&record, 1), {}), "skip = 49");
}

}  // namespace
}  // namespace hyst
