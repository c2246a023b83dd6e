// Offset and drift removal against records whose offset and drift are known by construction.

#include "hyst/data/corrections.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "synthetic_records.hpp"

namespace hyst::data {
namespace {

TEST(RemoveOffset, EachReferenceRemovesItsOwnOffset) {
  // Mean 0, first -2, midrange 0.5 before adding 3.5.
  const std::vector<double> base{-2, 3, 1, -2};
  std::vector<double> values;
  for (const double v : base)
    values.push_back(v + 3.5);
  const auto mean = remove_offset(values, OffsetReference::mean);
  EXPECT_DOUBLE_EQ(mean.offset, 3.5);
  for (std::size_t k = 0; k < base.size(); ++k)
    EXPECT_DOUBLE_EQ(mean.values[k], base[k]);
  EXPECT_DOUBLE_EQ(remove_offset(values, OffsetReference::first).offset, 1.5);
  EXPECT_DOUBLE_EQ(remove_offset(values, OffsetReference::midrange).offset, 4.0);
  EXPECT_EQ(remove_offset(values, OffsetReference::first).values[0], 0.0);
  EXPECT_EQ(offset_reference_from_string("midrange"), OffsetReference::midrange);
  EXPECT_EQ(to_string(OffsetReference::first), "first");
  EXPECT_HYST_ERROR(offset_reference_from_string("median"), "unknown offset reference 'median'");
  EXPECT_HYST_ERROR(remove_offset(std::vector<double>{}), "values has 0 samples");
}

// A periodic loop over the triangle input: output = input on rising parts, input + 4 falling.
std::vector<double> periodic_loop(const std::vector<double>& input) {
  std::vector<double> output(input.size());
  for (std::size_t k = 0; k < input.size(); ++k) {
    const bool falling = k > 0 && input[k] < input[k - 1];
    output[k] = input[k] + (falling ? 4.0 : 0.0);
  }
  return output;
}

TEST(RemoveDrift, LinearDriftIsRemovedExactlyAndTheLoopCloses) {
  const auto input = test::triangle(10, 3);  // cycles [0,40], [40,80], [80,120]
  const auto loop = periodic_loop(input);
  // Drift 0.02 per sample in cycle 1, -0.01 in cycle 2, 0.05 in cycle 3: piecewise linear.
  std::vector<double> drift(input.size());
  for (std::size_t k = 1; k < input.size(); ++k) {
    const double rate = k <= 40 ? 0.02 : (k <= 80 ? -0.01 : 0.05);
    drift[k] = drift[k - 1] + rate;
  }
  std::vector<double> measured(input.size());
  for (std::size_t k = 0; k < input.size(); ++k)
    measured[k] = loop[k] + drift[k];

  const auto removal = remove_drift(input, measured, 1.5);
  EXPECT_EQ(removal.cycles, 3U);
  EXPECT_NEAR(removal.closure_error, 40 * 0.02 + 40 * (-0.01) + 40 * 0.05, 1e-12);
  for (std::size_t k = 0; k < input.size(); ++k) {
    EXPECT_NEAR(removal.output[k], loop[k], 1e-12) << k;
    EXPECT_NEAR(removal.drift[k], drift[k], 1e-12) << k;
  }
}

TEST(RemoveDrift, ExtrapolatesTheLastSlopeAfterTheLastCycle) {
  auto input = test::triangle(10, 2);  // cycles end at 40 and 80
  for (int v = 1; v <= 5; ++v)
    input.push_back(v);  // a partial third period
  const auto loop = periodic_loop(input);
  std::vector<double> measured(input.size());
  for (std::size_t k = 0; k < input.size(); ++k)
    measured[k] = loop[k] - 0.03 * static_cast<double>(k);
  const auto removal = remove_drift(input, measured, 1.5);
  EXPECT_EQ(removal.cycles, 2U);
  for (std::size_t k = 0; k < input.size(); ++k)
    EXPECT_NEAR(removal.output[k], loop[k], 1e-12) << k;
}

TEST(RemoveDrift, NeedsACompleteCycle) {
  const auto input = test::through_nodes({0, 10, -10});
  const std::vector<double> output(input.size(), 1.0);
  EXPECT_HYST_ERROR(remove_drift(input, output, 1.5), "needs at least one complete cycle");
  EXPECT_HYST_ERROR(remove_drift(input, std::vector<double>{1, 2}, 1.5), "output");
}

}  // namespace
}  // namespace hyst::data
