// HYST_ASSERT in a debug build (NDEBUG not defined): a broken precondition stops the program
// with a message naming it. NDEBUG is undefined here whatever the build type, so that the check
// is proven in every configuration; this file includes nothing else of hyst, whose inline
// functions must see the build's own NDEBUG.

#undef NDEBUG

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "hyst/core/assert.hpp"

namespace {

double checked_square_root(double x) {
  HYST_ASSERT(std::isfinite(x) && x >= 0.0, "needs a finite, non-negative x");
  return std::sqrt(x);
}

TEST(AssertChecked, HoldingConditionPasses) {
  EXPECT_EQ(checked_square_root(4.0), 2.0);
}

TEST(AssertCheckedDeathTest, BrokenConditionAbortsNamingIt) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(checked_square_root(std::numeric_limits<double>::quiet_NaN()),
               "hyst precondition failed: needs a finite, non-negative x");
  EXPECT_DEATH(checked_square_root(-1.0), "test_assert_checked.cpp:[0-9]+: ");
}

}  // namespace
