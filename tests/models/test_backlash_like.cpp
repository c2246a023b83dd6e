// Backlash-like model (Su et al. 2000): exact steps against a fine Euler integration and the
// figures printed by reference/checks/misc_check.py and duhem_bw_check.py.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/models/backlash_like.hpp"

namespace hyst {
namespace {

std::vector<double> decaying_sine() {  // the input of misc_check.py
  std::vector<double> v(600);
  for (std::size_t k = 0; k < v.size(); ++k)
    v[k] = 2.0 * std::sin(2.0 * std::numbers::pi * k / 200.0) * std::exp(-(double)k / 500.0);
  return v;
}

TEST(BacklashLike, ExactStepMatchesFineEuler) {
  const BacklashLike model({.a = 3.0, .c = 1.2, .b1 = 0.4});
  const auto v = decaying_sine();
  auto state = model.initial_state();
  state.input = v[0];
  double w_euler = 0.0;
  double max_diff = 0.0;
  for (std::size_t k = 1; k < v.size(); ++k) {
    const double w = model.step(state, v[k]);
    const double dv = (v[k] - v[k - 1]) / 2000.0;
    double x = v[k - 1];
    for (int i = 0; i < 2000; ++i, x += dv)
      w_euler += 3.0 * std::abs(dv) * (1.2 * x - w_euler) + 0.4 * dv;
    max_diff = std::max(max_diff, std::abs(w - w_euler));
  }
  // misc_check.py: "backlash-like exact vs fine Euler max diff: 4.546727696230768e-06".
  EXPECT_NEAR(max_diff, 4.546727696230768e-06, 1e-9);
}

TEST(BacklashLike, ReversalSlopeAndPeakOfReferenceCheck) {
  struct Case {
    double a, c, b1, min_slope, peak;
  };
  // duhem_bw_check.py: min dw/dv and w at sample 1000 (v = 3 peak).
  for (const Case& t :
       {Case{1.0, 3.1635, 0.345, -2.4599, 6.812325}, Case{3.0, 1.2, 0.4, -0.4000, 3.333366},
        Case{3.0, 1.2, 0.8, 0.4000, 3.466683}}) {
    const BacklashLike model({.a = t.a, .c = t.c, .b1 = t.b1});
    auto state = model.initial_state();
    double previous_v = 0.0, previous_w = 0.0, min_slope = 1e9, peak = 0.0;
    for (int k = 1; k <= 8000; ++k) {
      const double v = 3.0 * std::sin(2.0 * std::numbers::pi * k / 4000.0);
      const double w = model.step(state, v);
      if (v != previous_v) min_slope = std::min(min_slope, (w - previous_w) / (v - previous_v));
      if (k == 1000) peak = w;
      previous_v = v;
      previous_w = w;
    }
    EXPECT_NEAR(min_slope, t.min_slope, 5e-5) << t.b1;
    EXPECT_NEAR(peak, t.peak, 5e-7) << t.b1;
    EXPECT_EQ(model.is_monotone(), t.b1 >= t.c / 2);
  }
}

TEST(BacklashLike, RateIndependentAndExactWhateverTheSpacing) {
  // Refining the samples along the same straight segments changes nothing (exact solution).
  const BacklashLike model({.a = 2.0, .c = 1.0, .b1 = 0.6});
  const auto v = decaying_sine();
  auto coarse = model.initial_state();
  auto fine = model.initial_state();
  double previous = 0.0;
  for (double x : v) {
    const double y = model.step(coarse, x);
    double y_fine = 0.0;
    for (int i = 1; i <= 7; ++i)
      y_fine = model.step(fine, previous + (x - previous) * i / 7.0);
    EXPECT_NEAR(y, y_fine, 1e-12);
    previous = x;
  }
}

TEST(BacklashLike, RejectsInvalidParameters) {
  EXPECT_HYST_ERROR(BacklashLike({.a = 0.0, .c = 1.0, .b1 = 0.5}),
                    "backlash-like a = 0 must be > 0");
  EXPECT_HYST_ERROR(BacklashLike({.a = 1.0, .c = -1.0, .b1 = 0.5}), "c = -1 must be > 0");
  EXPECT_HYST_ERROR(BacklashLike({.a = 1.0, .c = 1.0, .b1 = 1.0}), "B1 = 1 must be < 1");
}

}  // namespace
}  // namespace hyst
