// Integration between samples of the differential models, whatever the sample spacing: the exact
// Bouc-Wen solution for n = 1 (hand-computed cases, a 10^5-step RK4 reference) and the adaptive
// Dormand-Prince option `tolerance` of Bouc-Wen (n != 1), Duhem and Jiles-Atherton (convergence to
// a fine-step RK4 reference as the tolerance shrinks, rate independence across sample spacings).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "hyst/models/duhem.hpp"
#include "hyst/models/jiles_atherton.hpp"
#include "hyst/registry/dynamic_model.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

//! A decaying sine of amplitude `amplitude`, sampled with `per_period` samples per period over
//! `periods` periods; the phase is exact at multiples of 1 / per_period of a period.
std::vector<double> sine_path(double amplitude, std::size_t per_period, std::size_t periods) {
  std::vector<double> x(per_period * periods + 1);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double cycles = static_cast<double>(k) / static_cast<double>(per_period);
    x[k] = amplitude * std::sin(2.0 * std::numbers::pi * cycles) * (1.0 - 0.15 * cycles);
  }
  return x;
}

//! Large and small steps: a coarse sine (8 samples a period, steps up to 0.7 amplitude), full
//! jumps between the extremes, then a finely sampled sine with minor loops.
std::vector<double> mixed_path(double amplitude) {
  std::vector<double> x = sine_path(amplitude, 8, 2);
  for (double jump : {1.0, -1.0, 0.9, -0.3, 0.5})
    x.push_back(amplitude * jump);
  for (double v : sine_path(0.6 * amplitude, 200, 2))
    x.push_back(0.5 * amplitude + v);
  return x;
}

//! The same piecewise-linear path with `parts` equal sub-steps per step of `x`: sample k of `x` is
//! sample parts k of the result.
std::vector<double> refine(const std::vector<double>& x, std::size_t parts) {
  std::vector<double> fine{x.front()};
  for (std::size_t k = 1; k < x.size(); ++k) {
    for (std::size_t j = 1; j < parts; ++j)
      fine.push_back(x[k - 1] + (x[k] - x[k - 1]) * static_cast<double>(j) / parts);
    fine.push_back(x[k]);
  }
  return fine;
}

