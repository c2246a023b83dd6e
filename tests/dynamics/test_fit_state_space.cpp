// The state-space fit against systems known in closed form: responses given by their poles and
// residues (not through hyst::StateSpace) are recovered with their poles; the result is stable.

#include "hyst/dynamics/fit_state_space.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"

namespace hyst {
namespace {

using Complex = std::complex<double>;

// G(z) = D + sum_i R_i / (z - l_i) + conj(R_i) / (z - conj(l_i)), p = 2, m = 2, with residues of
// rank 1 (R_i = c_i b_i^T): two states per complex pole pair, so order 4 for two pairs.
struct Resonances {
  std::vector<Complex> poles;
  std::vector<Eigen::MatrixXcd> residues;
  Eigen::MatrixXd d;

  Eigen::MatrixXcd at(Complex z) const {
    Eigen::MatrixXcd g = d.cast<Complex>();
    for (std::size_t i = 0; i < poles.size(); ++i)
      g += residues[i] / (z - poles[i]) + residues[i].conjugate() / (z - std::conj(poles[i]));
    return g;
  }
};

Resonances two_resonances(double radius_1 = 0.98) {
  Resonances system;
  system.poles = {std::polar(radius_1, 0.3), std::polar(0.95, 1.1)};
  const Eigen::Vector2cd c1(Complex(0.4, 0.1), Complex(-0.2, 0.3));
  const Eigen::Vector2cd b1(Complex(0.5, 0.0), Complex(0.1, -0.4));
  const Eigen::Vector2cd c2(Complex(0.1, -0.3), Complex(0.3, 0.2));
  const Eigen::Vector2cd b2(Complex(-0.2, 0.1), Complex(0.6, 0.0));
  system.residues = {c1 * b1.transpose(), c2 * b2.transpose()};
  system.d = (Eigen::MatrixXd(2, 2) << 0.01, 0.0, 0.02, -0.01).finished();
  return system;
}

BestLinearApproximation bla_of(const Resonances& system, std::size_t samples,
                               std::size_t max_line) {
  BestLinearApproximation bla;
  bla.sample_time = 1e-3;
  bla.samples = samples;
  for (std::size_t k = 1; k <= max_line; ++k) {
    bla.lines.push_back(k);
    bla.response.push_back(
        system.at(std::polar(1.0, 2.0 * std::numbers::pi * double(k) / double(samples))));
  }
  bla.blocks = 1;
  bla.periods = 1;
  return bla;
}

std::vector<Complex> sorted(std::vector<Complex> v) {
  std::sort(v.begin(), v.end(), [](Complex a, Complex b) {
    return a.imag() != b.imag() ? a.imag() < b.imag() : a.real() < b.real();
  });
  return v;
}

TEST(FitStateSpace, RecoversAFourthOrderMimoSystemAndItsPoles) {
  const auto system = two_resonances();
  const auto bla = bla_of(system, 512, 250);
  const auto fit = fit_state_space(bla, {.order = 4});
  EXPECT_EQ(fit.model.order(), 4u);
  EXPECT_TRUE(fit.model.is_stable());
  const auto response = fit.model.frequency_response(bla.frequencies());
  for (std::size_t l = 0; l < bla.lines.size(); ++l)
    EXPECT_LT((response[l] - bla.response[l]).norm(), 1e-8 * bla.response[l].norm()) << l;
  const auto poles = fit.model.poles();
  const auto found = sorted(std::vector<Complex>(poles.begin(), poles.end()));
  const auto expected = sorted(
      {system.poles[0], std::conj(system.poles[0]), system.poles[1], std::conj(system.poles[1])});
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_LT(std::abs(found[i] - expected[i]), 1e-8) << i;
  EXPECT_EQ(fit.report.model, "state_space");
  EXPECT_EQ(fit.report.parameters, 4u + 8u + 8u + 4u);
  EXPECT_LT(fit.report.fit.rmse, 1e-8);
  EXPECT_LE(fit.report.final_cost, fit.subspace_cost + 1e-20);
}

TEST(FitStateSpace, SubspaceStageAloneIsExactOnNoiseFreeData) {
  const auto system = two_resonances();
  const auto bla = bla_of(system, 512, 250);
  const auto fit = fit_state_space(bla, {.order = 4, .max_iterations = 0});
  EXPECT_EQ(fit.report.iterations, 0u);
  EXPECT_LT(fit.report.fit.rmse, 1e-8);
}

TEST(FitStateSpace, RefinementLowersTheCostOfANoisyResponse) {
  auto bla = bla_of(two_resonances(), 512, 250);
  std::mt19937_64 random(5);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (auto& g : bla.response)
    for (Eigen::Index i = 0; i < g.size(); ++i)
      g(i) += Complex(noise(random), noise(random));
  const auto fit = fit_state_space(bla, {.order = 4, .weighting = BlaWeighting::none});
  EXPECT_LT(fit.report.final_cost, fit.subspace_cost);
  EXPECT_TRUE(fit.model.is_stable());
}

TEST(FitStateSpace, AnUnstableResponseGivesAStableModel) {
  const auto bla = bla_of(two_resonances(1.02), 512, 250);
  const auto fit = fit_state_space(bla, {.order = 4, .max_pole_radius = 0.999});
  EXPECT_LE(fit.model.spectral_radius(), 0.999 + 1e-12);
}

TEST(FitStateSpace, RejectsImpossibleRequests) {
  const auto bla = bla_of(two_resonances(), 64, 10);
  EXPECT_HYST_ERROR(fit_state_space(bla, {.order = 0}), "order 0 must be in 1..");
  EXPECT_HYST_ERROR(fit_state_space(bla, {.order = 4, .subspace_block_rows = 4}),
                    "q = 4 must exceed the order 4");
  EXPECT_HYST_ERROR(fit_state_space(bla, {.order = 12}), "10 lines are too few for order 12");
  EXPECT_HYST_ERROR(fit_state_space(bla, {.order = 2, .max_pole_radius = 1.0}),
                    "max_pole_radius 1 must be in (0, 1)");
  EXPECT_HYST_ERROR(fit_state_space(bla, {.order = 2, .weighting = BlaWeighting::noise_variance}),
                    "needs a BLA of 2 periods or more");
}

}  // namespace
}  // namespace hyst
