#include "hyst/operators/dead_zone.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"

namespace hyst {
namespace {

TEST(DeadZone, PositiveThresholdPassesOnlyWhatExceedsIt) {
  const DeadZone s(0.5);
  EXPECT_EQ(s(0.2), 0.0);
  EXPECT_EQ(s(-3.0), 0.0);
  EXPECT_EQ(s(0.5), 0.0);
  EXPECT_DOUBLE_EQ(s(1.25), 0.75);
}

TEST(DeadZone, NegativeThresholdPassesOnlyWhatIsBelowIt) {
  const DeadZone s(-0.5);
  EXPECT_EQ(s(0.2), 0.0);
  EXPECT_EQ(s(3.0), 0.0);
  EXPECT_DOUBLE_EQ(s(-1.25), -0.75);
}

TEST(DeadZone, ZeroThresholdIsTheIdentity) {
  const DeadZone s(0.0);
  for (double y : {-2.0, -0.1, 0.0, 0.3, 5.0})
    EXPECT_EQ(s(y), y);
}

TEST(DeadZone, RejectsNonFiniteThreshold) {
  EXPECT_HYST_ERROR(DeadZone(NAN), "dead-zone threshold d = nan is not finite");
}

}  // namespace
}  // namespace hyst
