// fit_model(): the record is prepared before fitting, and a validation record (separate or held
// out) gets the drift removal of the fit record.

#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../data_processing/synthetic_records.hpp"
#include "../support/expect_error.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

// A drift-free, loop-free record y = 2 v: a PI model (its threshold-0 play) reproduces it exactly,
// so any validation error left is drift.
struct Records {
  std::vector<double> input = test::triangle(10, 3);
  std::vector<double> output;
  std::vector<double> drifting;  // output + 0.01 per sample
  Records() {
    for (std::size_t k = 0; k < input.size(); ++k) {
      output.push_back(2.0 * input[k]);
      drifting.push_back(output.back() + 0.01 * static_cast<double>(k));
    }
  }
};

FitOutcome fit_pi(const FitRequest& request) {
  return fit_model(ModelRegistry::builtin().find("pi"), request);
}

TEST(FitModel, SeparateValidationRecordLosesItsDriftToo) {
  const Records records;
  FitRequest request;
  request.input = records.input;
  request.output = records.output;
  request.validation_input = records.input;
  request.validation_output = records.drifting;
  request.options = {{"operators", 4}};

  const auto raw = fit_pi(request);
  ASSERT_TRUE(raw.report.validation);
  // Without preprocessing the validation error is the drift: 0.01 k, k = 0..120.
  EXPECT_NEAR(raw.report.validation->max_error, 1.2, 1e-6);
  EXPECT_TRUE(raw.report.preprocessing.empty());

  request.preprocessing.detrend = true;
  request.preprocessing.cycles = data::cycle_range_from_string("2");
  const auto prepared = fit_pi(request);
  ASSERT_TRUE(prepared.report.validation);
  EXPECT_EQ(prepared.report.fit.samples, 41U);             // cycle 2 only
  EXPECT_EQ(prepared.report.validation->samples, 121U);    // all cycles: fit-only selection
  EXPECT_LT(prepared.report.validation->max_error, 1e-6);  // the drift is gone
  const auto& steps = prepared.report.preprocessing;
  ASSERT_EQ(steps.size(), 3U);
  EXPECT_EQ(steps[0].rfind("fit record: linear drift removed between 4 cycle boundaries", 0), 0U)
      << steps[0];
  EXPECT_EQ(steps[1].rfind("fit record: cycles 2 of 3 kept", 0), 0U) << steps[1];
  EXPECT_EQ(steps[2].rfind("validation record: linear drift removed between 4 cycle boundaries "
                           "(band 0.4; largest closure error 1.2 before)",
                           0),
            0U)
      << steps[2];
}

TEST(FitModel, HeldOutFractionIsPreparedWithTheRecord) {
  const Records records;
  FitRequest request;
  request.input = records.input;
  request.output = records.drifting;
  request.validate_fraction = 0.25;
  request.options = {{"operators", 4}};
  request.preprocessing.detrend = true;
  const auto outcome = fit_pi(request);
  ASSERT_TRUE(outcome.report.validation);
  EXPECT_EQ(outcome.report.validation->samples, 30U);  // round(0.25 * 121)
  EXPECT_LT(outcome.report.validation->max_error, 1e-6);
  ASSERT_EQ(outcome.report.preprocessing.size(), 1U);
  EXPECT_EQ(outcome.report.preprocessing[0].rfind(
                "fit and held-out validation part: linear drift removed", 0),
            0U)
      << outcome.report.preprocessing[0];
}

// Several records through the registry: y = 2 v at two sample times is fitted by the PI with
// creep exactly (creep weights 0), its sample times reach the fit, and a model without a sample
// time or without such a fit says so.
TEST(FitRecords, CreepModelAtEachRecordsSampleTime) {
  const Records data;
  const std::vector<FitRecord> records{{data.input, data.output}, {data.input, data.output}};
  const std::vector<double> sample_times{0.01, 0.1};
  const auto& entry = ModelRegistry::builtin().find("pi_creep");
  ASSERT_TRUE(entry.can_fit_records());
  const auto outcome = entry.fit_records(records, sample_times, {{"operators", 2}, {"lags", 2}});
  EXPECT_EQ(outcome.report.model, "pi_creep");
  EXPECT_EQ(outcome.report.fit.samples, 2 * data.input.size());
  EXPECT_LT(outcome.report.fit.nrmse_percent, 1e-6);
  EXPECT_DOUBLE_EQ(outcome.model->params().at("sample_time").get<double>(), 0.01);
  // Time constants from 10 Ts (the shortest) to the longest record's duration.
  EXPECT_DOUBLE_EQ(outcome.model->params().at("time_constants")[0].get<double>(), 0.1);

  EXPECT_FALSE(ModelRegistry::builtin().find("pi").can_fit_records());
  const auto& butterfly = ModelRegistry::builtin().find("butterfly_strain");
  EXPECT_HYST_ERROR(butterfly.fit_records(records, sample_times, nlohmann::json::object()),
                    "model 'butterfly_strain' has no sample time");
}

}  // namespace
}  // namespace hyst
