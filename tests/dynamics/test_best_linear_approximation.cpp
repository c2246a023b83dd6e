// The best linear approximation against closed forms: a linear system's response is recovered
// exactly, the noise variance matches its expectation, a static nonlinearity gives the BLA of
// Bussgang's theorem and a total variance above the noise variance.

#include "hyst/dynamics/best_linear_approximation.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "periodic_experiments.hpp"

namespace hyst {
namespace {

constexpr std::size_t kSamples = 256;
constexpr std::size_t kMaxLine = 60;

std::complex<double> point(std::size_t line) {
  return std::polar(1.0, 2.0 * std::numbers::pi * double(line) / double(kSamples));
}

TEST(BestLinearApproximation, RecoversTheResponseOfALinearMimoSystem) {
  const auto e = test::periodic_experiment(test::two_lags, 2, 2, 2, kSamples, kMaxLine, 4, 2, 7);
  const auto bla = estimate_bla(std::span(&e, 1), 0.5);
  ASSERT_EQ(bla.lines.size(), kMaxLine);
  EXPECT_EQ(bla.lines.front(), 1u);
  EXPECT_EQ(bla.blocks, 2u);
  EXPECT_EQ(bla.periods, 2u);
  EXPECT_DOUBLE_EQ(bla.frequencies()[2], 3.0 / (kSamples * 0.5));
  for (std::size_t l = 0; l < bla.lines.size(); ++l) {
    const Eigen::MatrixXcd expected = test::two_lags_response(point(bla.lines[l]));
    EXPECT_LT((bla.response[l] - expected).norm(), 1e-10 * expected.norm()) << "line " << l;
    EXPECT_LT(bla.noise_variance[l].maxCoeff(), 1e-24);
    EXPECT_LT(bla.total_variance[l].maxCoeff(), 1e-24);
  }
}

TEST(BestLinearApproximation, NoiseVarianceMatchesItsExpectation) {
  // SISO gain 1 plus white noise of variance s^2: the DFT of the noise has E|N|^2 = N s^2, so
  // var(G) = N s^2 / (|U|^2 P B) at each line.
  const double sigma = 0.05;
  const auto gain = [](Eigen::VectorXd&, const Eigen::VectorXd& u) -> Eigen::VectorXd { return u; };
  const std::size_t realisations = 8;
  const std::size_t periods = 4;
  const auto e = test::periodic_experiment(gain, 0, 1, 1, kSamples, kMaxLine, realisations, periods,
                                           11, sigma, 0);
  const auto bla = estimate_bla(std::span(&e, 1), 1.0);
  // |U_k|^2 = (N/2)^2 for a unit cosine.
  const double expected = double(kSamples) * sigma * sigma /
                          (std::pow(kSamples / 2.0, 2) * double(periods * realisations));
  double mean_noise = 0.0;
  double mean_total = 0.0;
  for (std::size_t l = 0; l < bla.lines.size(); ++l) {
    mean_noise += bla.noise_variance[l](0, 0) / double(bla.lines.size());
    mean_total += bla.total_variance[l](0, 0) / double(bla.lines.size());
    EXPECT_LT(std::abs(bla.response[l](0, 0) - 1.0), 6.0 * std::sqrt(expected));
  }
  // Averages of 60 lines' chi-square estimates: within 20 % (noise: 8 x 3 degrees of freedom per
  // line; total: 7).
  EXPECT_NEAR(mean_noise / expected, 1.0, 0.2);
  EXPECT_NEAR(mean_total / expected, 1.0, 0.25);
}

TEST(BestLinearApproximation, StaticCubicGivesBussgangGainAndDistortionVariance) {
  // y = u + c u^3 with Gaussian-like u of variance s^2: BLA = 1 + 3 c s^2 (Bussgang), and the
  // distortions vary from realisation to realisation: total variance >> noise variance (0 here).
  const double c = 0.02;
  const auto cubic = [c](Eigen::VectorXd&, const Eigen::VectorXd& u) -> Eigen::VectorXd {
    return u.array() + c * u.array().cube();
  };
  const auto e = test::periodic_experiment(cubic, 0, 1, 1, kSamples, kMaxLine, 40, 1, 3, 0.0, 0);
  const auto bla = estimate_bla(std::span(&e, 1), 1.0);
  const double variance = double(kMaxLine) / 2.0;  // 60 unit cosines
  std::complex<double> mean = 0.0;
  double total = 0.0;
  for (std::size_t l = 0; l < bla.lines.size(); ++l) {
    mean += bla.response[l](0, 0) / double(bla.lines.size());
    total += bla.total_variance[l](0, 0);
  }
  EXPECT_NEAR(mean.real(), 1.0 + 3.0 * c * variance, 0.05 * 3.0 * c * variance);
  EXPECT_NEAR(mean.imag(), 0.0, 0.01);
  EXPECT_GT(total, 0.0);
  EXPECT_TRUE(bla.noise_variance.empty());  // one period: no noise estimate
}

TEST(BestLinearApproximation, PoolsExperimentsAtSeveralLevels) {
  const auto low = test::periodic_experiment(test::two_lags, 2, 2, 2, kSamples, kMaxLine, 2, 1, 5);
  auto high = test::periodic_experiment(test::two_lags, 2, 2, 2, kSamples, kMaxLine, 2, 1, 6);
  for (double& v : high.input.values)
    v *= 3.0;
  for (double& v : high.output.values)
    v *= 3.0;
  const std::vector<PeriodicExperiment> both{low, high};
  const auto bla = estimate_bla(both, 1.0);
  EXPECT_EQ(bla.blocks, 2u);
  const Eigen::MatrixXcd expected = test::two_lags_response(point(bla.lines[4]));
  EXPECT_LT((bla.response[4] - expected).norm(), 1e-10);
}

TEST(BestLinearApproximation, RejectsWhatItCannotEstimate) {
  auto e = test::periodic_experiment(test::two_lags, 2, 2, 2, kSamples, kMaxLine, 2, 1, 5);
  EXPECT_HYST_ERROR(estimate_bla({}, 1.0), "no experiment");
  EXPECT_HYST_ERROR(estimate_bla(std::span(&e, 1), 0.0), "sample time");
  auto odd = e;
  odd.input.realisations = odd.output.realisations = 1;
  odd.input.values.resize(odd.input.values.size() / 2);
  odd.output.values.resize(odd.output.values.size() / 2);
  EXPECT_HYST_ERROR(estimate_bla(std::span(&odd, 1), 1.0),
                    "1 realisations are not a whole number of blocks of 2");
  auto same = e;  // both realisations alike: the block's inputs are not independent
  for (std::size_t n = 0; n < kSamples; ++n)
    for (std::size_t c = 0; c < 2; ++c)
      same.input(n, c, 1, 0) = same.input(n, c, 0, 0);
  EXPECT_HYST_ERROR(estimate_bla(std::span(&same, 1), 1.0), "are not independent");
  auto flat = e;
  std::fill(flat.input.values.begin(), flat.input.values.end(), 1.0);
  EXPECT_HYST_ERROR(estimate_bla(std::span(&flat, 1), 1.0), "no excited line");
  auto bad = e;
  bad.output.values[17] = std::nan("");
  EXPECT_HYST_ERROR(estimate_bla(std::span(&bad, 1), 1.0), "experiment 1 output[17]");
  auto mismatched = e;
  mismatched.output.periods = 2;
  EXPECT_HYST_ERROR(estimate_bla(std::span(&mismatched, 1), 1.0), "outputs 256 x 2 x 2");
}

}  // namespace
}  // namespace hyst
