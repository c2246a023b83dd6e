// Bouc-Wen model: reference values of duhem_bw_check.py, the normalised form, boundedness,
// convergence in the sub-steps, rate independence, parameter rules.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/models/bouc_wen.hpp"

namespace hyst {
namespace {

std::vector<double> reference_input() {  // x = 2.5 sin(2 pi k / 1000) (1 - k / 4000)
  std::vector<double> x(3000);
  for (std::size_t k = 0; k < x.size(); ++k)
    x[k] = 2.5 * std::sin(2.0 * std::numbers::pi * k / 1000.0) * (1.0 - k / 4000.0);
  return x;
}

BoucWen::Params reference_params() {
  BoucWen::Params p;
  p.a = 1.0;
  p.beta = 0.6;
  p.gamma = 0.2;
  p.n = 1.5;
  p.stiffness = 1.0;
  p.alpha_k = 0.0;  // F = z
  return p;
}

TEST(BoucWen, ReferenceValuesAndBound) {
  const BoucWen model(reference_params());
  EXPECT_NEAR(model.z_bound(), 1.160397208, 1e-9);  // duhem_bw_check.py
  auto state = model.initial_state();
  std::vector<double> z;
  for (double x : reference_input())
    z.push_back(model.step(state, x));
  EXPECT_NEAR(z[250], 1.080417782, 1e-9);
  EXPECT_NEAR(z[750], -1.138086613, 1e-9);
  EXPECT_NEAR(z[1250], 1.112309402, 1e-9);
  double max_abs = 0.0;
  for (double value : z)
    max_abs = std::max(max_abs, std::abs(value));
  EXPECT_NEAR(max_abs, 1.141696766, 1e-9);
  EXPECT_LE(max_abs, model.z_bound());
}

TEST(BoucWen, NormalisedFormGivesTheSameOutput) {
  auto p = reference_params();
  p.stiffness = 3.0;
  p.alpha_k = 0.25;
  const BoucWen standard(p);
  const auto w = standard.normalised();
  EXPECT_NEAR(w.sigma, 0.75, 1e-15);
  const BoucWen normalised(BoucWen::from_normalised(w));
  EXPECT_DOUBLE_EQ(normalised.params().a, 1.0);
  auto s1 = standard.initial_state();
  auto s2 = normalised.initial_state();
  for (double x : reference_input())
    EXPECT_NEAR(standard.step(s1, x), normalised.step(s2, x), 1e-11);
}

TEST(BoucWen, ConvergesToFineStepReference) {
  // 20 vs 200 RK4 sub-steps: 6.6e-11 in duhem_bw_check.py; the error falls as the step^4.
  auto coarse_params = reference_params();
  coarse_params.substeps = 20;
  auto fine_params = reference_params();
  fine_params.substeps = 200;
  auto few_params = reference_params();
  few_params.substeps = 2;
  const BoucWen coarse(coarse_params), fine(fine_params), few(few_params);
  auto sc = coarse.initial_state(), sf = fine.initial_state(), s2 = few.initial_state();
  double err20 = 0.0, err2 = 0.0;
  for (double x : reference_input()) {
    const double yf = fine.step(sf, x);
    err20 = std::max(err20, std::abs(coarse.step(sc, x) - yf));
    err2 = std::max(err2, std::abs(few.step(s2, x) - yf));
  }
  EXPECT_NEAR(err20, 6.6265e-11, 1e-12);
  EXPECT_GT(err2, 100.0 * err20);  // not 10^4: |z|^(n-1) z is not smooth at z = 0
}

TEST(BoucWen, MaxInputStepMakesLargeStepsAccurate) {
  // One sample from 0 to 2: with max_input_step = 0.01 it matches a 20000-step reference, with a
  // single RK4 step (a bound beyond the jump) it does not; the automatic bound (0) keeps it
  // accurate too.
  auto p = reference_params();
  p.substeps = 1;
  p.max_input_step = 1e9;
  const BoucWen single(p);
  p.max_input_step = 0.01;
  const BoucWen limited(p);
  p.max_input_step = 0.0;
  const BoucWen automatic(p);
  p.max_input_step = 1e-4;
  const BoucWen reference(p);
  auto s1 = single.initial_state(), s2 = limited.initial_state(), s3 = reference.initial_state(),
       s4 = automatic.initial_state();
  const double y_reference = reference.step(s3, 2.0);
  EXPECT_NEAR(limited.step(s2, 2.0), y_reference, 1e-8);
  EXPECT_NEAR(automatic.step(s4, 2.0), y_reference, 1e-5);
  EXPECT_GT(std::abs(single.step(s1, 2.0) - y_reference), 1e-3);
}

TEST(BoucWen, RateIndependent) {
  // Repeating each sample (a slower input) leaves the output sequence unchanged.
  const BoucWen model(reference_params());
  auto a = model.initial_state();
  auto b = model.initial_state();
  for (double x : reference_input()) {
    const double y = model.step(a, x);
    model.step(b, x);
    EXPECT_EQ(model.step(b, x), y);
  }
}

TEST(BoucWen, RejectsUnboundedOrInconsistentParameters) {
  auto p = reference_params();
  p.gamma = 0.8;
  EXPECT_HYST_ERROR(BoucWen{p}, "Bouc-Wen beta - gamma = 0.6 - 0.8 = -0.2 must be >= 0");
  p = reference_params();
  p.beta = -0.6;
  p.gamma = -0.7;
  EXPECT_HYST_ERROR(BoucWen{p}, "beta + gamma = -0.6 + -0.7 = -1.3 must be > 0");
  p = reference_params();
  p.n = 0.5;
  EXPECT_HYST_ERROR(BoucWen{p}, "exponent n = 0.5 must be >= 1");
  p = reference_params();
  p.a = 0.0;
  EXPECT_HYST_ERROR(BoucWen{p}, "Bouc-Wen A = 0 must be > 0");
  p = reference_params();
  p.alpha_k = 1.5;
  EXPECT_HYST_ERROR(BoucWen{p}, "alpha_k = 1.5 must be <= 1");
  EXPECT_HYST_ERROR(
      BoucWen::from_normalised({.rho = 1.0, .sigma = 0.4, .n = 1.0, .kx = 1.0, .kw = 1.0}),
      "sigma = 0.4 must be >= 0.5");
  const BoucWen model(reference_params());
  EXPECT_HYST_ERROR(model.make_state(0.0, 2.0), "|z| = 2 must be <= z0");
}

}  // namespace
}  // namespace hyst
