#include "hyst/identify/fit_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The reference model of prandtl_ishlinskii.md with an offset; all weights > 0.
PrandtlIshlinskii reference_model() {
  return PrandtlIshlinskii({.thresholds = {0, 0.3, 0.7, 1.0, 1.6, 2.2},
                            .weights = {0.8, 0.5, 0.3, 0.2, 0.1, 0.05},
                            .offset = 0.3});
}

std::vector<double> simulate_from(const PrandtlIshlinskii& model, PrandtlIshlinskii::State state,
                                  const std::vector<double>& input) {
  return simulate(model, state, input);
}

// One period of a signal with two internal loops per period, range about 6.6 > 2 * 2.2, so that
// every play of reference_model() moves on both branches of the major loop.
std::vector<double> periodic_input(std::size_t samples) {
  std::vector<double> v(samples);
  for (std::size_t k = 0; k < samples; ++k) {
    const double phase = 2 * std::numbers::pi * static_cast<double>(k) / samples;
    v[k] = 3.0 * std::sin(phase) + 0.6 * std::sin(3 * phase + 0.4) + 0.5;
  }
  return v;
}

template <class Statement>
std::string field_of(Statement statement) {
  try {
    statement();
  } catch (const Error& error) {
    return error.field();
  }
  return "no error";
}

void expect_weights_near(const PrandtlIshlinskii& fitted, const PrandtlIshlinskii& truth,
                         double tolerance) {
  ASSERT_EQ(fitted.params().thresholds, truth.params().thresholds);
  for (std::size_t j = 0; j < truth.size(); ++j) {
    EXPECT_NEAR(fitted.params().weights[j], truth.params().weights[j], tolerance)
        << "p[" << j << "]";
  }
  EXPECT_NEAR(fitted.params().offset, truth.params().offset, tolerance) << "offset";
}

TEST(FitPrandtlIshlinskii, RecoversTheWeightsOfSimulatedData) {
  const auto truth = reference_model();
  const auto input = test::pi_check_signal();
  const auto output = simulate_from(truth, truth.initial_state(), input);

  const PiFit fit =
      fit_prandtl_ishlinskii(input, output, {.thresholds = truth.params().thresholds});
  expect_weights_near(fit.model, truth, 1e-9);
  EXPECT_EQ(fit.initial_state.play, std::vector<double>(6, 0.0)) << "virgin";
  EXPECT_TRUE(fit.model.is_invertible());

  const FitReport& report = fit.report;
  EXPECT_EQ(report.model, "pi");
  EXPECT_EQ(report.method, "nnls (Lawson-Hanson)");
  EXPECT_EQ(report.termination, Termination::converged) << report.message;
  EXPECT_GE(report.iterations, 6u);
  EXPECT_EQ(report.parameters, 7u);
  EXPECT_LT(report.fit.rmse, 1e-9);
  EXPECT_LT(report.final_cost, 1e-15);
  EXPECT_EQ(report.fit.samples, input.size());
  EXPECT_FALSE(report.validation);
  EXPECT_GE(report.seconds, 0.0);
  // The initial cost is that of the best constant, the mean of the output.
  double mean = 0;
  for (double y : output)
    mean += y / static_cast<double>(output.size());
  double initial_cost = 0;
  for (double y : output)
    initial_cost += 0.5 * (y - mean) * (y - mean);
  EXPECT_NEAR(report.initial_cost, initial_cost, 1e-9 * initial_cost);
}

