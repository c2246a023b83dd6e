// The forward sensitivities of a hysteretic LFR's simulation against a second algorithm: central
// differences of the simulation itself, for every parameter of both fitted structures (the
// feedback LFR of fit_hysteretic_lfr, the Hammerstein system of fit_hammerstein) at parameters
// where every entry they move matters (feedback and play weights non-zero, poles and B, C, D
// moved away from the linear fit).

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../../src/dynamics/detail/feedback_lfr_parametrisation.hpp"
#include "../../src/dynamics/detail/general_lfr_parametrisation.hpp"
#include "../../src/dynamics/detail/hammerstein_parametrisation.hpp"
#include "../../src/dynamics/detail/lfr_sensitivity.hpp"

namespace hyst::lfr_sensitivity_test {
namespace {

using detail::LfrParametrisation;
using Eigen::Index;
using Eigen::MatrixXd;

// Two inputs, two outputs, a pole pair and two real poles, in real modal form.
StateSpace linear_block() {
  const double r = 0.95, t = 0.3;
  MatrixXd a = MatrixXd::Zero(4, 4);
  a.topLeftCorner(2, 2) << r * std::cos(t), r * std::sin(t), -r * std::sin(t), r * std::cos(t);
  a(2, 2) = 0.8;
  a(3, 3) = -0.4;
  MatrixXd b(4, 2), c(2, 4), d(2, 2);
  b << 0.0, 1.0, 1.0, 0.3, 0.5, -0.2, 0.1, 0.4;
  c << 0.2, 0.1, 0.3, -0.1, -0.1, 0.25, 0.05, 0.2;
  d << 0.05, 0.0, 0.01, -0.02;
  return StateSpace({a, b, c, d, 1e-3});
}

// Two random-phase multisine inputs (two periods of 128 samples).
MatrixXd input() {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  MatrixXd u = MatrixXd::Zero(256, 2);
  for (Index c = 0; c < 2; ++c)
    for (int line = 1; line <= 20; ++line) {
      const double ph = phase(random);
      for (Index k = 0; k < u.rows(); ++k)
        u(k, c) += 0.4 * std::cos(2.0 * std::numbers::pi * line * double(k) / 128.0 + ph);
    }
  return u;
}

// Parameters away from the start: each moved by a random amount of the order of its own scale.
std::vector<double> moved(const LfrParametrisation& structure, double amount) {
  std::vector<double> theta = structure.initial();
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> uniform(-amount, amount);
  for (double& v : theta)
    v += uniform(random);
  return theta;
}

// Analytic against central differences: every entry within 1e-5 of its column's largest value
// (differences of a piecewise-smooth simulation are exact to the order of h^2 and of the few
// samples where a play turns between theta - h and theta + h).
void expect_sensitivities(const LfrParametrisation& structure, const std::vector<double>& theta) {
  const MatrixXd u = input();
  const Eigen::VectorXd start = Eigen::VectorXd::LinSpaced(4, -0.1, 0.2);
  const Index first = 128, p = 2, P = structure.size();
  const detail::SensitivitySink sink{first, (Eigen::RowVectorXd(2) << 1.0, 2.0).finished(),
                                     nullptr};
  std::vector<double> jacobian(std::size_t((u.rows() - first) * p * P));
  auto with_jacobian = sink;
  with_jacobian.jacobian = jacobian.data();
  const auto point = structure.at(theta.data());
  // A start with the plays away from rest (where a short run leaves them), the same for every
  // parameter vector: the fit starts each realisation in such a state, taken as given.
  auto warmed = point.model.make_state(start);
  point.model.simulate(input().topRows(40), warmed);
  const auto start_of = [&](const auto& model) { return model.make_state(start, warmed.feedback); };
  const MatrixXd y =
      detail::simulate_with_sensitivities(point, P, u, start_of(point.model), with_jacobian);

  auto state = start_of(point.model);
  const MatrixXd plain = point.model.simulate(u, state);
  EXPECT_EQ((y - plain).cwiseAbs().maxCoeff(), 0.0) << "the outputs are the model's own";

  const double h = 1e-6;
  for (Index j = 0; j < P; ++j) {
    auto up = theta, down = theta;
    up[std::size_t(j)] += h;
    down[std::size_t(j)] -= h;
    auto state_up = start_of(structure.at(up.data()).model);
    auto state_down = start_of(structure.at(down.data()).model);
    const MatrixXd difference = (structure.at(up.data()).model.simulate(u, state_up) -
                                 structure.at(down.data()).model.simulate(u, state_down)) /
                                (2.0 * h);
    double scale = 0.0, worst = 0.0;
    for (Index k = first; k < u.rows(); ++k)
      for (Index c = 0; c < p; ++c) {
        const double numeric = difference(k, c) * sink.weight[c];
        const double analytic = jacobian[std::size_t(((k - first) * p + c) * P + j)];
        scale = std::max(scale, std::abs(numeric));
        worst = std::max(worst, std::abs(analytic - numeric));
      }
    EXPECT_GT(scale, 0.0) << "parameter " << j << " moves the output";
    EXPECT_LE(worst, 1e-5 * scale) << "parameter " << j;
  }
}

// The largest difference between the analytic derivatives of one period simulated from the
// model's periodic state and central differences of that periodic simulation (each perturbed
// model from its own periodic state), relative to the column's largest value, over the parameters.
double periodic_sensitivity_error(const LfrParametrisation& structure,
                                  const std::vector<double>& theta, bool periodic_start) {
  const MatrixXd u = input().topRows(128);
  const LfrPeriodicOptions tight{2000, 1e-13};
  const Index p = 2, P = structure.size();
  const Eigen::RowVectorXd weight = (Eigen::RowVectorXd(2) << 1.0, 2.0).finished();
  std::vector<double> jacobian(std::size_t(u.rows() * p * P));
  const auto point = structure.at(theta.data());
  const MatrixXd y =
      detail::simulate_with_sensitivities(point, P, u, point.model.periodic_state(u, tight),
                                          {0, weight, jacobian.data(), periodic_start});
  EXPECT_LT((y - point.model.simulate_periodic(u, tight)).cwiseAbs().maxCoeff(),
            1e-12 * y.cwiseAbs().maxCoeff())
      << "the outputs are the model's periodic ones";

  const double h = 1e-6;
  double worst_relative = 0.0;
  for (Index j = 0; j < P; ++j) {
    auto up = theta, down = theta;
    up[std::size_t(j)] += h;
    down[std::size_t(j)] -= h;
    const MatrixXd difference = (structure.at(up.data()).model.simulate_periodic(u, tight) -
                                 structure.at(down.data()).model.simulate_periodic(u, tight)) /
                                (2.0 * h);
    double scale = 0.0, worst = 0.0;
    for (Index k = 0; k < u.rows(); ++k)
      for (Index c = 0; c < p; ++c) {
        const double numeric = difference(k, c) * weight[c];
        const double analytic = jacobian[std::size_t((k * p + c) * P + j)];
        scale = std::max(scale, std::abs(numeric));
        worst = std::max(worst, std::abs(analytic - numeric));
      }
    EXPECT_GT(scale, 0.0) << "parameter " << j << " moves the output";
    worst_relative = std::max(worst_relative, worst / scale);
  }
  return worst_relative;
}

// The periodic derivatives against central differences of the periodic simulation, and the
// derivatives of the same run with the start taken as given, which miss how the start moves.
void expect_periodic_sensitivities(const LfrParametrisation& structure,
                                   const std::vector<double>& theta) {
  EXPECT_LE(periodic_sensitivity_error(structure, theta, true), 1e-5);
  EXPECT_GT(periodic_sensitivity_error(structure, theta, false), 1e-2);
}

detail::SignalScales scales() {
  return {(Eigen::VectorXd(2) << 2.0, 1.5).finished(), (Eigen::VectorXd(2) << 0.5, 0.8).finished()};
}

TEST(LfrSensitivity, FeedbackLfrMatchesCentralDifferences) {
  HystereticLfrFitOptions options;
  options.threshold_fractions = {0.0, 0.1, 0.3};
  const detail::FeedbackLfrParametrisation structure(linear_block(), scales(), options, "test");
  // Theta (4), T (4), 2 x 2 weights, 4 pole parameters, B (8), C (8), D (4).
  EXPECT_EQ(structure.size(), 4 + 4 + 4 + 4 + 8 + 8 + 4);
  expect_sensitivities(structure, moved(structure, 0.2));
}

TEST(LfrSensitivity, PeriodicFeedbackLfrMatchesCentralDifferences) {
  HystereticLfrFitOptions options;
  options.threshold_fractions = {0.0, 0.1, 0.3};
  const detail::FeedbackLfrParametrisation structure(linear_block(), scales(), options, "test");
  expect_periodic_sensitivities(structure, moved(structure, 0.05));  // 0.2: no periodic state
}

TEST(LfrSensitivity, GeneralLfrMatchesCentralDifferences) {
  HystereticLfrFitOptions options;
  options.threshold_fractions = {0.0, 0.1, 0.3};
  const detail::FeedbackLfrParametrisation structure(linear_block(), scales(), options, "test");
  const auto theta = moved(structure, 0.05);  // poles stay inside max_pole_radius
  const detail::GeneralLfrParametrisation general(structure.at(theta.data()).model, true, 0.99999,
                                                  "test");
  // 2 x 2 weights, 4 pole parameters, B 4 x 4, C 4 x 4, D 4 x 4 but its zero 2 x 2 Dzw corner.
  EXPECT_EQ(general.size(), 4 + 4 + 16 + 16 + 12);
  const auto start = general.initial();
  const auto same = general.at(start.data()).model.simulate(input());
  const auto expected = structure.at(theta.data()).model.simulate(input());
  EXPECT_LT((same - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff())
      << "it starts where the structured model is";
  expect_sensitivities(general, moved(general, 0.05));
  expect_periodic_sensitivities(general, moved(general, 0.05));
}

TEST(LfrSensitivity, HammersteinMatchesCentralDifferences) {
  HammersteinFitOptions options;
  options.threshold_fractions = {0.0, 0.2, 0.5};
  const detail::HammersteinParametrisation structure(linear_block(), scales(), options, "test");
  EXPECT_EQ(structure.size(), 4 + 4 + 8 + 8 + 4);  // weights, poles, B, C, D
  expect_sensitivities(structure, moved(structure, 0.2));
  expect_periodic_sensitivities(structure, moved(structure, 0.2));
}

TEST(LfrSensitivity, TheStartIsTheLinearModel) {
  const MatrixXd u = input();
  const StateSpace linear = linear_block();
  const MatrixXd expected = linear.simulate(u);
  const detail::FeedbackLfrParametrisation lfr(linear, scales(), {}, "test");
  const detail::HammersteinParametrisation hammerstein(linear, scales(), {}, "test");
  for (const LfrParametrisation* structure :
       std::initializer_list<const LfrParametrisation*>{&lfr, &hammerstein}) {
    const auto theta = structure->initial();
    const MatrixXd y = structure->at(theta.data()).model.simulate(u);
    EXPECT_LT((y - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  }
}

}  // namespace
}  // namespace hyst::lfr_sensitivity_test
