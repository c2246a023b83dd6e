// The Hammerstein fit on data of a system of its own structure: two inputs, each through a PI
// model whose gain falls with the amplitude, drive two lightly coupled modes, measured at two
// amplitudes. One linear model cannot serve both levels (6 % and 50 % error); the fit, started
// from the linear block that drives the true system, finds the system.

#include "hyst/dynamics/fit_hammerstein.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/dynamics/simulation_score.hpp"

namespace hyst::fit_hammerstein_test {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;

constexpr Index kSamples = 256;
constexpr double kTs = 1e-3;

// Modes at 60 and 110 Hz, two inputs, two outputs, in real modal form.
StateSpace linear_block() {
  MatrixXd a = MatrixXd::Zero(4, 4);
  const auto pair = [&a](Index at, double r, double hz) {
    const double t = 2.0 * std::numbers::pi * hz * kTs;
    a.block(at, at, 2, 2) << r * std::cos(t), r * std::sin(t), -r * std::sin(t), r * std::cos(t);
  };
  pair(0, 0.96, 60.0);
  pair(2, 0.94, 110.0);
  MatrixXd b(4, 2), c(2, 4), d = MatrixXd::Zero(2, 2);
  b << 0.0, 0.2, 1.0, 0.1, 0.3, 0.0, 0.1, 1.0;
  c << 0.2, 0.1, 0.05, 0.0, 0.0, 0.05, 0.1, 0.25;
  return StateSpace({a, b, c, d, kTs});
}

// Random-phase multisines (lines 1..40) on both inputs at an RMS: 3 realisations of one period.
std::vector<MatrixXd> multisines(double rms, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  std::vector<MatrixXd> periods;
  for (int r = 0; r < 3; ++r) {
    MatrixXd period = MatrixXd::Zero(kSamples, 2);
    for (Index c = 0; c < 2; ++c) {
      for (int line = 1; line <= 40; ++line) {
        const double ph = phase(random);
        for (Index k = 0; k < kSamples; ++k)
          period(k, c) += std::cos(2.0 * std::numbers::pi * line * double(k) / kSamples + ph);
      }
      period.col(c) *= rms / std::sqrt(period.col(c).squaredNorm() / kSamples);
    }
    periods.push_back(period);
  }
  return periods;
}

const std::vector<std::vector<MatrixXd>>& levels() {
  static const std::vector<std::vector<MatrixXd>> inputs = {multisines(0.3, 1), multisines(1.5, 2)};
  return inputs;
}

// The thresholds the fit places, as fractions of each input's largest magnitude over the data.
const std::vector<double> kFractions = {0.0, 0.1, 0.2, 0.3, 0.5};

// The inputs' PI models, softening by different amounts, with thresholds on the fit's grid (10
// and 30 % of input 1's largest magnitude, 20 % of input 2's): the fit can find the system.
HystereticLfr<PrandtlIshlinskii> true_system() {
  Eigen::RowVectorXd largest = Eigen::RowVectorXd::Zero(2);
  for (const auto& level : levels())
    for (const auto& period : level)
      largest = largest.cwiseMax(period.cwiseAbs().colwise().maxCoeff());
  return HystereticLfr<PrandtlIshlinskii>::hammerstein(
      linear_block(),
      {PrandtlIshlinskii({{0.0, 0.1 * largest[0], 0.3 * largest[0]}, {1.0, -0.3, -0.2}, 0.0}),
       PrandtlIshlinskii({{0.0, 0.2 * largest[1]}, {1.0, -0.4}, 0.0})});
}

// Level `level` measured on the true system in periodic steady state, 2 periods per realisation.
PeriodicExperiment experiment(std::size_t level) {
  const auto system = true_system();
  const auto& periods = levels()[level];
  PeriodicExperiment x{{std::size_t(kSamples), 2, periods.size(), 2, {}},
                       {std::size_t(kSamples), 2, periods.size(), 2, {}}};
  x.input.values.resize(std::size_t(kSamples) * 2 * periods.size() * 2);
  x.output.values.resize(x.input.values.size());
  for (std::size_t r = 0; r < periods.size(); ++r) {
    auto state = system.periodic_state(periods[r]);
    for (std::size_t p = 0; p < 2; ++p) {
      const MatrixXd y = system.simulate(periods[r], state);
      for (Index k = 0; k < kSamples; ++k)
        for (Index c = 0; c < 2; ++c) {
          x.input(std::size_t(k), std::size_t(c), r, p) = periods[r](k, c);
          x.output(std::size_t(k), std::size_t(c), r, p) = y(k, c);
        }
    }
  }
  return x;
}

SimulationScore score(const HystereticLfr<PrandtlIshlinskii>& model, const PeriodicExperiment& x) {
  return score_simulation(
      x.input, x.output,
      [&](const MatrixXd& u, const MatrixXd& one_period) {
        auto state = model.periodic_state(one_period);
        return model.simulate(u, state);
      },
      0);
}

TEST(FitHammerstein, ServesBothAmplitudesWhereTheLinearModelCannot) {
  const std::vector<PeriodicExperiment> data = {experiment(0), experiment(1)};
  HammersteinFitOptions options;
  options.threshold_fractions = kFractions;
  const auto fit = fit_hammerstein(linear_block(), data, options);
  // 2 x 4 weights, 4 pole parameters, B (8), C (8), D (4).
  EXPECT_EQ(fit.report.parameters, 8u + 4u + 8u + 8u + 4u);
  EXPECT_EQ(fit.report.model, "hammerstein");
  EXPECT_LT(fit.report.final_cost, 1e-8 * fit.report.initial_cost);
  for (const auto& x : data) {
    const auto linear = score_state_space(linear_block(), x.input, x.output, {.periodic = true});
    EXPECT_GT(linear.mean_relative_error, 0.05);  // the input hysteresis matters at this level
    EXPECT_LT(score(fit.model, x).mean_relative_error, 1e-4);
  }
  // The model is a Hammerstein system: the hysteresis sees the inputs alone.
  const auto& m = fit.model.matrices();
  EXPECT_EQ(m.c_z.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(m.d_zu, MatrixXd::Identity(2, 2));
  EXPECT_EQ(m.b_u.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(m.d_yu.cwiseAbs().maxCoeff(), 0.0);
}

TEST(FitHammerstein, WithTheLinearBlockFixedOnlyTheWeightsMove) {
  const std::vector<PeriodicExperiment> data = {experiment(0), experiment(1)};
  HammersteinFitOptions options;
  options.threshold_fractions = kFractions;
  options.fit_poles = options.fit_io_matrices = false;
  options.max_iterations = 10;
  const auto fit = fit_hammerstein(linear_block(), data, options);
  EXPECT_EQ(fit.report.parameters, 8u);
  EXPECT_EQ(fit.model.matrices().a, linear_block().params().a);
  EXPECT_EQ(fit.model.matrices().b_w, linear_block().params().b);
  // The linear block is the true one: the weights alone find the system.
  EXPECT_LT(fit.report.final_cost, 1e-8 * fit.report.initial_cost);
}

TEST(FitHammerstein, NamesWhatIsWrong) {
  const std::vector<PeriodicExperiment> data = {experiment(0)};
  HammersteinFitOptions options;
  options.threshold_fractions = {0.1, 0.2};
  EXPECT_HYST_ERROR(fit_hammerstein(linear_block(), data, options),
                    "Hammerstein fit: threshold_fractions must start at 0");
  EXPECT_HYST_ERROR(fit_hammerstein(linear_block(), {}, {}), "Hammerstein fit: no experiment");
  auto silent = data;
  std::fill(silent[0].input.values.begin(), silent[0].input.values.end(), 0.0);
  EXPECT_HYST_ERROR(fit_hammerstein(linear_block(), silent, {}), "zero throughout");
  options = {};
  options.max_pole_radius = 0.95;  // below the 60 Hz mode's 0.96
  EXPECT_HYST_ERROR(fit_hammerstein(linear_block(), data, options),
                    "Hammerstein fit: a pole of the linear model has magnitude 0.96");
}

}  // namespace
}  // namespace hyst::fit_hammerstein_test