TEST(FitPrandtlIshlinskii, RecoversRandomModelsWithRandomThresholds) {
  std::mt19937_64 seeds(77);
  for (int trial = 0; trial < 20; ++trial) {
    const std::uint64_t seed = seeds();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 draw(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::size_t n = 1 + draw() % 12;
    PrandtlIshlinskii::Params params{{0.0}, {0.2 + unit(draw)}, 4 * unit(draw) - 2};
    for (std::size_t j = 1; j < n; ++j) {
      params.thresholds.push_back(params.thresholds.back() + 0.05 + 0.15 * unit(draw));
      params.weights.push_back(0.05 + unit(draw));
    }
    const PrandtlIshlinskii truth(params);
    const auto input = test::random_walk(3000, draw(), 2.0, 0.2);
    const auto output = simulate_from(truth, truth.initial_state(), input);
    const PiFit fit = fit_prandtl_ishlinskii(input, output, {.thresholds = params.thresholds});
    EXPECT_EQ(fit.report.termination, Termination::converged) << fit.report.message;
    expect_weights_near(fit.model, truth, 1e-9);
  }
}

TEST(FitPrandtlIshlinskii, PeriodicStateIsTheSteadyState) {
  // A second period from the periodic state ends where it started (idempotence of the clamps).
  std::mt19937_64 seeds(5);
  for (int trial = 0; trial < 20; ++trial) {
    const std::uint64_t seed = seeds();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const auto model = reference_model();
    const auto input = test::random_walk(500, seed, 3.0, 0.3);
    auto state = pi_periodic_state(model, input);
    const auto start = state.play;
    simulate(model, state, input);
    EXPECT_EQ(state.play, start);
  }
}

TEST(FitPrandtlIshlinskii, RecoversWeightsFromOnePeriodInSteadyState) {
  const auto truth = reference_model();
  const auto input = periodic_input(800);
  const auto output = simulate_from(truth, pi_periodic_state(truth, input), input);
  const PiFit fit = fit_prandtl_ishlinskii(input, output,
                                           {.thresholds = truth.params().thresholds,
                                            .initial_state = PiFitOptions::InitialState::periodic});
  expect_weights_near(fit.model, truth, 1e-9);
  EXPECT_EQ(fit.initial_state.play, pi_periodic_state(truth, input).play);

  // Assuming the virgin state instead explains a first loading that never happened: worse.
  const PiFit wrong =
      fit_prandtl_ishlinskii(input, output, {.thresholds = truth.params().thresholds});
  EXPECT_GT(wrong.report.fit.rmse, 1e3 * fit.report.fit.rmse + 1e-6);
}

TEST(FitPrandtlIshlinskii, RecoversWeightsFromNoisyDataWithinTheirStandardError) {
  const auto truth = reference_model();
  const auto input = test::pi_check_signal();
  auto output = simulate_from(truth, truth.initial_state(), input);
  const double sigma = 0.01;  // output range is about 8: 0.1 % noise
  const std::uint64_t seed = 4242;
  SCOPED_TRACE(testing::Message() << "seed " << seed);
  std::mt19937_64 draw(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (double& y : output)
    y += noise(draw);

  const PiFit fit =
      fit_prandtl_ishlinskii(input, output, {.thresholds = truth.params().thresholds});
  EXPECT_EQ(fit.report.termination, Termination::converged);
  EXPECT_TRUE(fit.model.is_invertible());

  // Least-squares standard errors sigma * sqrt(diag((X^T X)^-1)), X = [plays, 1]. The true
  // weights are far from the bound 0, so the constraint is inactive and the NNLS estimate is the
  // LS estimate: each weight must lie within 5 standard errors (a 1 in 1.7 million event).
  const std::size_t n = truth.size();
  Eigen::MatrixXd X(static_cast<Eigen::Index>(input.size()), static_cast<Eigen::Index>(n + 1));
  std::vector<double> w(n, 0.0);
  for (std::size_t k = 0; k < input.size(); ++k) {
    for (std::size_t j = 0; j < n; ++j) {
      w[j] = play_step(input[k], truth.params().thresholds[j], w[j]);
      X(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = w[j];
    }
    X(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(n)) = 1.0;
  }
  const Eigen::MatrixXd covariance =
      (X.transpose() * X).ldlt().solve(Eigen::MatrixXd::Identity(X.cols(), X.cols()));
  for (std::size_t j = 0; j < n; ++j) {
    const double standard_error =
        sigma * std::sqrt(covariance(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j)));
    EXPECT_NEAR(fit.model.params().weights[j], truth.params().weights[j], 5 * standard_error)
        << "p[" << j << "], standard error " << standard_error;
  }
  const double offset_error = sigma * std::sqrt(covariance(X.cols() - 1, X.cols() - 1));
  EXPECT_NEAR(fit.model.params().offset, truth.params().offset, 5 * offset_error);
  // The residual is the noise, less the part the 7 parameters absorb.
  EXPECT_NEAR(fit.report.fit.rmse, sigma, 0.05 * sigma);
}

TEST(FitPrandtlIshlinskii, DefaultThresholdsSpanHalfTheInputRange) {
  // Input range [-1, 3]: spacing 4 / (2 * 5) = 0.4.
  const std::vector<double> input{0, 3, -1, 2, 0, 1.5, -0.5, 1, 0.2, 0.8, 0.4, 0.6};
  EXPECT_EQ(pi_default_thresholds(input, 5), uniform_thresholds(5, 0.4));
  std::vector<double> output(input.size());
  for (std::size_t k = 0; k < input.size(); ++k)
    output[k] = 2 * input[k] + (k % 3);
  const PiFit fit = fit_prandtl_ishlinskii(input, output, {.operators = 5});
  EXPECT_EQ(fit.model.params().thresholds, uniform_thresholds(5, 0.4));
  EXPECT_EQ(fit.report.parameters, 6u);
  const PiFit few = fit_prandtl_ishlinskii(input, output, {.operators = 1});
  EXPECT_EQ(few.model.params().thresholds, std::vector<double>{0.0});
}

TEST(FitPrandtlIshlinskii, FittedModelIsAlwaysInvertible) {
  // Data from models with negative weights (still invertible) and from a falling output that no
  // invertible PI model can follow: the fit keeps p_0 >= eps > 0 and p_j >= 0.
  const auto input = test::pi_check_signal();
  const PrandtlIshlinskii negative(
      {.thresholds = {0, 0.5, 1.0, 1.5}, .weights = {1.0, 0.8, -0.6, -0.5}});
  ASSERT_TRUE(negative.is_invertible());
  std::vector<double> falling(input.size());
  for (std::size_t k = 0; k < input.size(); ++k)
    falling[k] = -2 * input[k];
  for (const auto& output : {simulate_from(negative, negative.initial_state(), input), falling}) {
    const PiFit fit = fit_prandtl_ishlinskii(input, output, {.operators = 8});
    ASSERT_TRUE(fit.model.is_invertible());
    for (double p : fit.model.params().weights)
      EXPECT_GE(p, 0.0);
    const InversePrandtlIshlinskii inverse(fit.model);
    auto forward_state = fit.model.initial_state();
    auto inverse_state = inverse.initial_state();
    for (double v : input) {
      const double y = fit.model.step(forward_state, v);
      EXPECT_NEAR(inverse.step(inverse_state, y), v, 1e-6 * (1 + std::abs(v)));
    }
  }
  // For the falling output the best invertible model has every weight at its bound:
  // p_0 = min_linear_weight * output range / input range, the rest 0.
  const PiFit flat =
      fit_prandtl_ishlinskii(input, falling, {.operators = 8, .min_linear_weight = 1e-3});
  const auto [v_min, v_max] = std::minmax_element(input.begin(), input.end());
  const double eps = 1e-3 * (2 * (*v_max - *v_min)) / (*v_max - *v_min);
  EXPECT_NEAR(flat.model.params().weights[0], eps, 1e-15);
  for (std::size_t j = 1; j < 8; ++j)
    EXPECT_EQ(flat.model.params().weights[j], 0.0);
  EXPECT_NE(flat.report.message.find("8 of 8 weights at their lower bound"), std::string::npos)
      << flat.report.message;
}

TEST(FitPrandtlIshlinskii, WithoutOffsetTheOffsetIsZero) {
  PrandtlIshlinskii::Params params = reference_model().params();
  params.offset = 0.0;
  const PrandtlIshlinskii truth(params);
  const auto input = test::pi_check_signal();
  const auto output = simulate_from(truth, truth.initial_state(), input);
  const PiFit fit =
      fit_prandtl_ishlinskii(input, output, {.thresholds = params.thresholds, .fit_offset = false});
  expect_weights_near(fit.model, truth, 1e-9);
  EXPECT_EQ(fit.model.params().offset, 0.0);
  EXPECT_EQ(fit.report.parameters, 6u);
  double initial_cost = 0;
  for (double y : output)
    initial_cost += 0.5 * y * y;
  EXPECT_NEAR(fit.report.initial_cost, initial_cost, 1e-9 * initial_cost) << "all weights 0";
}

TEST(FitPrandtlIshlinskii, HeldOutFractionIsPredictedFromTheFitState) {
  const auto truth = reference_model();
  const auto input = test::pi_check_signal();
  auto output = simulate_from(truth, truth.initial_state(), input);

  const PiFit exact = fit_prandtl_ishlinskii(
      input, output, {.thresholds = truth.params().thresholds, .validate_fraction = 0.25});
  ASSERT_TRUE(exact.report.validation);
  EXPECT_EQ(exact.report.fit.samples, 3000u);
  EXPECT_EQ(exact.report.validation->samples, 1000u);
  EXPECT_LT(exact.report.validation->rmse, 1e-9);

  // A model with fewer operators than the truth: the validation metrics are those of simulating
  // the whole record from the initial state and scoring the last quarter.
  const PiFit coarse =
      fit_prandtl_ishlinskii(input, output, {.operators = 3, .validate_fraction = 0.25});
  const auto predicted = simulate_from(coarse.model, coarse.initial_state, input);
  const std::span<const double> all_measured(output), all_predicted(predicted);
  const ErrorMetrics fit = error_metrics(all_measured.first(3000), all_predicted.first(3000));
  const ErrorMetrics validation = error_metrics(all_measured.last(1000), all_predicted.last(1000));
  ASSERT_TRUE(coarse.report.validation);
  EXPECT_DOUBLE_EQ(coarse.report.fit.rmse, fit.rmse);
  EXPECT_DOUBLE_EQ(coarse.report.fit.nrmse_percent, fit.nrmse_percent);
  EXPECT_DOUBLE_EQ(coarse.report.validation->rmse, validation.rmse);
  EXPECT_DOUBLE_EQ(coarse.report.validation->max_error, validation.max_error);
  EXPECT_DOUBLE_EQ(coarse.report.final_cost, 0.5 * 3000 * fit.rmse * fit.rmse);
  EXPECT_GT(coarse.report.validation->rmse, 1e-3) << "3 operators cannot match 6";
}

TEST(FitPrandtlIshlinskii, SeparateValidationRecordStartsFromItsOwnState) {
  const auto truth = reference_model();
  const auto fit_input = periodic_input(800);
  std::vector<double> other_input = periodic_input(500);
  for (double& v : other_input)
    v *= 0.6;  // a smaller amplitude: nested loops
  const auto fit_output = simulate_from(truth, pi_periodic_state(truth, fit_input), fit_input);
  const auto other_output =
      simulate_from(truth, pi_periodic_state(truth, other_input), other_input);
  const PiFitOptions options{.operators = 4, .initial_state = PiFitOptions::InitialState::periodic};

  const PiFit fit =
      fit_prandtl_ishlinskii(fit_input, fit_output, other_input, other_output, options);
  ASSERT_TRUE(fit.report.validation);
  EXPECT_EQ(fit.report.validation->samples, 500u);
  const auto predicted =
      simulate_from(fit.model, pi_periodic_state(fit.model, other_input), other_input);
  const ErrorMetrics expected = error_metrics(other_output, predicted);
  EXPECT_DOUBLE_EQ(fit.report.validation->rmse, expected.rmse);
  EXPECT_DOUBLE_EQ(fit.report.validation->nrmse_percent, expected.nrmse_percent);
  // Fit metrics are the same as without the validation record.
  const PiFit alone = fit_prandtl_ishlinskii(fit_input, fit_output, options);
  EXPECT_EQ(alone.model.params().weights, fit.model.params().weights);
  EXPECT_DOUBLE_EQ(alone.report.fit.rmse, fit.report.fit.rmse);

  // With the true thresholds the prediction of the other amplitude is exact.
  const PiFit exact =
      fit_prandtl_ishlinskii(fit_input, fit_output, other_input, other_output,
                             {.thresholds = truth.params().thresholds,
                              .initial_state = PiFitOptions::InitialState::periodic});
  EXPECT_LT(exact.report.validation->rmse, 1e-9);
}

TEST(FitPrandtlIshlinskii, InitialStateNamesConvert) {
  using S = PiFitOptions::InitialState;
  for (const S state : {S::virgin, S::periodic})
    EXPECT_EQ(pi_initial_state_from_string(to_string(state)), state);
  EXPECT_EQ(to_string(S::periodic), "periodic");
  EXPECT_HYST_ERROR(pi_initial_state_from_string("steady"),
                    "unknown PI initial state 'steady' (expected virgin or periodic)");
}

TEST(FitPrandtlIshlinskii, RejectsInvalidData) {
  const auto input = test::pi_check_signal();
  const auto output = simulate_from(reference_model(), reference_model().initial_state(), input);
  const std::span<const double> v(input), y(output);
  std::vector<double> bad = input;
  bad[17] = kNan;

  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v, y.first(10)),
                    "PI fit input has 4000 values but PI fit output has 10");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v.first(0), y.first(0)), "PI fit input is empty");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(bad, y), "PI fit input[17] = nan is not finite");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v, bad), "PI fit output[17] = nan is not finite");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v.first(11), y.first(11)),
                    "PI fit: the fit part has 11 samples, fewer than operators + 2 = 12");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v.first(20), y.first(20), {.validate_fraction = 0.5}),
                    "PI fit: the fit part has 10 samples, fewer than operators + 2 = 12");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v.first(4), y.first(4), {.thresholds = {0, 0.5, 1}}),
                    "fewer than operators + 2 = 5");
  const std::vector<double> constant(50, 1.5);
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(constant, y.first(50)),
                    "PI fit: the input of the fit part is constant (all 50 samples = 1.5); the "
                    "play operators need a varying input");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v.first(50), constant),
                    "PI fit: the output of the fit part is constant (all 50 samples = 1.5)");
  // Constant over the fit part only.
  std::vector<double> step_input(50, 1.5);
  step_input.back() = 2.0;
  EXPECT_HYST_ERROR(
      fit_prandtl_ishlinskii(step_input, y.first(50), {.operators = 2, .validate_fraction = 0.1}),
      "the input of the fit part is constant (all 45 samples = 1.5)");

  // The separate validation record.
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v, y, v.first(3), y.first(2)),
                    "PI fit validation input has 3 values but PI fit validation output has 2");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v, y, v, bad),
                    "PI fit validation output[17] = nan is not finite");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v, y, v.first(0), y.first(0)),
                    "PI fit validation input is empty");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v, y, v.first(50), constant),
                    "PI fit: the validation output is constant (all 50 samples = 1.5)");
  EXPECT_HYST_ERROR(fit_prandtl_ishlinskii(v, y, v, y, {.validate_fraction = 0.2}),
                    "PI fit validate_fraction = 0.2 must be 0 when a separate validation record "
                    "is given");
  EXPECT_HYST_ERROR(pi_periodic_state(reference_model(), bad),
                    "PI periodic input[17] = nan is not finite");
  EXPECT_HYST_ERROR(pi_default_thresholds(constant, 3), "PI fit: the input is constant");
}

