// The initial state from measured samples: a linear model's by least squares (exact on
// noise-free data, to the noise level with noise), a hysteretic LFR's by Gauss-Newton, and the
// benchmark score under the rule that lets a model see the first n outputs.

#include "hyst/dynamics/initial_state_estimate.hpp"

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/expect_error.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/registry/hysteretic_lfr_file.hpp"
#include "hyst/registry/model_registry.hpp"
#include "random_matrix.hpp"

namespace hyst {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

using test::random_matrix;

// Four states with the poles 0.9, 0.7, -0.5, 0.3 (upper triangular A), m inputs, p outputs.
StateSpace stable_model(Eigen::Index m, Eigen::Index p, std::mt19937_64& random) {
  StateSpace::Params params;
  params.a = random_matrix(4, 4, random, 0.2).triangularView<Eigen::StrictlyUpper>();
  params.a.diagonal() << 0.9, 0.7, -0.5, 0.3;
  params.b = random_matrix(4, m, random, 1.0);
  params.c = random_matrix(p, 4, random, 1.0);
  params.d = random_matrix(p, m, random, 0.1);
  params.sample_time = 1e-3;
  return StateSpace(params);
}

TEST(InitialStateEstimate, ALinearModelsStateFromItsFirstSamples) {
  std::mt19937_64 random(3);
  const auto model = stable_model(2, 2, random);
  const VectorXd truth = random_matrix(4, 1, random, 3.0);
  const MatrixXd u = random_matrix(200, 2, random, 1.0);
  auto state = model.make_state(truth);
  const MatrixXd y = model.simulate(u, state);

  const auto exact = estimate_initial_state(model, u, y, 20);
  EXPECT_EQ(exact.samples, 20u);
  EXPECT_LT((exact.state - truth).norm(), 1e-9 * truth.norm());
  EXPECT_LT(exact.rms_residual, 1e-9);

  // Noise of 1e-3 on the outputs: the state to about the noise over sqrt(samples) times the
  // observability's gain, the residual at the noise level.
  const MatrixXd noisy = y + random_matrix(200, 2, random, 1e-3);
  const auto estimate = estimate_initial_state(model, u, noisy, 100);
  EXPECT_LT((estimate.state - truth).norm(), 0.02);
  EXPECT_NEAR(estimate.rms_residual, 1e-3, 3e-4);

  EXPECT_HYST_ERROR(estimate_initial_state(model, u, y, 0), "0 samples of a record of 200");
  EXPECT_HYST_ERROR(estimate_initial_state(model, u, y, 201), "201 samples");
  EXPECT_HYST_ERROR(estimate_initial_state(model, u.leftCols(1), y, 10), "2 inputs");
}

// A hysteretic LFR (two PI channels in feedback): its state from 60 samples by Gauss-Newton.
TEST(InitialStateEstimate, AHystereticLfrsStateByGaussNewton) {
  std::mt19937_64 random(5);
  auto linear = stable_model(3, 3, random).params();  // inputs (u, w), outputs (y, z): m = p = 1
  linear.b.rightCols(2) *= 0.3;
  linear.d.bottomRightCorner(2, 2).setZero();
  const auto& pi = ModelRegistry::builtin().find("pi");
  const auto channel = pi.create(
      nlohmann::json{{"thresholds", {0.0, 0.3, 0.8}}, {"weights", {0.5, 0.3, 0.2}}}, nullptr);
  const AnyHystereticLfr model(StateSpace(linear), 1, {channel.get(), channel.get()});
  const VectorXd truth = random_matrix(4, 1, random, 2.0);
  const MatrixXd u = random_matrix(300, 1, random, 1.0);
  const MatrixXd y = model.simulate_from_state(u, truth);

  const auto estimate = model.estimate_initial_state(u, y, 60);
  EXPECT_LT((estimate.state - truth).norm(), 1e-5 * truth.norm()) << estimate.state.transpose();
  EXPECT_LT(estimate.rms_residual, 1e-6);
  EXPECT_GE(estimate.iterations, 1u);
  EXPECT_LE(estimate.iterations, 20u);
  // The hysteresis path matters: the linear block's u -> y part alone misses the state.
  const StateSpace u_to_y({linear.a, linear.b.leftCols(1), linear.c.topRows(1),
                           linear.d.topLeftCorner(1, 1), linear.sample_time});
  const auto linear_only = estimate_initial_state(u_to_y, u, y, 60);
  EXPECT_GT((linear_only.state - truth).norm(), 1e-3 * truth.norm());
}

// The score under the rule: simulated from a state far from rest, the record scores (almost)
// exactly when the model sees its first 30 outputs, and not from rest with the same 30 left out.
TEST(InitialStateEstimate, TheScoreWithInitSamplesStartsFromTheEstimatedState) {
  std::mt19937_64 random(9);
  const auto model = stable_model(1, 1, random);
  PeriodicSignals input;
  input.samples = 100;
  input.channels = 1;
  input.realisations = 2;
  input.periods = 1;
  PeriodicSignals output = input;
  for (std::size_t r = 0; r < 2; ++r) {
    const MatrixXd u = random_matrix(100, 1, random, 1.0);
    auto state = model.make_state(random_matrix(4, 1, random, 20.0));
    const MatrixXd y = model.simulate(u, state);
    for (Eigen::Index n = 0; n < 100; ++n) {
      input.values.push_back(u(n, 0));
      output.values.push_back(y(n, 0));
    }
  }
  ScoreOptions seeing;
  seeing.init_samples = 30;
  ScoreOptions from_rest;
  from_rest.transient_samples = 30;
  const auto seen = score_state_space(model, input, output, seeing);
  const auto rest = score_state_space(model, input, output, from_rest);
  EXPECT_EQ(seen.scored_samples, 2u * 70u);
  EXPECT_LT(seen.mean_relative_error, 1e-8);
  EXPECT_GT(rest.mean_relative_error, 1e-3);
  seeing.periodic = true;
  EXPECT_HYST_ERROR(score_state_space(model, input, output, seeing), "two ways to start");
}

}  // namespace
}  // namespace hyst