template <class Model>
std::vector<double> run(const Model& model, const std::vector<double>& input) {
  auto state = model.initial_state();
  std::vector<double> y;
  y.reserve(input.size());
  for (double x : input)
    y.push_back(model.step(state, x));
  return y;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
    d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

//! Adaptive runs at tolerances 1e-6 and 1e-10 against the fine-step reference: the error falls
//! with the tolerance and is small at 1e-10 (relative to the output scale `scale`). The tolerance
//! bounds the local error per Dormand-Prince step; the global error over the ~900 samples is larger
//! where the right-hand side is not smooth (z = 0 with n = 1.5, the Jiles-Atherton switch):
//! measured 6.5e-8 (Bouc-Wen), 1e-10 (Duhem), 4.5e-9 and 7.9e-9 T (Jiles-Atherton) at 1e-10.
template <class Model>
void expect_convergence(typename Model::Params params, const Model& reference,
                        const std::vector<double>& input, double scale) {
  const std::vector<double> y_reference = run(reference, input);
  params.tolerance = 1e-6;
  const double error_loose = max_difference(run(Model(params), input), y_reference);
  params.tolerance = 1e-10;
  const double error_tight = max_difference(run(Model(params), input), y_reference);
  std::printf("max error against the reference: tolerance 1e-6 %.3g, 1e-10 %.3g\n", error_loose,
              error_tight);
  EXPECT_LT(error_tight, 1e-7 * scale);
  EXPECT_LT(error_tight, 0.1 * error_loose);
}

//! The same piecewise-linear path sampled as mixed_path() and with each step cut into 7, compared
//! at the common samples.
template <class Model>
void expect_rate_independent(typename Model::Params params, double amplitude, double scale) {
  params.tolerance = 1e-10;
  const Model model(params);
  const auto coarse = mixed_path(amplitude);
  const auto y_coarse = run(model, coarse);
  const auto y_fine = run(model, refine(coarse, 7));
  double d = 0.0;
  for (std::size_t k = 0; k < coarse.size(); ++k)
    d = std::max(d, std::abs(y_coarse[k] - y_fine[7 * k]));
  std::printf("largest difference between the two samplings %.3g\n", d);
  EXPECT_LT(d, 1e-7 * scale);
}

BoucWen::Params bouc_wen_params(double n) {
  BoucWen::Params p;
  p.a = 1.0;
  p.beta = 0.6;
  p.gamma = 0.2;
  p.n = n;
  p.stiffness = 1.0;
  p.alpha_k = 0.0;  // F = z
  return p;
}

TEST(BoucWenExact, FromZeroRelaxesExponentially) {
  // z(0) = 0, s = +1, c = beta + gamma = 0.8: z = A / c (1 - e^(-c dx)), one sample of 0.7.
  const BoucWen model(bouc_wen_params(1.0));
  auto state = model.initial_state();
  EXPECT_NEAR(model.step(state, 0.7), 1.0 / 0.8 * (1.0 - std::exp(-0.8 * 0.7)), 1e-15);
  // Back down by 0.7 from z1 > 0: s = -1, c = beta - gamma = 0.4, dz/du = -A - c z until z = 0 at
  // u0 = ln(1 + c z1 / A) / c; then c = beta + gamma, z = -(A / 0.8) (1 - e^(-0.8 (0.7 - u0))).
  const double z1 = state.hysteretic;
  const double u0 = std::log(1.0 + 0.4 * z1) / 0.4;
  ASSERT_LT(u0, 0.7);
  EXPECT_NEAR(model.step(state, 0.0), -1.0 / 0.8 * (1.0 - std::exp(-0.8 * (0.7 - u0))), 1e-15);
}

TEST(BoucWenExact, CrossesZeroInsideOneLargeSample) {
  // beta = gamma = 0.5, A = 1, z(0) = -0.5, one sample to x = 1: while z < 0 (s = +1),
  // dz/dx = A - beta z + gamma z = 1, so z reaches 0 at x = 0.5; then dz/dx = 1 - z, so
  // z(1) = 1 - e^(-0.5).
  auto p = bouc_wen_params(1.0);
  p.beta = 0.5;
  p.gamma = 0.5;
  const BoucWen model(p);
  auto state = model.make_state(0.0, -0.5);
  EXPECT_NEAR(model.step(state, 1.0), 1.0 - std::exp(-0.5), 1e-15);
}

TEST(BoucWenExact, MatchesRk4WithManySubsteps) {
  // The exact path against 10^5 RK4 sub-steps per sample from the same start, over a decaying sine
  // of 100 samples a period (steps up to 0.16).
  const auto p = bouc_wen_params(1.0);
  const BoucWen model(p);
  auto state = model.initial_state();
  double z_rk4 = 0.0, x_previous = 0.0, d = 0.0;
  for (double x : sine_path(2.5, 100, 3)) {
    const double z = model.step(state, x);
    if (x != x_previous) {
      z_rk4 = detail::bouc_wen_advance(p.a, p.beta, p.gamma, p.n, z_rk4, x - x_previous, 100000);
    }
    x_previous = x;
    d = std::max(d, std::abs(z - z_rk4));
  }
  std::printf("exact against 10^5 RK4 sub-steps: %.3g\n", d);
  EXPECT_LT(d, 1e-12);
}

TEST(BoucWenExact, IndependentOfTheSampleSpacing) {
  // n = 1: the same piecewise-linear path sampled coarsely (steps up to the full range) and with
  // each step cut into 100 gives the same output at the common samples up to rounding.
  const BoucWen model(bouc_wen_params(1.0));
  const auto coarse = mixed_path(2.5);
  const auto y_coarse = run(model, coarse);
  const auto y_fine = run(model, refine(coarse, 100));
  for (std::size_t k = 0; k < coarse.size(); ++k)
    EXPECT_NEAR(y_coarse[k], y_fine[100 * k], 1e-12) << "sample " << k;
}

TEST(BoucWenAdaptive, ConvergesToFineStepReference) {
  auto reference_params = bouc_wen_params(1.5);
  reference_params.max_input_step = 1e-4;
  expect_convergence(bouc_wen_params(1.5), BoucWen(reference_params), mixed_path(2.5), 1.0);
}

TEST(BoucWenAdaptive, RateIndependent) {
  expect_rate_independent<BoucWen>(bouc_wen_params(1.5), 2.5, 1.0);
}

TEST(DuhemAdaptive, ConvergesToFineStepReference) {
  auto reference_params = Duhem::Params{};
  reference_params.max_input_step = 1e-4;
  expect_convergence(Duhem::Params{}, Duhem(reference_params), mixed_path(3.0), 3.0);
}

TEST(DuhemAdaptive, RateIndependent) {
  expect_rate_independent<Duhem>(Duhem::Params{}, 3.0, 3.0);
}

TEST(JilesAthertonAdaptive, ConvergesToFineStepReference) {
  for (auto variant : {JilesAthertonVariant::original, JilesAthertonVariant::venkataraman}) {
    SCOPED_TRACE(to_string(variant));
    JilesAtherton::Params params;
    params.variant = variant;
    auto reference_params = params;
    reference_params.max_field_step = 0.02;  // k / 20000
    expect_convergence(params, JilesAtherton(reference_params), mixed_path(3000.0), 2.0);
  }
}

TEST(JilesAthertonAdaptive, RateIndependent) {
  for (auto variant : {JilesAthertonVariant::original, JilesAthertonVariant::venkataraman}) {
    SCOPED_TRACE(to_string(variant));
    JilesAtherton::Params params;
    params.variant = variant;
    expect_rate_independent<JilesAtherton>(params, 3000.0, 2.0);
  }
}

TEST(DifferentialIntegration, RejectsBadTolerance) {
  auto bw = bouc_wen_params(1.5);
  bw.tolerance = -1e-6;
  EXPECT_HYST_ERROR(BoucWen{bw}, "tolerance = -1e-06 must be >= 0");
  Duhem::Params duhem;
  duhem.tolerance = std::nan("");
  EXPECT_HYST_ERROR(Duhem{duhem}, "tolerance = nan is not finite");
  JilesAtherton::Params ja;
  ja.tolerance = INFINITY;
  EXPECT_HYST_ERROR(JilesAtherton{ja}, "tolerance = inf is not finite");
  ja.tolerance = 1e-20;
  EXPECT_HYST_ERROR(JilesAtherton{ja}, "tolerance = 1e-20 must be 0 (fixed RK4 sub-steps) or in");
}

TEST(DifferentialIntegration, AdaptiveStepPassesNanOn) {
  Duhem::Params p;
  p.tolerance = 1e-10;
  const Duhem model(p);
  auto state = model.initial_state();
  EXPECT_TRUE(std::isnan(model.step(state, std::nan(""))));
}

TEST(DifferentialIntegration, ModelFileReadsAndWritesTolerance) {
  for (const char* name : {"bouc_wen", "duhem", "jiles_atherton"}) {
    SCOPED_TRACE(name);
    const ModelEntry& entry = ModelRegistry::builtin().find(name);
    nlohmann::json params = entry.example_params;
    if (std::string(name) == "bouc_wen") params["n"] = 1.5;
    params["tolerance"] = 1e-9;
    const auto model = entry.create(params, nullptr);
    EXPECT_EQ(model->params().at("tolerance").get<double>(), 1e-9);
    EXPECT_NE(model->describe().find("adaptive Dormand-Prince"), std::string::npos);
    params["tolerance"] = -1.0;
    EXPECT_HYST_ERROR(entry.create(params, nullptr), "tolerance = -1 must be >= 0");
  }
}

}  // namespace
}  // namespace hyst
