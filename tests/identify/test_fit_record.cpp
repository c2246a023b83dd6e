// The one record type of the fitters and its checks (hyst/identify/fit_record.hpp).

#include "hyst/identify/fit_record.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"

namespace hyst {
namespace {

TEST(FitRecord, AcceptsWhatTheRulesAllow) {
  const std::vector<double> input{0, 1, 2, 3, 4, 5};
  const std::vector<double> output{0, 1, 2};
  EXPECT_NO_THROW(check_fit_record({input, input}, "records[0]", {.min_samples = 6}));
  EXPECT_NO_THROW(check_fit_record({input, output, 2, 1}, "records[0]",
                                   {.min_samples = 2, .oversampling = true, .skip = true}));
}

TEST(FitRecord, NamesTheRecordAndWhatIsWrong) {
  const std::vector<double> input{0, 1, 2, 3, 4, 5};
  const std::vector<double> output{0, 1, 2};
  const FitRecordRules oscillator{.min_samples = 2, .oversampling = true, .skip = true};
  EXPECT_HYST_ERROR(check_fit_record({input, output}, "FORC 3", {}),
                    "FORC 3 input has 6 values but FORC 3 output has 3");
  EXPECT_HYST_ERROR(check_fit_record({input, output, 3}, "records[1]", oscillator),
                    "records[1] input has 6 values but records[1] output x oversampling 3 has 9");
  EXPECT_HYST_ERROR(check_fit_record({input, output, 0}, "records[1]", oscillator),
                    "records[1]: oversampling must be >= 1");
  EXPECT_HYST_ERROR(check_fit_record({input, output, 2}, "GPI fit record 2", {}),
                    "GPI fit record 2: oversampling = 2: this fit compares every input sample");
  EXPECT_HYST_ERROR(check_fit_record({input, input, 1, 1}, "GPI fit", {}),
                    "GPI fit: skip = 1: this fit compares every sample (0 only)");
  EXPECT_HYST_ERROR(check_fit_record({input, output, 2, 2}, "records[0]", oscillator),
                    "records[0]: 3 output samples after skip = 2 leave fewer than the 2");
  EXPECT_HYST_ERROR(check_fit_record({input, input}, "loops[0]", {.min_samples = 8}),
                    "loops[0]: 6 output samples leave fewer than the 8 this fit needs");
  EXPECT_HYST_ERROR(check_fit_record({{}, {}}, "FORC 0", {}), "FORC 0 input is empty");
  const std::vector<double> gap{0, NAN, 2};
  EXPECT_HYST_ERROR(check_fit_record({input, gap, 2}, "records[0]", oscillator),
                    "records[0] output[1] = nan is not finite");
}

TEST(FitRecord, ViewsRecordsKeptElsewhere) {
  struct Curve {
    std::vector<double> input;
    std::vector<double> output;
  };
  const std::vector<Curve> curves{{{1, 2}, {3, 4}}, {{5}, {6}}};
  const auto records = fit_records_of(curves);
  ASSERT_EQ(records.size(), 2U);
  EXPECT_EQ(records[1].input.data(), curves[1].input.data());
  EXPECT_EQ(records[0].output[1], 4.0);
  EXPECT_EQ(records[0].oversampling, 1U);
  EXPECT_EQ(records[0].skip, 0U);
}

}  // namespace
}  // namespace hyst
