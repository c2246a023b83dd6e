// Continuous Preisach models: the factorised Gaussian and Lorentzian Everett functions against
// 2-D quadrature of their densities, the tabulated (bilinear) Everett function, and their
// properties under the staircase memory.

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/models/preisach.hpp"

namespace hyst {
namespace {

GaussianEverett::Params gaussian_params() {
  return {.lower = -1.0,
          .upper = 1.0,
          .saturation = 2.0,
          .alpha_centre = 0.3,
          .alpha_width = 0.15,
          .beta_centre = -0.25,
          .beta_width = 0.2};
}

LorentzianEverett::Params lorentzian_params() {
  return {.lower = -1.0,
          .upper = 1.5,
          .saturation = 0.7,
          .alpha_centre = 0.2,
          .alpha_width = 0.05,
          .beta_centre = -0.3,
          .beta_width = 0.1};
}

// E(alpha, beta) = integral_beta^alpha da integral_beta^a db mu(a, b), by composite 10-point
// Gauss-Legendre rules in both directions (independent of the F, G, H decomposition).
template <class Everett>
double everett_by_quadrature(const Everett& everett, double alpha, double beta) {
  static constexpr std::array<double, 5> x{0.1488743389816312, 0.4333953941292472,
                                           0.6794095682990244, 0.8650633666889845,
                                           0.9739065285171717};
  static constexpr std::array<double, 5> w{0.2955242247147529, 0.2692667193099963,
                                           0.2190863625159820, 0.1494513491505806,
                                           0.0666713443086881};
  const auto integrate = [](double from, double to, int panels, auto&& f) {
    double sum = 0.0;
    const double width = (to - from) / panels;
    for (int p = 0; p < panels; ++p) {
      const double centre = from + (p + 0.5) * width;
      for (std::size_t k = 0; k < x.size(); ++k) {
        sum += w[k] * (f(centre - 0.5 * width * x[k]) + f(centre + 0.5 * width * x[k]));
      }
    }
    return 0.5 * width * sum;
  };
  return integrate(beta, alpha, 200, [&](double a) {
    return integrate(beta, a, 100, [&](double b) { return everett.density(a, b); });
  });
}

template <class Everett>
void expect_everett_matches_quadrature(const Everett& everett) {
  const double lo = everett.lower();
  const double hi = everett.upper();
  const double total = everett.total();
  EXPECT_NEAR(everett(hi, lo), total, 1e-13 * total);
  EXPECT_NEAR(everett_by_quadrature(everett, hi, lo), total, 1e-11 * total);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> level(lo, hi);
  double worst = 0;
  for (int trial = 0; trial < 12; ++trial) {
    double a = level(rng);
    double b = level(rng);
    if (a < b) std::swap(a, b);
    const double numeric = everett_by_quadrature(everett, a, b);
    worst = std::max(worst, std::abs(everett(a, b) - numeric) / total);
    EXPECT_NEAR(everett(a, b), numeric, 1e-11 * total) << "alpha = " << a << ", beta = " << b;
  }
  testing::Test::RecordProperty("worst_relative_error", fmt::format("{:.2e}", worst));
}

TEST(ContinuousPreisach, GaussianEverettMatchesQuadrature) {
  expect_everett_matches_quadrature(GaussianEverett(gaussian_params()));
}

TEST(ContinuousPreisach, LorentzianEverettMatchesQuadrature) {
  expect_everett_matches_quadrature(LorentzianEverett(lorentzian_params()));
}

// Equal widths: the Gaussian in alpha and beta is the Gaussian in (alpha+beta)/2 and
// (alpha-beta)/2 with standard deviations w / sqrt 2 (the header's remark).
TEST(ContinuousPreisach, IsotropicGaussianIsFactorisedInBothCoordinateSystems) {
  const GaussianEverett everett({.lower = -1,
                                 .upper = 1,
                                 .saturation = 1,
                                 .alpha_centre = 0.3,
                                 .alpha_width = 0.2,
                                 .beta_centre = -0.3,
                                 .beta_width = 0.2});
  const double s = 0.2 / std::sqrt(2.0);
  const auto rotated = [&](double a, double b) {
    const double u = 0.5 * (a + b);
    const double c = 0.5 * (a - b) - 0.3;
    return std::exp(-0.5 * (u * u + c * c) / (s * s));
  };
  const double scale = everett.density(0.3, -0.3) / rotated(0.3, -0.3);
  for (auto [a, b] : {std::pair{0.1, -0.2}, {0.5, 0.4}, {0.9, -0.8}, {0.0, -0.05}})
    EXPECT_NEAR(everett.density(a, b), scale * rotated(a, b), 1e-12 * scale);
}

TEST(ContinuousPreisach, EverettFunctionShapeAndClamping) {
  const GaussianEverett everett(gaussian_params());
  EXPECT_EQ(everett(0.2, 0.2), 0.0);
  EXPECT_EQ(everett(0.1, 0.3), 0.0);
  EXPECT_EQ(everett(INFINITY, -INFINITY), everett(1.0, -1.0));
  EXPECT_EQ(everett(5.0, 0.1), everett(1.0, 0.1));
  EXPECT_EQ(everett(-2.0, -3.0), 0.0);
  // Grows with alpha, falls with beta (mu >= 0).
  double previous = 0;
  for (double a = -0.5; a <= 1.0; a += 0.01) {
    const double e = everett(a, -0.5);
    EXPECT_GE(e, previous - 1e-15);
    previous = e;
  }
  previous = everett(0.8, -1.0);
  for (double b = -1.0; b <= 0.8; b += 0.01) {
    const double e = everett(0.8, b);
    EXPECT_LE(e, previous + 1e-15);
    previous = e;
  }
}

// The FORC identity (Mayergoyz): up from negative saturation to alpha, down to beta:
// E(alpha, beta) = (f_alpha - f_alpha,beta) / 2.
TEST(ContinuousPreisach, FirstOrderReversalCurvesGiveTheEverettFunction) {
  const LorentzianPreisach model({.everett = lorentzian_params(), .offset = 0.4});
  for (auto [a, b] : {std::pair{0.3, -0.2}, {1.2, -0.9}, {0.05, 0.0}}) {
    auto state = model.initial_state();
    const double f_a = model.step(state, a);
    const double f_ab = model.step(state, b);
    EXPECT_NEAR((f_a - f_ab) / 2, model.everett()(a, b), 1e-15);
  }
}

template <class Model>
void expect_preisach_properties(const Model& model) {
  // Saturation and bounds.
  auto state = model.make_state(PreisachInitialState::negative_saturation);
  EXPECT_EQ(model.output(state), model.output_min());
  EXPECT_EQ(model.step(state, model.upper() + 1), model.output_max());
  // Wiping-out: a larger maximum erases the smaller ones and the minima between them.
  auto a = model.initial_state();
  auto b = model.initial_state();
  simulate(model, a, std::vector<double>{0.6, -0.2, 0.3, 0.1, 0.6});
  simulate(model, b, std::vector<double>{0.6});
  for (double v : {0.2, -0.5, 0.4})
    EXPECT_EQ(model.step(a, v), model.step(b, v));
  // Congruency: the rise between the same extrema is 2 E(u2, u1) whatever the history.
  for (std::uint64_t seed : {1U, 2U}) {
    auto s = model.initial_state();
    simulate(model, s, test::random_walk(300, seed, 0.9, 0.2));
    simulate(model, s, std::vector<double>{0.95, -0.95, 0.9});
    const double bottom = model.step(s, -0.33);
    EXPECT_NEAR(model.step(s, 0.47) - bottom, 2 * model.everett()(0.47, -0.33),
                1e-13 * model.total_weight());
    EXPECT_NEAR(model.step(s, -0.33), bottom, 1e-13 * model.total_weight());
  }
  // Bounded, monotone, rate independent; the running sums agree with the recomputed formula.
  const auto v = test::random_walk(4000, 3, 1.0, 0.2);
  auto coarse = model.initial_state();
  auto fine = model.initial_state();
  const auto y = simulate(model, coarse, v);
  const auto y_fine = simulate(model, fine, test::upsample_linear(v, 3));
  for (std::size_t k = 0; k < v.size(); ++k) {
    ASSERT_NEAR(y[k], y_fine[3 * k], 1e-12 * model.total_weight());
    ASSERT_GE(y[k], model.output_min() - 1e-12);
    ASSERT_LE(y[k], model.output_max() + 1e-12);
    if (k > 0) {
      ASSERT_GE((y[k] - y[k - 1]) * (v[k] - v[k - 1]), -1e-13) << k;
    }
  }
  EXPECT_NEAR(y.back(), model.output(coarse), 1e-13 * model.total_weight());
}

TEST(ContinuousPreisach, GaussianModelHasThePreisachProperties) {
  expect_preisach_properties(GaussianPreisach({.everett = gaussian_params(), .offset = 1.0}));
}

TEST(ContinuousPreisach, LorentzianModelHasThePreisachProperties) {
  expect_preisach_properties(LorentzianPreisach({.everett = lorentzian_params()}));
}

TEST(ContinuousPreisach, TabulatedModelHasThePreisachProperties) {
  const GaussianEverett gauss(gaussian_params());
  TabulatedEverett::Params table;
  for (int a = 0; a <= 50; ++a)
    table.levels.push_back(-1.0 + 0.04 * a);
  for (std::size_t a = 1; a < table.levels.size(); ++a) {
    for (std::size_t c = 0; c < a; ++c)
      table.values.push_back(gauss(table.levels[a], table.levels[c]));
  }
  expect_preisach_properties(TabulatedPreisach({.everett = table, .offset = -0.3}));
}

// A density symmetric about the anti-diagonal (mu(alpha, beta) = mu(-beta, -alpha)) gives
// output 0 in the demagnetised state; the midpoint staircase gets there to O(h^2).
TEST(ContinuousPreisach, DemagnetisedSymmetricModelOutputsItsOffset) {
  const GaussianPreisach model({.everett = {.lower = -1,
                                            .upper = 1,
                                            .saturation = 1,
                                            .alpha_centre = 0.3,
                                            .alpha_width = 0.2,
                                            .beta_centre = -0.3,
                                            .beta_width = 0.2},
                                .offset = 0.5,
                                .initial_state = PreisachInitialState::demagnetised});
  const auto state = model.initial_state();
  EXPECT_NEAR(model.output(state), 0.5, 1e-4);
  // 64 maxima and 63 stored minima; the input rests at the last minimum, the centre 0.
  EXPECT_EQ(state.size, 2 * 64U);
  EXPECT_EQ(state.input, 0.0);
  testing::Test::RecordProperty("demagnetised_output_error",
                                fmt::format("{:.2e}", model.output(state) - 0.5));
  EXPECT_FALSE(state.from_positive_saturation());
}

// ---------------------------------------------------------------------------------------------
// Tabulated Everett function

// The discrete grid's Everett table at the cell boundaries b_k, as a TabulatedEverett.
TabulatedEverett::Params table_of(const Preisach& grid) {
  const std::size_t n = grid.everett().levels();
  TabulatedEverett::Params table;
  for (std::size_t k = 0; k <= n; ++k)
    table.levels.push_back(-1.0 + 2.0 * static_cast<double>(k) / static_cast<double>(n));
  for (std::size_t a = 1; a <= n; ++a) {
    for (std::size_t c = 0; c < a; ++c)
      table.values.push_back(grid.everett()(table.levels[a], table.levels[c]));
  }
  return table;
}

TEST(TabulatedPreisach, EqualsTheRelayGridForInputsOnTheCellBoundaries) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> mu(preisach_relay_count(15));
  for (double& m : mu)
    m = unit(rng);
  const Preisach grid(
      {.everett = {.levels = 15, .lower = -1, .upper = 1, .weights = mu}, .offset = 0.1});
  const TabulatedPreisach table({.everett = table_of(grid), .offset = 0.1});
  EXPECT_NEAR(table.total_weight(), grid.total_weight(), 1e-12);
  auto s_grid = grid.initial_state();
  auto s_table = table.initial_state();
  for (int k = 0; k < 5000; ++k) {
    const double v = table.everett().levels()[rng() % 16];
    ASSERT_NEAR(table.step(s_table, v), grid.step(s_grid, v), 1e-12) << "k = " << k;
  }
}

TEST(TabulatedPreisach, InterpolatesBilinearlyAndStaysContinuousOnTheDiagonal) {
  // Two cells: levels 0, 1, 3; E(1,0) = 1, E(3,1) = 2, E(3,0) = 5 (cell weight 5-1-2+0 = 2).
  const TabulatedEverett e({.levels = {0, 1, 3}, .values = {1, 5, 2}});
  EXPECT_EQ(e.total(), 5.0);
  EXPECT_EQ(e(1, 0), 1.0);
  EXPECT_EQ(e(3, 1), 2.0);
  EXPECT_DOUBLE_EQ(e(2, 0.5), 0.25 * (1 + 5 + 0 + 2));  // centre of the off-diagonal cell
  EXPECT_DOUBLE_EQ(e(0.75, 0.25), 0.5);                 // diagonal cell: 1 * (0.75 - 0.25)
  EXPECT_EQ(e(0.4, 0.4), 0.0);
  EXPECT_DOUBLE_EQ(e(2, 1), 1.0);  // edge between the cells
  EXPECT_EQ(e(10, -10), 5.0);
  // Output continuous at a reversal: a tiny step back changes it only a little.
  const TabulatedPreisach model({.everett = {.levels = {0, 1, 3}, .values = {1, 5, 2}}});
  auto state = model.initial_state();
  const double top = model.step(state, 2.0);
  EXPECT_NEAR(model.step(state, 2.0 - 1e-9), top, 1e-8);
}

TEST(TabulatedPreisach, ApproximatesTheGaussianItWasSampledFrom) {
  const GaussianPreisach exact({.everett = gaussian_params()});
  TabulatedEverett::Params table;
  const std::size_t k = 80;
  for (std::size_t a = 0; a <= k; ++a)
    table.levels.push_back(-1.0 + 2.0 * static_cast<double>(a) / k);
  for (std::size_t a = 1; a <= k; ++a) {
    for (std::size_t c = 0; c < a; ++c)
      table.values.push_back(exact.everett()(table.levels[a], table.levels[c]));
  }
  const TabulatedPreisach model({.everett = table});
  auto s_exact = exact.initial_state();
  auto s_table = model.initial_state();
  double worst = 0;
  for (double v : test::random_walk(5000, 4, 1.0, 0.2))
    worst = std::max(worst, std::abs(model.step(s_table, v) - exact.step(s_exact, v)));
  EXPECT_LT(worst / exact.total_weight(), 2e-3);  // h = 0.025: O(h) near the diagonal
}

TEST(TabulatedPreisach, RejectsBadTables) {
  using T = TabulatedEverett;
  EXPECT_HYST_ERROR(T({.levels = {0}, .values = {}}),
                    "tabulated Everett function has 1 levels x; it needs at least 2");
  EXPECT_HYST_ERROR(T({.levels = {0, 1, 1}, .values = {1, 1, 1}}),
                    "tabulated Everett level x[2] = 1 must be > x[1] = 1");
  EXPECT_HYST_ERROR(T({.levels = {0, NAN}, .values = {1}}),
                    "tabulated Everett level x[1] = nan is not finite");
  EXPECT_HYST_ERROR(T({.levels = {0, 1, 2}, .values = {1, 2}}),
                    "tabulated Everett function has 2 values but K + 1 = 3 levels need K(K+1)/2 "
                    "= 3");
  EXPECT_HYST_ERROR(T({.levels = {0, 1, 2}, .values = {1, INFINITY, 1}}),
                    "tabulated Everett value E[2,0] (values[1]) = inf is not finite");
  EXPECT_HYST_ERROR(T({.levels = {0, 1, 2}, .values = {1, 1.5, 1}}),
                    "tabulated Everett cell weight mu(1, 0) = E[2,0] - E[1,0] - E[2,1] + E[1,1] "
                    "= -0.5 must be >= 0");
  EXPECT_HYST_ERROR(T({.levels = {0, 1, 2}, .values = {-1, 1, 2}}),
                    "tabulated Everett cell weight mu(0, 0) = E[1,0] = -1 must be >= 0");
  try {
    T({.levels = {0, 1, 2}, .values = {1, 1.5, 1}});
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "values[1]");
  }
}

