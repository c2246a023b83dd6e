// Cross-record model comparison: models fitted on some records and ranked on others, and
// leave-one-out. The records are simulated by a known Prandtl-Ishlinskii model; fitted with its
// own thresholds, the PI family reproduces any record it did not see exactly, so it ranks first
// with a held-out error at rounding level, while another family does not.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/cross_record_compare.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {
namespace {

const std::vector<double> kPiThresholds = {0.0, 0.3, 0.7, 1.1};

void ramp_to(std::vector<double>& v, double target, std::size_t steps = 40) {
  const double from = v.empty() ? 0.0 : v.back();
  for (std::size_t i = 1; i <= steps; ++i)
    v.push_back(from + (target - from) * static_cast<double>(i) / static_cast<double>(steps));
}

// `periods` periods of a sine of `amplitude` from 0. With `back_to_rest`, a tail of ramps
// -2, +1.1, -0.7, +0.3, 0 follows: by the play-operator rule y = max(v - r, min(v + r, y)) it
// sets every operator of kPiThresholds back to 0 whatever came before (|v| <= 2), so records
// simulated from rest can be joined in any order without a jump in the state.
std::vector<double> sine_record(double amplitude, int periods, bool back_to_rest) {
  std::vector<double> v;
  const int per_period = 200;
  for (int i = 0; i <= periods * per_period; ++i)
    v.push_back(amplitude * std::sin(2.0 * std::numbers::pi * i / per_period));
  if (back_to_rest) {
    for (const double target : {-2.0, 1.1, -0.7, 0.3, 0.0})
      ramp_to(v, target);
  }
  return v;
}

NamedRecord pi_record(const std::string& name, std::vector<double> v) {
  const PrandtlIshlinskii model({.thresholds = kPiThresholds, .weights = {0.8, 0.5, 0.3, 0.2}});
  auto state = model.initial_state();
  auto y = simulate(model, state, v);
  return {name, std::move(v), std::move(y)};
}

// Bouc-Wen is the model that PI must rank above: a short, coarse fit (no global stage, 20
// iterations, 4 RK4 steps per sample) is enough for that and keeps the leave-one-out test (three
// fits) short under the sanitizers.
CrossRecordOptions pi_against_bouc_wen() {
  CrossRecordOptions options;
  options.models = {"bouc_wen", "pi"};
  options.fit_options["pi"] = {{"thresholds", kPiThresholds}};
  options.fit_options["bouc_wen"] = {
      {"global_evaluations", 0}, {"max_iterations", 20}, {"substeps", 4}};
  return options;
}

TEST(CrossRecordCompare, FitOnOneAmplitudeRankOnAnother) {
  const auto large = pi_record("a1.5", sine_record(1.5, 3, false));
  const auto small = pi_record("a0.8", sine_record(0.8, 3, false));
  const auto comparison = compare_across_records({large}, {small}, pi_against_bouc_wen());
  ASSERT_EQ(comparison.ranking.size(), 2u);
  EXPECT_FALSE(comparison.leave_one_out);
  EXPECT_EQ(comparison.fit_records, std::vector<std::string>{"a1.5"});
  EXPECT_EQ(comparison.validate_records, std::vector<std::string>{"a0.8"});
  const auto& best = comparison.ranking.front();
  ASSERT_TRUE(best.ok) << best.error;
  EXPECT_EQ(best.model, "pi") << cross_record_markdown(comparison);
  ASSERT_EQ(best.scores.size(), 1u);
  EXPECT_EQ(best.scores[0].record, "a0.8");
  EXPECT_LT(best.scores[0].metrics.nrmse_percent, 1e-6);
  EXPECT_EQ(best.mean_nrmse_percent, best.scores[0].metrics.nrmse_percent);
  EXPECT_EQ(best.worst_record, "a0.8");
  const auto& other = comparison.ranking[1];
  ASSERT_TRUE(other.ok) << other.error;
  EXPECT_GT(other.mean_nrmse_percent, 0.1);  // another family: no exact prediction
  const auto markdown = cross_record_markdown(comparison);
  EXPECT_NE(markdown.find("Fitted on the records a1.5"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| 1 | pi |"), std::string::npos) << markdown;
  const auto csv = cross_record_csv(comparison);
  EXPECT_EQ(csv.rfind("rank,model,status,mean_nrmse_percent,worst_nrmse_percent,worst_record,"
                      "parameters,fit_seconds,beats_yardstick,\"nrmse_percent:a0.8\",message\n",
                      0),
            0u)
      << csv;
}

TEST(CrossRecordCompare, ProgressCountsModelsNotRecords) {
  const auto large = pi_record("a1.5", sine_record(1.5, 3, false));
  const auto small = pi_record("a0.8", sine_record(0.8, 3, false));
  CrossRecordOptions options;
  options.models = {"pi"};
  options.fit_options["pi"] = {{"thresholds", kPiThresholds}};
  std::vector<std::pair<std::size_t, std::size_t>> told;
  options.progress = [&](const Progress& progress) {
    told.emplace_back(progress.done, progress.total);
  };
  compare_leave_one_out({large, small}, options);
  EXPECT_EQ(told, (std::vector<std::pair<std::size_t, std::size_t>>{{0, 1}, {1, 1}}));
}

TEST(CrossRecordCompare, ContinueStartRunsOnFromTheFitRecord) {
  // The same records, but the held-out record predicted from where the fit record ended: the
  // generator started it from rest, so even the exact PI model is off.
  const auto large = pi_record("a1.5", sine_record(1.5, 3, false));
  const auto small = pi_record("a0.8", sine_record(0.8, 3, false));
  auto options = pi_against_bouc_wen();
  options.models = {"pi"};
  options.fit_options.erase("bouc_wen");
  options.validation.start = ValidationStart::continued;
  const auto comparison = compare_across_records({large}, {small}, options);
  ASSERT_TRUE(comparison.ranking.front().ok);
  // After whole periods of the 1.5 sine the input has risen from -1.5 to 0: the operator of
  // threshold r holds max(-r, r - 1.5), not the rest value 0.
  EXPECT_GT(comparison.ranking.front().mean_nrmse_percent, 1e-3);
  EXPECT_NE(comparison.rule.find("continue"), std::string::npos) << comparison.rule;
}

TEST(CrossRecordCompare, LeaveOneOut) {
  const std::vector<NamedRecord> records = {pi_record("a0.6", sine_record(0.6, 2, true)),
                                            pi_record("a1.0", sine_record(1.0, 2, true)),
                                            pi_record("a1.5", sine_record(1.5, 2, true))};
  // The tail brings the generator back to rest: the last output is the rest output, 0.
  for (const auto& record : records)
    ASSERT_NEAR(record.output.back(), 0.0, 1e-12) << record.name;
  const auto comparison = compare_leave_one_out(records, pi_against_bouc_wen());
  EXPECT_TRUE(comparison.leave_one_out);
  EXPECT_EQ(comparison.validate_records, (std::vector<std::string>{"a0.6", "a1.0", "a1.5"}));
  ASSERT_EQ(comparison.ranking.size(), 2u);
  for (const auto& row : comparison.ranking) {
    ASSERT_TRUE(row.ok) << row.model << ": " << row.error;
    ASSERT_EQ(row.scores.size(), 3u);
    double sum = 0.0;
    double worst = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(row.scores[i].record, records[i].name);
      ASSERT_EQ(row.scores[i].fitted_on.size(), 2u);
      EXPECT_EQ(std::count(row.scores[i].fitted_on.begin(), row.scores[i].fitted_on.end(),
                           records[i].name),
                0);
      sum += row.scores[i].metrics.nrmse_percent;
      worst = std::max(worst, row.scores[i].metrics.nrmse_percent);
    }
    EXPECT_DOUBLE_EQ(row.mean_nrmse_percent, sum / 3.0);
    EXPECT_DOUBLE_EQ(row.worst_nrmse_percent, worst);
  }
  const auto& best = comparison.ranking.front();
  EXPECT_EQ(best.model, "pi") << cross_record_markdown(comparison);
  EXPECT_LT(best.worst_nrmse_percent, 1e-6) << cross_record_markdown(comparison);
  EXPECT_GT(comparison.ranking[1].worst_nrmse_percent, 0.1);
  EXPECT_NE(cross_record_markdown(comparison)
                .find("Leave-one-out over the records a0.6, a1.0, "
                      "a1.5"),
            std::string::npos);
}

TEST(CrossRecordCompare, YardstickOfReferencePredictors) {
  const auto large = pi_record("a1.5", sine_record(1.5, 3, false));
  const auto small = pi_record("a0.8", sine_record(0.8, 3, false));
  auto options = pi_against_bouc_wen();
  options.models = {"pi"};
  options.fit_options.erase("bouc_wen");
  const auto comparison = compare_across_records({large}, {small}, options);
  // Start "rest": the held-out record does not follow the fit record in time, so no ARX.
  ASSERT_EQ(comparison.references.size(), 3u) << cross_record_markdown(comparison);
  EXPECT_EQ(comparison.references[0].name, "mean");
  EXPECT_EQ(comparison.references[1].name, "last value held");
  for (const auto& reference : comparison.references) {
    ASSERT_TRUE(reference.ok) << reference.name << ": " << reference.error;
    ASSERT_EQ(reference.scores.size(), 1u);
    EXPECT_EQ(reference.mean_nrmse_percent, reference.scores[0].metrics.nrmse_percent);
  }
  // The mean predictor by hand: the fit record's mean output held over the held-out record.
  double mean = 0.0;
  for (const double y : large.output)
    mean += y / static_cast<double>(large.output.size());
  double squares = 0.0;
  for (const double y : small.output)
    squares += (y - mean) * (y - mean);
  EXPECT_NEAR(comparison.references[0].scores[0].metrics.rmse,
              std::sqrt(squares / static_cast<double>(small.output.size())), 1e-12);
  const auto& pi = comparison.ranking.front();
  EXPECT_TRUE(pi.beats_yardstick);
  EXPECT_TRUE(comparison.no_fit.empty());
  const auto markdown = cross_record_markdown(comparison);
  EXPECT_NE(markdown.find("Every fitted model beats it."), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| ref | reference: mean |"), std::string::npos) << markdown;
  const auto csv = cross_record_csv(comparison);
  EXPECT_NE(csv.find("\nreference,\"reference: mean\",reference,"), std::string::npos) << csv;
  // Start "continue": the held-out record follows the fit record, and ARX joins the yardstick.
  options.validation.start = ValidationStart::continued;
  const auto continued = compare_across_records({large}, {small}, options);
  ASSERT_EQ(continued.references.size(), 4u);
  EXPECT_EQ(continued.references[3].name, "ARX(2,2)");
}

TEST(CrossRecordCompare, NoFitVerdictNamesWhatTheRecordShows) {
  // Held out: a record whose output is the square of the input (a butterfly) over twice the
  // fitted input range; the PI model fitted on a plain loop cannot describe it.
  const auto plain = pi_record("plain", sine_record(1.0, 2, false));
  NamedRecord butterfly{"butterfly", sine_record(2.0, 2, false), {}};
  for (const double v : butterfly.input)
    butterfly.output.push_back(v * v);
  CrossRecordOptions options;
  options.models = {"pi"};
  const auto comparison = compare_across_records({plain}, {butterfly}, options);
  ASSERT_TRUE(comparison.ranking.front().ok) << comparison.ranking.front().error;
  ASSERT_EQ(comparison.no_fit.size(), 1u) << cross_record_markdown(comparison);
  const auto& verdict = comparison.no_fit.front();
  EXPECT_EQ(verdict.record, "butterfly");
  EXPECT_EQ(verdict.best_model, "pi");
  EXPECT_GT(verdict.best_nrmse_percent, 20.0);
  EXPECT_TRUE(verdict.seen.butterfly);
  EXPECT_TRUE(verdict.seen.extrapolation);
  EXPECT_NE(cross_record_markdown(comparison).find("No model describes the record butterfly"),
            std::string::npos);
  // Above a threshold higher than every error, there is no verdict.
  options.no_fit_percent = 1e6;
  EXPECT_TRUE(compare_across_records({plain}, {butterfly}, options).no_fit.empty());
  options.no_fit_percent = 0.0;
  EXPECT_HYST_ERROR(compare_across_records({plain}, {butterfly}, options), "no_fit_percent");
}

TEST(CrossRecordCompare, BadRecordsAreRejectedBeforeAnyFit) {
  const auto record = pi_record("a", sine_record(1.0, 1, false));
  auto short_output = record;
  short_output.name = "b";
  short_output.output.pop_back();
  EXPECT_HYST_ERROR(compare_across_records({record}, {short_output}), "held-out record 'b'");
  EXPECT_HYST_ERROR(compare_across_records({record}, {record}), "record 'a' is given twice");
  EXPECT_HYST_ERROR(compare_across_records({record}, {}), "no held-out record");
  EXPECT_HYST_ERROR(compare_leave_one_out({record}), "at least 2 records");
  auto other = record;
  other.name = "c";
  auto options = pi_against_bouc_wen();
  options.models = {"no_such_model"};
  EXPECT_HYST_ERROR(compare_across_records({record}, {other}, options), "no_such_model");
}

}  // namespace
}  // namespace hyst
