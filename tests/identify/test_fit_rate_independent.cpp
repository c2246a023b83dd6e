// Fits of the rate-independent differential models (Bouc-Wen, Duhem, backlash-like): known
// parameters recovered from simulated noisy data.

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_bouc_wen.hpp"
#include "hyst/identify/fit_duhem.hpp"

namespace hyst {
namespace {

std::vector<double> excitation() {  // decaying and growing loops: minor loops included
  std::vector<double> v(800);
  for (std::size_t k = 0; k < v.size(); ++k)
    v[k] =
        2.0 * std::sin(2 * M_PI * k / 200.0) * (0.4 + 0.6 * std::abs(std::sin(M_PI * k / 800.0)));
  return v;
}

template <class Model>
std::vector<double> noisy_output(const Model& model, typename Model::State state,
                                 const std::vector<double>& v, double sigma) {
  auto y = simulate(model, state, v);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, sigma);
  for (double& value : y)
    value += noise(rng);
  return y;
}

TEST(FitRateIndependent, BoucWenNormalisedParametersRecovered) {
  const BoucWen::Normalised truth{.rho = 1.5, .sigma = 0.8, .n = 1.0, .kx = 0.4, .kw = 1.2};
  const BoucWen model(BoucWen::from_normalised(truth));
  const auto v = excitation();
  auto state = model.initial_state();
  state.input = v.front();
  const auto y = noisy_output(model, state, v, 1e-3);
  BoucWenFitOptions options;
  options.validate_fraction = 0.25;
  const auto fit = fit_bouc_wen(v, y, options);
  EXPECT_EQ(fit.report.termination, Termination::converged) << fit.report.message;
  const auto w = fit.model.normalised();
  EXPECT_NEAR(w.rho, truth.rho, 0.02 * truth.rho);
  EXPECT_NEAR(w.sigma, truth.sigma, 0.02);
  EXPECT_NEAR(w.kx, truth.kx, 0.02 * truth.kx);
  EXPECT_NEAR(w.kw, truth.kw, 0.02 * truth.kw);
  ASSERT_TRUE(fit.report.validation.has_value());
  EXPECT_NEAR(fit.report.validation->rmse, 1e-3, 2e-4);
}

TEST(FitRateIndependent, DuhemParametersRecovered) {
  Duhem::Params truth;
  truth.alpha = 2.0;
  truth.f_slope = 0.3;
  truth.f_sat = 1.0;
  truth.v_sat = 0.8;
  truth.g_peak = 0.6;
  const Duhem model(truth);
  const auto v = excitation();
  const auto y = noisy_output(model, model.make_state(v.front(), 0.0), v, 1e-3);
  auto y0 = y;
  y0[0] = 0.0;  // the fit starts from the measured first output
  const auto fit = fit_duhem(v, y0);
  EXPECT_EQ(fit.report.termination, Termination::converged) << fit.report.message;
  const auto& p = fit.model.params();
  EXPECT_NEAR(p.alpha, truth.alpha, 0.05 * truth.alpha);
  EXPECT_NEAR(p.f_slope, truth.f_slope, 0.05 * truth.f_slope);
  EXPECT_NEAR(p.f_sat, truth.f_sat, 0.05 * truth.f_sat);
  EXPECT_NEAR(p.v_sat, truth.v_sat, 0.05 * truth.v_sat);
  EXPECT_NEAR(p.g_peak, truth.g_peak, 0.05 * truth.g_peak);
}

TEST(FitRateIndependent, BacklashLikeParametersRecovered) {
  const BacklashLike model({.a = 3.0, .c = 1.2, .b1 = 0.7});
  const auto v = excitation();
  auto y = noisy_output(model, model.state_at(v.front(), 0.0), v, 1e-3);
  y[0] = 0.0;
  const auto fit = fit_backlash_like(v, y);
  EXPECT_EQ(fit.report.termination, Termination::converged) << fit.report.message;
  const auto& p = fit.model.params();
  EXPECT_NEAR(p.a, 3.0, 0.03);
  EXPECT_NEAR(p.c, 1.2, 0.01);
  EXPECT_NEAR(p.b1, 0.7, 0.01);
}

}  // namespace
}  // namespace hyst
