// Branches and cycles of records whose turning points and periods are known by construction.

#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/data/branches.hpp"
#include "hyst/data/cycles.hpp"
#include "synthetic_records.hpp"

namespace hyst::data {
namespace {

using test::through_nodes;
using test::triangle;

TEST(Branches, TriangleSplitsAtEveryPeak) {
  const auto input = triangle(10, 3);  // peaks at 10, 30, 50, ..., 110; last sample 120
  const auto found = branches(input, 1.5);
  ASSERT_EQ(found.size(), 7U);
  EXPECT_EQ(found[0].first, 0U);
  EXPECT_EQ(found[0].last, 10U);
  EXPECT_EQ(found[0].direction, Direction::ascending);
  for (std::size_t j = 1; j < 6; ++j) {
    EXPECT_EQ(found[j].first, 10 + 20 * (j - 1));
    EXPECT_EQ(found[j].last, 10 + 20 * j);
    EXPECT_EQ(found[j].direction, j % 2 == 1 ? Direction::descending : Direction::ascending);
    EXPECT_EQ(found[j].samples(), 21U);
  }
  EXPECT_EQ(found[6].first, 110U);
  EXPECT_EQ(found[6].last, 120U);
  EXPECT_EQ(found[6].direction, Direction::ascending);
  EXPECT_EQ(to_string(found[1].direction), "descending");
}

TEST(Branches, MonotoneRecordIsOneBranch) {
  const auto input = through_nodes({5, -3});
  const auto found = branches(input, 0.5);
  ASSERT_EQ(found.size(), 1U);
  EXPECT_EQ(found[0].direction, Direction::descending);
  EXPECT_EQ(found[0].last, 8U);
  EXPECT_HYST_ERROR(branches(input, 8.0), "never moves by more than the hysteresis band 8");
}

TEST(Cycles, TriangleHasOneCyclePerPeriod) {
  const auto input = triangle(10, 3);
  const auto found = cycles(input, 1.5);
  ASSERT_EQ(found.size(), 3U);
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_EQ(found[j].first, 40 * j);
    EXPECT_EQ(found[j].last, 40 * (j + 1));
    EXPECT_FALSE(found[j].ends_at_record_end);
  }
  EXPECT_EQ(found[0].samples(), 41U);
}

TEST(Cycles, RecordStartingAtItsMinimumClosesAtEachMinimum) {
  const auto input = through_nodes({-10, 10, -10, 10, -10});
  const auto found = cycles(input, 1.5);
  ASSERT_EQ(found.size(), 2U);
  EXPECT_EQ(found[0].first, 0U);
  EXPECT_EQ(found[0].last, 40U);
  EXPECT_EQ(found[1].last, 80U);  // the last sample: back at the minimum it started from
  EXPECT_TRUE(found[1].ends_at_record_end);
  // A sine-like record that ends half a period into its second cycle closes only one.
  EXPECT_EQ(cycles(through_nodes({0, 10, -10, 0, 10, 0}), 1.5).size(), 1U);
}

TEST(Cycles, NoisyReturnsToAStartingExtremeStillClose) {
  // From the minimum -10 up and down twice, with +-0.3 on every sample: the later minima miss
  // -10 by up to 0.3 in either direction, within the band 1.5.
  auto input = through_nodes({-10, 10, -10, 10, -10});
  for (std::size_t k = 1; k < input.size(); ++k)
    input[k] += (k % 3 == 0 ? 0.3 : (k % 3 == 1 ? -0.3 : 0.1));
  const auto found = cycles(input, 1.5);
  ASSERT_EQ(found.size(), 2U);
  EXPECT_NEAR(static_cast<double>(found[0].last), 40.0, 1.0);
  EXPECT_EQ(found[1].last, input.size() - 1);
}

TEST(Cycles, OnePeriodStoppingShortOfItsStartClosesAtTheRecordEnd) {
  // Starts at 2 rising, ends at 0 rising: 2 short of the anchor, like a measured period.
  const auto input = through_nodes({2, 10, -10, 0});
  const auto within = cycles(input, 2.5);
  ASSERT_EQ(within.size(), 1U);
  EXPECT_EQ(within[0].first, 0U);
  EXPECT_EQ(within[0].last, input.size() - 1);
  EXPECT_TRUE(within[0].ends_at_record_end);
  EXPECT_TRUE(cycles(input, 1.5).empty());  // 2 away is more than the band
}

TEST(Cycles, MinorLoopBelongsToItsCycle) {
  // After the minimum -10 the input turns at -2 and -6 before it reaches the anchor 0 again.
  const auto input = through_nodes({0, 10, -10, -2, -6, 5, -1});
  const auto found = cycles(input, 1.5);
  ASSERT_EQ(found.size(), 1U);
  // Samples: 0..10 up, ..30 down, ..38 up to -2, ..42 down to -6, then 0 at 48.
  EXPECT_EQ(found[0].last, 48U);
  EXPECT_EQ(input[48], 0.0);
}

TEST(Cycles, NoneWithoutAFullPeriod) {
  EXPECT_TRUE(cycles(through_nodes({0, 10, -10}), 1.5).empty());
  EXPECT_TRUE(cycles(through_nodes({0, 10}), 1.5).empty());
}

}  // namespace
}  // namespace hyst::data
