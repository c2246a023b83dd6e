// The generic numerical inverse (bracketed search on the one-step map): hand-computed answers on
// the Ikuta SMA's cosine branches (a decreasing map, searched through a copy of the state), round
// trips on KP (through its preview) and Ikuta, range limits, options, no allocation.

#include "hyst/inverse/numerical_inverse.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"
#include "../support/expect_error.hpp"
#include "hyst/models/ikuta_sma.hpp"
#include "hyst/models/krasnoselskii_pokrovskii.hpp"

namespace hyst {
namespace {

static_assert(Previewable<KrasnoselskiiPokrovskii>);
static_assert(!Previewable<IkutaSma>);  // searched on a copy of its trivially copyable state

NumericalInverseOptions range(double input_min, double input_max) {
  NumericalInverseOptions options;
  options.input_min = input_min;
  options.input_max = input_max;
  return options;
}

// Heating window A_s = 1 .. A_f = 3, cooling window M_f = 0 .. M_s = 2, output 0 (austenite) ..
// 1 (martensite): y = xi, which falls while heating (a non-increasing map).
IkutaSma sma(double output_austenite, double output_martensite) {
  return IkutaSma({.martensite_finish = 0.0,
                   .martensite_start = 2.0,
                   .austenite_start = 1.0,
                   .austenite_finish = 3.0,
                   .output_austenite = output_austenite,
                   .output_martensite = output_martensite,
                   .initial_fraction = 1.0,
                   .initial_input = 0.0});
}

// 6 cells on [0, 3], ramps of one cell, weights 1 + (i + j)/10: a continuous, hysteretic,
// non-decreasing model (Lipschitz constant sum mu 2/a).
KrasnoselskiiPokrovskii kp() {
  KrasnoselskiiPokrovskii::Params params;
  params.levels = 6;
  params.lower = 0.0;
  params.upper = 3.0;
  for (std::size_t i = 0; i < 6; ++i) {
    for (std::size_t j = 0; j <= i; ++j)
      params.weights.push_back(1.0 + 0.1 * double(i + j));
  }
  params.offset = 0.5;
  return KrasnoselskiiPokrovskii(params);
}

// A damped oscillation with internal reversals inside [lo, hi].
std::vector<double> wandering_input(double lo, double hi, int samples) {
  std::vector<double> v(samples);
  for (int k = 0; k < samples; ++k) {
    const double t = double(k) / samples;
    v[k] = lo + (hi - lo) * (0.5 + 0.5 * (1.0 - 0.7 * t) * std::sin(2 * std::numbers::pi * 5 * t));
  }
  return v;
}

TEST(NumericalInverse, SolvesTheIkutaBranchesByHand) {
  // Heating from xi = 1: xi = h(v) = (cos(pi (v - 1)/2) + 1)/2 = 0.5 at v = 2. Cooling from
  // there: scale = (1 - 0.5)/g(2) = 0.5, xi = 1 - 0.5 g(v) = 0.75 where g(v) = (1 - cos(pi
  // v/2))/2 = 0.5, at v = 1.
  const NumericalInverse<IkutaSma> inverse(sma(0.0, 1.0), range(-1.0, 4.0));
  auto state = inverse.initial_state();
  auto first = inverse.solve(state, 0.5);
  EXPECT_EQ(first.status, InverseStatus::ok);
  EXPECT_NEAR(first.input, 2.0, 1e-9);
  EXPECT_NEAR(state.fraction, 0.5, 1e-12);
  auto second = inverse.solve(state, 0.75);
  EXPECT_EQ(second.status, InverseStatus::ok);
  EXPECT_NEAR(second.input, 1.0, 1e-9);
  EXPECT_NEAR(state.fraction, 0.75, 1e-12);
}

TEST(NumericalInverse, RoundTripsOnKpThroughItsPreview) {
  const auto model = kp();
  // preview() is the output step() would give, without changing the state.
  auto probe = model.initial_state();
  model.step(probe, 2.0);
  for (double u : {0.0, 0.7, 1.4, 2.2, 3.0}) {
    auto copy = probe;
    const auto before = probe.kernels;
    EXPECT_NEAR(model.preview(probe, u), model.step(copy, u), 1e-12);
    EXPECT_EQ(probe.kernels, before);
  }
  const NumericalInverse<KrasnoselskiiPokrovskii> inverse(model, range(0.0, 3.0));
  const double lipschitz = model.total_weight() * 2.0 / model.ramp_width();
  auto forward = model.initial_state();
  auto state = inverse.initial_state();
  for (double v : wandering_input(0.1, 2.9, 400)) {
    const double target = model.step(forward, v);
    const auto sample = inverse.solve(state, target);
    ASSERT_EQ(sample.status, InverseStatus::ok);
    // y(u) is continuous: within the Lipschitz constant times the bracket width of the target.
    EXPECT_NEAR(model.output(state), target, lipschitz * inverse.input_tolerance() + 1e-12);
  }
}

TEST(NumericalInverse, RoundTripsOnIkutaRisingOrFalling) {
  for (const auto& model : {sma(0.0, 1.0), sma(1.0, 0.0)}) {
    const NumericalInverse<IkutaSma> inverse(model, range(-1.0, 4.0));
    auto forward = model.initial_state();
    auto state = inverse.initial_state();
    for (double v : wandering_input(-0.5, 3.5, 300)) {
      const double target = model.step(forward, v);
      ASSERT_EQ(inverse.solve(state, target).status, InverseStatus::ok);
      // |dy/dv| <= scale pi/4 on a branch (|y_M - y_A| = 1, window width 2, law slopes <= pi/4).
      const double slope = std::max(1.0, state.scale) * std::numbers::pi / 4.0;
      EXPECT_NEAR(model.output(state), target, slope * inverse.input_tolerance() + 1e-12);
    }
  }
}

TEST(NumericalInverse, LimitsTheInputOutsideTheReachableOutputs) {
  const auto model = kp();
  const NumericalInverse<KrasnoselskiiPokrovskii> inverse(model, range(0.5, 2.5));
  auto state = inverse.initial_state();
  const auto high = inverse.solve(state, 1e6);
  EXPECT_EQ(high.status, InverseStatus::above_range);
  EXPECT_EQ(high.input, 2.5);
  const auto low = inverse.solve(state, -1e6);
  EXPECT_EQ(low.status, InverseStatus::below_range);
  EXPECT_EQ(low.input, 0.5);
  // A falling map: the highest output needs the lowest input.
  const NumericalInverse<IkutaSma> falling(sma(0.0, 1.0), range(-1.0, 4.0));
  auto sma_state = falling.initial_state();
  const auto above = falling.solve(sma_state, 2.0);
  EXPECT_EQ(above.status, InverseStatus::below_range);
  EXPECT_EQ(above.input, -1.0);
}

TEST(NumericalInverse, RejectsInvalidOptions) {
  const auto model = kp();
  EXPECT_HYST_ERROR((NumericalInverse<KrasnoselskiiPokrovskii>(model, {})),
                    "numerical inverse input_min = nan must be < input_max = nan, both finite");
  EXPECT_HYST_ERROR((NumericalInverse<KrasnoselskiiPokrovskii>(model, range(2.0, 1.0))),
                    "input_min = 2 must be < input_max = 1");
  auto options = range(0.0, 1.0);
  options.input_tolerance = 0.0;
  EXPECT_HYST_ERROR((NumericalInverse<KrasnoselskiiPokrovskii>(model, options)),
                    "input_tolerance = 0 must be > 0");
  options.input_tolerance = std::nullopt;
  options.output_tolerance = -1.0;
  EXPECT_HYST_ERROR((NumericalInverse<KrasnoselskiiPokrovskii>(model, options)),
                    "output_tolerance = -1 must be >= 0");
}

TEST(NumericalInverse, SolveDoesNotAllocate) {
  const auto model = kp();
  const NumericalInverse<KrasnoselskiiPokrovskii> kp_inverse(model, range(0.0, 3.0));
  const NumericalInverse<IkutaSma> sma_inverse(sma(1.0, 0.0), range(-1.0, 4.0));
  auto kp_state = kp_inverse.initial_state();
  auto sma_state = sma_inverse.initial_state();
  double sink = 0.0;
  const long before = test::allocation_count();
  for (int k = 0; k < 2000; ++k) {
    const double phase = std::sin(1e-2 * k);
    sink += kp_inverse.step(kp_state, 0.5 + 10.0 * phase);
    sink += sma_inverse.step(sma_state, 0.5 + 0.6 * phase);
  }
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace hyst
