// The benchmark score by hand: a known output error gives its RMSE and relative error; a model
// of the system that made the data scores zero in periodic steady state, not from rest.

#include "hyst/dynamics/simulation_score.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "periodic_experiments.hpp"

namespace hyst {
namespace {

constexpr std::size_t kScoreSamples = 128;

StateSpace two_lags_model() {
  StateSpace::Params p;
  p.a = (Eigen::MatrixXd(2, 2) << test::kPole1, 0.0, 0.0, test::kPole2).finished();
  p.b = (Eigen::MatrixXd(2, 2) << 1.0, 0.0, 1.0, 1.0).finished();
  p.c = Eigen::MatrixXd::Identity(2, 2);
  p.d = (Eigen::MatrixXd(2, 2) << 0.0, 0.5, 0.0, 0.0).finished();
  return StateSpace(p);
}

TEST(SimulationScore, KnownErrorsGiveTheirRmseAndRelativeError) {
  const auto e = test::periodic_experiment(test::two_lags, 2, 2, 2, kScoreSamples, 20, 2, 2, 3);
  // Channel 1 off by 0.1 everywhere, channel 2 off by +-0.2 alternating in time.
  std::size_t realisation = 0;  // score_simulation() runs the realisations in order
  const auto simulate = [&](const Eigen::MatrixXd& u, const Eigen::MatrixXd&) {
    Eigen::MatrixXd y(u.rows(), 2);
    const Eigen::MatrixXd measured = realisation_record(e.output, realisation++);
    for (Eigen::Index n = 0; n < u.rows(); ++n) {
      y(n, 0) = measured(n, 0) + 0.1;
      y(n, 1) = measured(n, 1) + (n % 2 == 0 ? 0.2 : -0.2);
    }
    return y;
  };
  const auto score = score_simulation(e.input, e.output, simulate, 0);
  ASSERT_EQ(score.channels.size(), 2u);
  EXPECT_NEAR(score.channels[0].rmse, 0.1, 1e-14);
  EXPECT_NEAR(score.channels[1].rmse, 0.2, 1e-14);
  EXPECT_NEAR(score.mean_rmse, 0.15, 1e-14);
  // std by hand from the samples
  double sum = 0.0, squares = 0.0;
  for (std::size_t r = 0; r < 2; ++r)
    for (std::size_t q = 0; q < 2; ++q)
      for (std::size_t n = 0; n < kScoreSamples; ++n) {
        sum += e.output(n, 1, r, q);
        squares += e.output(n, 1, r, q) * e.output(n, 1, r, q);
      }
  const double count = 4.0 * kScoreSamples;
  const double std1 = std::sqrt(squares / count - (sum / count) * (sum / count));
  EXPECT_NEAR(score.channels[1].relative_error, 0.2 / std1, 1e-12);
  EXPECT_EQ(score.scored_samples, 4 * kScoreSamples);
}

TEST(SimulationScore, TheTrueModelScoresZeroInPeriodicSteadyStateOnly) {
  const auto e = test::periodic_experiment(test::two_lags, 2, 2, 2, kScoreSamples, 20, 2, 2, 3);
  const auto model = two_lags_model();
  const auto periodic = score_state_space(model, e.input, e.output, {.periodic = true});
  EXPECT_LT(periodic.mean_relative_error, 1e-12);
  const auto from_rest = score_state_space(model, e.input, e.output);
  EXPECT_GT(from_rest.mean_relative_error, 1e-3);  // the transient of the pole at 0.9
  // 0.9^100 = 2.7e-5 of the initial offset is left after a transient of 100 samples
  const auto settled = score_state_space(model, e.input, e.output, {.transient_samples = 100});
  EXPECT_LT(settled.mean_relative_error, from_rest.mean_relative_error / 10.0);
}

TEST(SimulationScore, RejectsMismatchedData) {
  const auto e = test::periodic_experiment(test::two_lags, 2, 2, 2, kScoreSamples, 20, 2, 1, 3);
  const auto model = two_lags_model();
  EXPECT_HYST_ERROR(
      score_state_space(model, e.input, e.output, {.transient_samples = kScoreSamples}),
      "leaves nothing of the first period");
  auto constant = e;
  for (std::size_t r = 0; r < 2; ++r)
    for (std::size_t n = 0; n < kScoreSamples; ++n)
      constant.output(n, 1, r, 0) = 3.0;
  EXPECT_HYST_ERROR(score_state_space(model, constant.input, constant.output),
                    "output channel 2 is constant");
  auto one_input = e.input;
  one_input.channels = 1;
  EXPECT_HYST_ERROR(score_state_space(model, one_input, e.output), "the model has 2 inputs");
}

TEST(SimulationScore, NamesANonFiniteSampleInsteadOfCallingItsChannelConstant) {
  const auto e = test::periodic_experiment(test::two_lags, 2, 2, 2, kScoreSamples, 20, 2, 1, 3);
  const auto model = two_lags_model();
  auto infinite = e;
  infinite.output(7, 0, 1, 0) = std::numeric_limits<double>::infinity();
  EXPECT_HYST_ERROR(score_state_space(model, infinite.input, infinite.output),
                    "score: output: the value at (N = 7, channel = 0, realisation = 1, period = 0) "
                    "is inf; every sample must be finite");
  auto not_a_number = e;
  not_a_number.input(3, 1, 0, 0) = std::nan("");
  EXPECT_HYST_ERROR(score_state_space(model, not_a_number.input, not_a_number.output),
                    "score: input: the value at (N = 3, channel = 1, realisation = 0, period = 0) "
                    "is nan");
}

}  // namespace
}  // namespace hyst
