// Resampling per branch: exact grid values on straight branches, equal arc-length steps, reversal
// points kept, and a rate-independent model sees the same loop.

#include "hyst/data/resampling.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/data/reversal_points.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst::data {
namespace {

// Up from 0 to 10 with a slow dense part (0 .. 1 in steps of 0.1), then down to 0 in unit steps.
// Output: y = 2 v going up, y = 3 v - 10 going down (both pass through (10, 20)).
struct SlowRecord {
  std::vector<double> input, output;
};
SlowRecord slow_record() {
  SlowRecord r;
  for (int i = 0; i <= 10; ++i)
    r.input.push_back(0.1 * i);
  for (int v = 2; v <= 10; ++v)
    r.input.push_back(v);
  for (int v = 9; v >= 0; --v)
    r.input.push_back(v);
  for (std::size_t k = 0; k < r.input.size(); ++k) {
    const bool down = k > 0 && r.input[k] < r.input[k - 1];
    r.output.push_back(down ? 3.0 * r.input[k] - 10.0 : 2.0 * r.input[k]);
  }
  return r;
}

TEST(ResampleOnInputGrid, StraightBranchesGiveExactGridValues) {
  const auto r = slow_record();  // 30 samples, 11 of them in the first unit of input
  const auto out = resample_on_input_grid(r.input, r.output, 0.5, 1.0);
  // 10 intervals up (11 points), 10 down (the shared maximum counted once): 21 points.
  ASSERT_EQ(out.input.size(), 21U);
  for (std::size_t i = 0; i <= 10; ++i) {
    EXPECT_NEAR(out.input[i], static_cast<double>(i), 1e-12);
    EXPECT_NEAR(out.output[i], 2.0 * out.input[i], 1e-12);
  }
  for (std::size_t i = 11; i < 21; ++i) {
    EXPECT_NEAR(out.input[i], 20.0 - static_cast<double>(i), 1e-12);
    EXPECT_NEAR(out.output[i], 3.0 * out.input[i] - 10.0, 1e-12);
  }
  // A step that does not divide the branch: intervals of equal size <= step (10 / 4 = 2.5).
  const auto coarse = resample_on_input_grid(r.input, r.output, 0.5, 3.0);
  ASSERT_EQ(coarse.input.size(), 9U);
  EXPECT_NEAR(coarse.input[1], 2.5, 1e-12);
  EXPECT_NEAR(coarse.output[1], 5.0, 1e-12);
}

TEST(ResampleByArcLength, EqualStepsAlongTheNormalisedCurve) {
  const auto r = slow_record();
  const double step = 0.05;
  const auto out = resample_by_arc_length(r.input, r.output, 0.5, step);
  // Ranges: input 10, output 30 (-10 .. 20). Branch up: length hypot(1, 20/30); down:
  // hypot(1, 30/30). Each gets ceil(length / step) equal intervals.
  const double up = std::hypot(1.0, 20.0 / 30.0), down = std::hypot(1.0, 1.0);
  const auto m_up = static_cast<std::size_t>(std::ceil(up / step));
  const auto m_down = static_cast<std::size_t>(std::ceil(down / step));
  ASSERT_EQ(out.input.size(), m_up + m_down + 1);
  for (std::size_t i = 1; i < out.input.size(); ++i) {
    const double d = std::hypot((out.input[i] - out.input[i - 1]) / 10.0,
                                (out.output[i] - out.output[i - 1]) / 30.0);
    EXPECT_NEAR(d, i <= m_up ? up / static_cast<double>(m_up) : down / static_cast<double>(m_down),
                1e-12)
        << i;
  }
  EXPECT_EQ(out.input[m_up], 10.0);  // the reversal point itself
  EXPECT_HYST_ERROR(
      resample_by_arc_length(r.input, std::vector<double>(r.input.size(), 1.0), 0.5, step),
      "output range 0");
}

TEST(Resampling, KeepsTheReversalsSoAPlayModelTracesTheSameLoop) {
  // A record with internal loops, sampled unevenly (slow near the minima).
  std::vector<double> input;
  const std::vector<double> nodes{0, 3, -2, 1.5, -1, 2.5, 0.5};
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const int steps = nodes[i] < nodes[i - 1] ? 60 : 7;
    for (int s = 0; s < steps; ++s)
      input.push_back(nodes[i - 1] + (nodes[i] - nodes[i - 1]) * s / steps);
  }
  input.push_back(nodes.back());
  std::vector<double> output(input.size());
  const PrandtlIshlinskii model({{0.0, 0.4, 0.9}, {1.0, 0.5, 0.25}, 0.0});
  auto state = model.initial_state();
  simulate(model, state, input, output);

  const double band = 0.1;
  const auto out = resample_on_input_grid(input, output, band, 0.25);
  const auto before = reversal_points(input, band);
  const auto after = reversal_points(out.input, band);
  ASSERT_EQ(after.size(), before.size());
  // The model driven by the resampled input passes through the same outputs at the reversal
  // points: a rate-independent model depends only on the monotone path between them.
  std::vector<double> replay(out.input.size());
  auto fresh = model.initial_state();
  simulate(model, fresh, out.input, replay);
  for (std::size_t j = 0; j < after.size(); ++j) {
    EXPECT_EQ(after[j].value, before[j].value);
    EXPECT_NEAR(replay[after[j].index], output[before[j].index], 1e-12);
  }
  // 19.5 input units of travel in steps of at most 0.25: about 80 samples instead of 202, of
  // which 180 were on the slow falling branches.
  EXPECT_LT(out.input.size(), input.size() / 2);
}

TEST(Resampling, RejectsInvalidSteps) {
  const auto r = slow_record();
  EXPECT_HYST_ERROR(resample_on_input_grid(r.input, r.output, 0.5, 0.0),
                    "input step = 0 must be finite and > 0");
  EXPECT_HYST_ERROR(resample_by_arc_length(r.input, r.output, 0.5, -1.0), "arc length step = -1");
  EXPECT_HYST_ERROR(resample_on_input_grid(r.input, r.output, 0.0, 1.0), "hysteresis band = 0");
}

// The sample count is bounded as a double before it becomes an integer: a step of 1e-17 used to
// overflow the conversion (undefined behaviour), and 1e-6 asked for gigabytes.
TEST(Resampling, RejectsStepsAskingForMoreSamplesThanTheLimit) {
  const auto r = slow_record();  // two branches of length 10
  EXPECT_HYST_ERROR(resample_on_input_grid(r.input, r.output, 0.5, 1e-17),
                    "input step 1e-17 asks for 2e+18 samples");
  EXPECT_HYST_ERROR(resample_on_input_grid(r.input, r.output, 0.5, 1e-6),
                    "more than the limit of 10000000");
  EXPECT_HYST_ERROR(resample_by_arc_length(r.input, r.output, 0.5, 1e-300),
                    "arc length step 1e-300 asks for");
  EXPECT_EQ(resample_on_input_grid(r.input, r.output, 0.5, 1e-5).input.size(), 2000001u);
}

}  // namespace
}  // namespace hyst::data
