// The backbone of a loop against the ellipse's analytic branches: x = A sin t, y = B sin(t - phi)
// has centre (B/A) cos(phi) x and half-width B sin(phi) sqrt(1 - x^2/A^2).

#include "hyst/data/backbone.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "synthetic_records.hpp"

namespace hyst::data {
namespace {

TEST(Backbone, EllipseCentreAndHalfWidthAreAnalytic) {
  const double a = 2.0, b = 3.0, phi = 0.7;
  const std::size_t n = 4000;
  std::vector<double> x, y;
  for (std::size_t k = 0; k <= n; ++k) {  // one period, from t = 0 to 2 pi
    const double t = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    x.push_back(a * std::sin(t));
    y.push_back(b * std::sin(t - phi));
  }
  const auto bone = backbone(x, y, 0.1, 0, n, 41);
  ASSERT_EQ(bone.input.size(), 41U);
  // The grid covers what both branches reach: the sampled extremes, +-A up to rounding.
  EXPECT_NEAR(bone.input.front(), -a, 1e-9);
  EXPECT_NEAR(bone.input.back(), a, 1e-9);
  // Linear interpolation on a curve sampled 2 pi / 4000 apart; near the tips, where the branches
  // are vertical in x, the error grows like sqrt(dx): compare inside 95 % of the range there.
  for (std::size_t i = 0; i < bone.input.size(); ++i) {
    const double v = bone.input[i];
    const double r = std::sqrt(std::max(0.0, 1.0 - v * v / (a * a)));
    const double tolerance = std::abs(v) < 0.95 * a ? 1e-5 : 0.05;
    EXPECT_NEAR(bone.centre[i], b / a * std::cos(phi) * v, tolerance) << v;
    EXPECT_NEAR(bone.half_width[i], b * std::sin(phi) * r, tolerance) << v;
    EXPECT_NEAR(bone.ascending[i], bone.centre[i] - bone.half_width[i], 1e-12);
    EXPECT_NEAR(bone.descending[i], bone.centre[i] + bone.half_width[i], 1e-12);
  }
}

TEST(Backbone, ParallelogramLoopHasAStraightCentre) {
  // Up along y = v, down along y = v + 4 (a triangle input, one period from 0): centre v + 2,
  // half-width 2, exactly.
  const auto input = test::triangle(10, 1);
  std::vector<double> output(input.size());
  for (std::size_t k = 0; k < input.size(); ++k)
    output[k] = input[k] + (k > 10 && k < 30 ? 4.0 : (k == 10 || k == 30 ? 2.0 : 0.0));
  // The descending branch runs 10 -> -10 with y = v + 4 except at its ends (2 at the reversals).
  const auto bone = backbone(input, output, 1.5, 0, input.size() - 1, 5);
  ASSERT_EQ(bone.input.size(), 5U);
  EXPECT_EQ(bone.input.front(), -10.0);
  EXPECT_EQ(bone.input.back(), 10.0);
  EXPECT_DOUBLE_EQ(bone.input[2], 0.0);
  EXPECT_DOUBLE_EQ(bone.centre[2], 2.0);
  EXPECT_DOUBLE_EQ(bone.half_width[2], 2.0);
  EXPECT_DOUBLE_EQ(bone.half_width[1], 2.0);
}

TEST(Backbone, RejectsLoopsWithoutBothBranches) {
  const auto ramp = test::through_nodes({0, 10});
  EXPECT_HYST_ERROR(backbone(ramp, ramp, 1.0, 0, 10), "has only ascending ones");
  const auto input = test::triangle(10, 1);
  EXPECT_HYST_ERROR(backbone(input, input, 1.0, 0, 50), "loop samples 0..50");
  EXPECT_HYST_ERROR(backbone(input, input, 1.0, 0, 40, 1), "backbone points = 1 must be >= 2");
}

}  // namespace
}  // namespace hyst::data
