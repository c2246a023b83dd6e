// The hysteretic LFR fit on data of a system of its own structure: a lightly damped mode whose
// stiffness a PI model in its feedback changes with the amplitude, measured at two amplitudes.
// The linear model cannot serve both; the fit, started from the true linear block, must.

#include "hyst/dynamics/fit_hysteretic_lfr.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/dynamics/fit_state_space.hpp"
#include "hyst/dynamics/simulation_score.hpp"

namespace hyst::fit_hysteretic_lfr_test {
namespace {

using Eigen::MatrixXd;

constexpr std::size_t kSamples = 256;
constexpr double kTs = 1e-3;

// A mode at 60 Hz (pole radius 0.97), one input, one output.
StateSpace linear_block() {
  const double r = 0.97, t = 2.0 * std::numbers::pi * 60.0 * kTs;
  MatrixXd a(2, 2);
  a << r * std::cos(t), r * std::sin(t), -r * std::sin(t), r * std::cos(t);
  return StateSpace({a, (MatrixXd(2, 1) << 0.0, 1.0).finished(),
                     (MatrixXd(1, 2) << 0.2, 0.1).finished(), MatrixXd::Zero(1, 1), kTs});
}

// The true system: w = PI[y] fed back to the input (u_eff = u - 0.5 w), with plays that make the
// feedback stronger at large amplitudes.
HystereticLfr<PrandtlIshlinskii> true_system() {
  const StateSpace linear = linear_block();
  const auto& lin = linear.params();
  const PrandtlIshlinskii pi({{0.0, 0.3, 0.8}, {0.2, 0.4, 0.3}, 0.0});
  const double gain = -0.5;
  MatrixXd b(2, 2), c(2, 2), d = MatrixXd::Zero(2, 2);
  b << lin.b, gain * lin.b;
  c << lin.c, lin.c;
  return {StateSpace({lin.a, b, c, d, kTs}), 1, {pi}};
}

// Random-phase multisines (lines 1..40 of the period) at an RMS, 3 realisations of 2 periods.
PeriodicExperiment experiment(double rms, std::uint64_t seed) {
  const auto system = true_system();
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  PeriodicExperiment x{{kSamples, 1, 3, 2, {}}, {kSamples, 1, 3, 2, {}}};
  for (std::size_t r = 0; r < 3; ++r) {
    MatrixXd period(kSamples, 1);
    period.setZero();
    for (int line = 1; line <= 40; ++line) {
      const double ph = phase(random);
      for (std::size_t k = 0; k < kSamples; ++k)
        period(Eigen::Index(k), 0) +=
            std::cos(2.0 * std::numbers::pi * line * double(k) / kSamples + ph);
    }
    period *= rms / std::sqrt(period.squaredNorm() / kSamples);
    MatrixXd record(2 * kSamples, 1);
    record << period, period;
    auto state = system.periodic_state(period);
    const MatrixXd y = system.simulate(record, state);
    for (Eigen::Index k = 0; k < record.rows(); ++k) {
      x.input.values.push_back(record(k, 0));
      x.output.values.push_back(y(k, 0));
    }
  }
  return x;
}

// The thresholds of these tests; general_iterations = 0: the structured stage alone.
HystereticLfrFitOptions fit_options(std::size_t general_iterations = 0) {
  HystereticLfrFitOptions options;
  options.threshold_fractions = {0.0, 0.1, 0.25, 0.5};
  options.general_iterations = general_iterations;
  return options;
}

TEST(FitHystereticLfr, ServesBothAmplitudesWhereTheLinearModelCannot) {
  const std::vector<PeriodicExperiment> data = {experiment(0.5, 1), experiment(3.0, 2)};
  const auto fit = fit_hysteretic_lfr(linear_block(), data,
                                      fit_options(HystereticLfrFitOptions{}.general_iterations));
  // Then every matrix free: 3 weights, a pole pair, B 2 x 2, C 2 x 2, D 2 x 2 but Dzw.
  EXPECT_EQ(fit.report.parameters, 3u + 2u + 4u + 4u + 3u);
  EXPECT_NE(fit.report.method.find("then of the PI weights (4 plays per channel) and every matrix"),
            std::string::npos)
      << fit.report.method;
  EXPECT_LT(fit.report.final_cost, 1e-2 * fit.report.initial_cost);
  for (const auto& x : data) {
    const auto linear = score_state_space(linear_block(), x.input, x.output, {.periodic = true});
    const auto lfr = score_simulation(
        x.input, x.output,
        [&](const MatrixXd& u, const MatrixXd& one_period) {
          auto state = fit.model.periodic_state(one_period);
          return fit.model.simulate(u, state);
        },
        0);
    EXPECT_GT(linear.mean_relative_error, 0.1);  // the feedback matters at this amplitude
    EXPECT_LT(lfr.mean_relative_error, 0.1 * linear.mean_relative_error);
  }
  // What the fit minimised is the error in periodic steady state (the benchmark's convention):
  // its RMSE is that of the second periods, each simulated from the fitted model's periodic state
  // for its input.
  double squares = 0.0;
  std::size_t count = 0;
  for (const auto& x : data)
    for (std::size_t r = 0; r < x.input.realisations; ++r) {
      const MatrixXd u = realisation_record(x.input, r), y = realisation_record(x.output, r);
      const MatrixXd simulated = fit.model.simulate_periodic(u.bottomRows(kSamples));
      squares += (simulated - y.bottomRows(kSamples)).squaredNorm();
      count += kSamples;
    }
  EXPECT_NEAR(fit.report.fit.rmse, std::sqrt(squares / double(count)), 1e-12 * fit.report.fit.rmse);
}

TEST(FitHystereticLfr, TheStructuredStageAloneFitsTheFeedbackAndTheLinearBlock) {
  const std::vector<PeriodicExperiment> data = {experiment(0.5, 1), experiment(3.0, 2)};
  auto options = fit_options();
  const auto fit = fit_hysteretic_lfr(linear_block(), data, options);
  // Theta, T, 3 weights, a pole pair, B (2), C (2), D (1).
  EXPECT_EQ(fit.report.parameters, 1u + 1u + 3u + 2u + 2u + 2u + 1u);
  EXPECT_LT(fit.report.final_cost, 1e-2 * fit.report.initial_cost);
  // The feedback enters where the input does: Bw = Bu Theta, parallel columns.
  const auto& m = fit.model.matrices();
  EXPECT_GT(m.b_w.norm(), 0.0);
  EXPECT_LT(std::abs(m.b_u(0, 0) * m.b_w(1, 0) - m.b_u(1, 0) * m.b_w(0, 0)),
            1e-12 * m.b_u.norm() * m.b_w.norm());
}

TEST(FitHystereticLfr, MoreChannelsThanOutputs) {
  const std::vector<PeriodicExperiment> data = {experiment(0.5, 1), experiment(3.0, 2)};
  auto options = fit_options();
  options.feedback_channels = 2;
  const auto structured = fit_hysteretic_lfr(linear_block(), data, options);
  // Theta (1 x 2), T (2 x 1), 2 x 3 weights, a pole pair, B (2), C (2), D (1).
  EXPECT_EQ(structured.report.parameters, 2u + 2u + 6u + 2u + 2u + 2u + 1u);
  ASSERT_EQ(structured.model.feedback().size(), 2u);
  // Both channels are used, and they are no copies: the second starts at 1.5 times the output
  // (one output: each z is T times it), and so sees the thresholds at other amplitudes.
  const auto& m = structured.model.matrices();
  EXPECT_GT(std::abs(m.b_w(0, 0)), 0.0);
  EXPECT_GT(std::abs(m.b_w(0, 1)), 0.0);
  EXPECT_GT(std::abs(m.c_z(1, 0) - m.c_z(0, 0)), 1e-3 * std::abs(m.c_z(0, 0)));
  EXPECT_LT(structured.report.final_cost, 1e-2 * structured.report.initial_cost);

  options.general_iterations = 20;
  const auto general = fit_hysteretic_lfr(linear_block(), data, options);
  // 2 x 3 weights, a pole pair, B 2 x 3, C 3 x 2, D 3 x 3 but its 2 x 2 Dzw.
  EXPECT_EQ(general.report.parameters, 6u + 2u + 6u + 6u + 5u);
  EXPECT_LT(general.report.final_cost, 1e-2 * general.report.initial_cost);
}

// Started from a linear model fitted to the same single experiment (its frequency response, which
// for periodic data is its simulation error), the fit must still leave the start: that model
// minimises every linear change, so the start would be a stationary point if Theta's derivative
// had no hysteresis in it (feedback_lfr_parametrisation.cpp).
TEST(FitHystereticLfr, LeavesALinearModelFittedToTheSameExperiment) {
  const std::vector<PeriodicExperiment> data = {experiment(3.0, 2)};
  StateSpaceFitOptions linear_options;
  linear_options.order = 2;
  const auto linear = fit_state_space(estimate_bla(data, kTs), linear_options).model;
  auto options = fit_options();
  options.max_iterations = 10;
  const auto fit = fit_hysteretic_lfr(linear, data, options);
  EXPECT_GT(fit.report.iterations, 0u) << fit.report.message;
  EXPECT_LT(fit.report.final_cost, 0.1 * fit.report.initial_cost) << fit.report.message;
}

// The limit counts accepted steps, each with its Jacobian; rejected trial steps come on top.
TEST(FitHystereticLfr, IterationsCountAcceptedSteps) {
  const std::vector<PeriodicExperiment> data = {experiment(0.5, 1), experiment(3.0, 2)};
  auto options = fit_options();
  options.max_iterations = 3;
  const auto fit = fit_hysteretic_lfr(linear_block(), data, options);
  EXPECT_EQ(fit.report.iterations, 3u);
  EXPECT_EQ(fit.report.termination, Termination::max_iterations);
  EXPECT_NE(fit.report.message.find("Limit of 3 accepted steps reached"), std::string::npos)
      << fit.report.message;
  EXPECT_LT(fit.report.final_cost, fit.report.initial_cost);
}

// A pole that an earlier fit left on max_pole_radius comes back from the model an ulp or so above
// it; the next fit takes it as on the bound, and refuses a pole clearly above it.
TEST(FitHystereticLfr, APoleOnTheBoundIsNoPoleAboveIt) {
  const std::vector<PeriodicExperiment> data = {experiment(3.0, 2)};
  auto options = fit_options();
  options.max_iterations = 2;
  options.max_pole_radius = 0.97 / (1.0 + 1e-14);  // the mode's radius is 0.97
  const auto fit = fit_hysteretic_lfr(linear_block(), data, options);
  EXPECT_LT(fit.report.final_cost, fit.report.initial_cost);
  options.max_pole_radius = 0.97 / (1.0 + 1e-9);
  EXPECT_HYST_ERROR(fit_hysteretic_lfr(linear_block(), data, options),
                    "a pole of the linear model has magnitude 0.97");
}

TEST(FitHystereticLfr, NamesWhatIsWrong) {
  const std::vector<PeriodicExperiment> data = {experiment(0.5, 1)};
  HystereticLfrFitOptions options;
  options.threshold_fractions = {0.1, 0.2};
  EXPECT_HYST_ERROR(fit_hysteretic_lfr(linear_block(), data, options), "must start at 0");
  options.threshold_fractions = {0.0, 0.2, 0.2};
  EXPECT_HYST_ERROR(fit_hysteretic_lfr(linear_block(), data, options),
                    "threshold_fractions[2] = 0.2 must be finite and above the one before");
  EXPECT_HYST_ERROR(fit_hysteretic_lfr(linear_block(), {}, {}), "no experiment");
  HystereticLfrFitOptions too_many;
  too_many.feedback_channels = kMaxFeedbackChannels + 1;
  EXPECT_HYST_ERROR(fit_hysteretic_lfr(linear_block(), data, too_many),
                    "feedback_channels = 65 is above the limit of 64");
  auto one_period = data;
  one_period[0].input.periods = one_period[0].output.periods = 1;
  one_period[0].input.realisations = one_period[0].output.realisations = 6;
  EXPECT_HYST_ERROR(fit_hysteretic_lfr(linear_block(), one_period, {}), "1 period per realisation");
}

}  // namespace
}  // namespace hyst::fit_hysteretic_lfr_test