TEST(FitPrandtlIshlinskii, RejectsInvalidOptions) {
  const auto input = test::pi_check_signal();
  const auto output = simulate_from(reference_model(), reference_model().initial_state(), input);
  const auto fit = [&](const PiFitOptions& options) {
    fit_prandtl_ishlinskii(input, output, options);
  };
  EXPECT_HYST_ERROR(fit({.operators = 0}), "PI fit operators = 0 must be >= 1");
  EXPECT_HYST_ERROR(pi_default_thresholds(input, 0), "PI fit operators = 0 must be >= 1");
  EXPECT_HYST_ERROR(fit({.thresholds = {0.1, 0.5}}),
                    "PI fit threshold r[0] = 0.1 must be 0 (the r = 0 play carries the linear "
                    "term)");
  EXPECT_HYST_ERROR(fit({.thresholds = {0, 0.5, 0.5}}),
                    "PI fit threshold r[2] = 0.5 must be > "
                    "r[1] = 0.5");
  EXPECT_HYST_ERROR(fit({.thresholds = {0, kNan}}), "PI fit threshold r[1] = nan is not finite");
  EXPECT_HYST_ERROR(fit({.min_linear_weight = 0}),
                    "PI fit min_linear_weight = 0 must be finite and > 0");
  EXPECT_HYST_ERROR(fit({.min_linear_weight = kNan}), "PI fit min_linear_weight = nan");
  EXPECT_HYST_ERROR(fit({.validate_fraction = 1.0}),
                    "PI fit: validate_fraction = 1 must be in [0, 1)");

  // Each names its field.
  EXPECT_EQ(field_of([&] { fit({.operators = 0}); }), "operators");
  EXPECT_EQ(field_of([&] { fit({.thresholds = {0.1, 0.5}}); }), "thresholds[0]");
  EXPECT_EQ(field_of([&] { fit({.thresholds = {0, 0.5, 0.4}}); }), "thresholds[2]");
  EXPECT_EQ(field_of([&] { fit({.min_linear_weight = -1}); }), "min_linear_weight");
  EXPECT_EQ(field_of([&] { fit({.validate_fraction = -0.5}); }), "validate_fraction");
  EXPECT_EQ(field_of([&] { pi_initial_state_from_string("x"); }), "initial_state");
  EXPECT_EQ(field_of([&] { fit({}); }), "no error");
}

}  // namespace
}  // namespace hyst
