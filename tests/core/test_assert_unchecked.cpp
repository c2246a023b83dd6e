// HYST_ASSERT in a release build (NDEBUG defined): no check, and the condition is not even
// evaluated, so a hot path costs what it would without it.

#ifndef NDEBUG
#define NDEBUG
#endif

#include <gtest/gtest.h>

#include "hyst/core/assert.hpp"

namespace {

TEST(AssertUnchecked, ConditionIsNotEvaluated) {
  int evaluations = 0;
  HYST_ASSERT(++evaluations < 0, "never checked");
  EXPECT_EQ(evaluations, 0);
}

}  // namespace
