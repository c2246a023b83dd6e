// The preparation of records for fitting: option parsing, the order of the steps, their report
// lines and their errors.

#include "hyst/data/preprocessing.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/data/cycles.hpp"
#include "synthetic_records.hpp"

namespace hyst::data {
namespace {

// output = input + 0.01 per sample: no loop, pure drift.
std::vector<double> drifting(const std::vector<double>& input) {
  std::vector<double> output(input.size());
  for (std::size_t k = 0; k < input.size(); ++k)
    output[k] = input[k] + 0.01 * static_cast<double>(k);
  return output;
}

TEST(CycleRange, ParsesAndPrints) {
  EXPECT_EQ(cycle_range_from_string("3").first, 3U);
  EXPECT_EQ(cycle_range_from_string("3").last, 3U);
  const auto range = cycle_range_from_string("2-4");
  EXPECT_EQ(range.first, 2U);
  EXPECT_EQ(range.last, 4U);
  EXPECT_EQ(cycle_range_from_string("2-").last, 0U);
  EXPECT_EQ(to_string(cycle_range_from_string("all")), "all");
  EXPECT_EQ(to_string(range), "2-4");
  EXPECT_EQ(to_string(cycle_range_from_string("2-")), "2-");
  for (const char* bad : {"0", "4-2", "x", "", "1-x", "-3"}) {
    EXPECT_HYST_ERROR(cycle_range_from_string(bad), "expected N, N-M");
  }
  EXPECT_EQ(resample_method_from_string("arc-length"), ResampleMethod::arc_length);
  EXPECT_EQ(to_string(ResampleMethod::input_grid), "input-grid");
  EXPECT_HYST_ERROR(resample_method_from_string("spline"), "unknown resampling method 'spline'");
}

TEST(Preprocess, NothingAskedGivesTheRecordUnchanged) {
  const auto input = test::triangle(10, 2);
  const auto prepared = preprocess(input, input, {});
  EXPECT_EQ(prepared.input, input);
  EXPECT_TRUE(prepared.steps.empty());
}

TEST(Preprocess, DetrendThenCyclesThenResample) {
  const auto input = test::triangle(10, 3);
  const auto output = drifting(input);

  Preprocessing options;
  options.band = 1.5;
  options.detrend = true;
  options.cycles = cycle_range_from_string("2-3");
  const auto kept = preprocess(input, output, options);
  ASSERT_EQ(kept.input.size(), 81U);  // samples 40..120
  ASSERT_EQ(kept.steps.size(), 2U);
  EXPECT_NE(kept.steps[0].find("linear drift removed between 4 cycle boundaries"),
            std::string::npos);
  EXPECT_NE(kept.steps[1].find("cycles 2-3 of 3 kept (samples 40..120)"), std::string::npos);
  for (std::size_t k = 0; k < kept.input.size(); ++k)
    EXPECT_NEAR(kept.output[k], kept.input[k], 1e-12);  // the drift is gone

  options.resample = ResampleMethod::input_grid;
  options.resample_step = 5.0;
  const auto resampled = preprocess(input, output, options);
  ASSERT_EQ(resampled.steps.size(), 3U);
  // 80 input units of travel (0 -> 10 -> -10 -> 10 -> -10 -> 0) in steps of 5: 16 + 1 points.
  EXPECT_EQ(resampled.input.size(), 17U);
  EXPECT_NE(resampled.steps[2].find("(81 -> 17 samples)"), std::string::npos);
}

TEST(Preprocess, DefaultBandAndErrors) {
  const auto input = test::triangle(10, 2);
  Preprocessing options;
  options.cycles = cycle_range_from_string("3");
  EXPECT_HYST_ERROR(preprocess(input, input, options),
                    "cycles 3 requested but the record has 2 complete cycles (band 0.4)");
  options.band = -1.0;
  EXPECT_HYST_ERROR(preprocess(input, input, options), "band = -1");
}

TEST(PrepareValidation, RemovesDriftOnlyAndSaysWhenItCannot) {
  const auto input = test::triangle(10, 3);
  const auto output = drifting(input);

  Preprocessing options;
  EXPECT_EQ(prepare_validation(input, output, options).output, output);  // nothing asked
  options.detrend = true;
  options.cycles = cycle_range_from_string("2");  // for the fit alone
  options.resample = ResampleMethod::input_grid;
  const auto prepared = prepare_validation(input, output, options);
  EXPECT_EQ(prepared.input, input);
  ASSERT_EQ(prepared.steps.size(), 1U);
  // The band is 2 % of this record's range of 20.
  EXPECT_NE(prepared.steps[0].find("linear drift removed between 4 cycle boundaries (band 0.4; "
                                   "largest closure error 1.2 before)"),
            std::string::npos)
      << prepared.steps[0];
  for (std::size_t k = 0; k < input.size(); ++k)
    EXPECT_NEAR(prepared.output[k], input[k], 1e-12);

  // Half a period: no cycle to read the drift at.
  const std::vector<double> half(input.begin(), input.begin() + 21);
  const auto kept = prepare_validation(half, half, options);
  EXPECT_EQ(kept.output, half);
  ASSERT_EQ(kept.steps.size(), 1U);
  EXPECT_EQ(kept.steps[0], "drift not removed: no complete cycle (band 0.2) to measure it on");
  options.band = -1.0;
  EXPECT_HYST_ERROR(prepare_validation(input, output, options), "band = -1");
}

}  // namespace
}  // namespace hyst::data