TEST(ContinuousPreisach, RejectsBadDensities) {
  const auto with = [](auto change) {
    auto p = gaussian_params();
    change(p);
    return p;
  };
  EXPECT_HYST_ERROR(GaussianEverett(with([](auto& p) { p.alpha_width = 0; })),
                    "Gaussian Preisach alpha_width = 0 must be > 0");
  EXPECT_HYST_ERROR(GaussianEverett(with([](auto& p) { p.beta_width = -1; })),
                    "Gaussian Preisach beta_width = -1 must be > 0");
  EXPECT_HYST_ERROR(GaussianEverett(with([](auto& p) { p.upper = -1; })),
                    "Gaussian Preisach upper = -1 must be > lower = -1");
  EXPECT_HYST_ERROR(GaussianEverett(with([](auto& p) { p.saturation = 0; })),
                    "Gaussian Preisach saturation = 0 must be > 0");
  EXPECT_HYST_ERROR(GaussianEverett(with([](auto& p) { p.alpha_centre = NAN; })),
                    "Gaussian Preisach alpha_centre = nan is not finite");
  EXPECT_HYST_ERROR(GaussianEverett(with([](auto& p) {
                      p.alpha_centre = 100;
                      p.alpha_width = 0.01;
                    })),
                    "Gaussian Preisach density integrates to 0");
  EXPECT_HYST_ERROR(LorentzianEverett({.lower = 0,
                                       .upper = 1,
                                       .saturation = 1,
                                       .alpha_centre = 0,
                                       .alpha_width = INFINITY,
                                       .beta_centre = 0,
                                       .beta_width = 1}),
                    "Lorentzian Preisach alpha_width = inf is not finite");
  EXPECT_HYST_ERROR(GaussianPreisach({.everett = gaussian_params(), .offset = INFINITY}),
                    "Preisach offset = inf is not finite");
}

}  // namespace
}  // namespace hyst
