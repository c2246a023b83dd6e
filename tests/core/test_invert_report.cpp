// The report of a batch inversion: counts and first indices of each status, checked on an inverse
// that answers a scripted sequence of statuses.

#include <array>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/core/invert.hpp"

namespace hyst {
namespace {

// Returns the statuses of `script` in turn, with the sample index as the input.
struct ScriptedInverse {
  struct State {
    std::size_t next = 0;
  };
  std::vector<InverseStatus> script;
  InverseSample solve(State& state, double) const {
    const std::size_t k = state.next++;
    return {static_cast<double>(k), script[k]};
  }
};

TEST(InvertReport, CountsAndFirstIndexOfEachStatus) {
  using enum InverseStatus;
  const ScriptedInverse inverse{
      {ok, not_invertible, ok, above_range, not_invertible, below_range, ok}};
  ScriptedInverse::State state;
  const std::vector<double> targets(7, 0.0);
  std::vector<double> inputs(7);
  const auto report = invert(inverse, state, targets, inputs);
  EXPECT_EQ(report.saturated_samples, 4U);
  EXPECT_EQ(report.first_saturated, 1U);
  EXPECT_EQ(report.not_invertible_samples, 2U);
  EXPECT_EQ(report.first_not_invertible, 1U);
  EXPECT_EQ(report.limited_samples, 2U);
  EXPECT_EQ(report.first_limited, 3U);  // not 1: that one was not invertible
  EXPECT_FALSE(report.ok());
  EXPECT_EQ(inputs[6], 6.0);
}

TEST(InvertReport, AllOkAndBadTargets) {
  const ScriptedInverse inverse{{InverseStatus::ok, InverseStatus::ok}};
  ScriptedInverse::State state;
  const std::array<double, 2> targets{1.0, 2.0};
  std::array<double, 2> inputs{};
  EXPECT_TRUE(invert(inverse, state, targets, inputs).ok());
  std::array<double, 1> short_inputs{};
  EXPECT_HYST_ERROR(invert(inverse, state, targets, short_inputs), "targets");
}

}  // namespace
}  // namespace hyst
