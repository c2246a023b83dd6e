// Model comparison: a record simulated from a known model is ranked with that model first; a
// model whose fit fails gets a row with the reason and the others still run; the tables.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/compare.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {
namespace {

const std::vector<double> kThresholds = {0.0, 0.3, 0.7, 1.1};

std::vector<double> pi_output(const std::vector<double>& v) {
  const PrandtlIshlinskii model({.thresholds = kThresholds, .weights = {0.8, 0.5, 0.3, 0.2}});
  auto state = model.initial_state();
  return simulate(model, state, v);
}

const ComparedModel& row_of(const ModelComparison& comparison, const std::string& model) {
  const auto found = std::find_if(comparison.ranking.begin(), comparison.ranking.end(),
                                  [&](const ComparedModel& row) { return row.model == model; });
  EXPECT_NE(found, comparison.ranking.end()) << model;
  return *found;
}

TEST(CompareModels, SaysWhereTheHeldOutPartLeavesTheFittedDomain) {
  // Amplitude 1 in the first three quarters (the fit part), 2 in the held-out quarter: its
  // inputs beyond 1 + 5 % of the width 2 (1.1) are extrapolation for every model.
  std::vector<double> v;
  for (int k = 0; k < 800; ++k)
    v.push_back((k < 600 ? 1.0 : 2.0) * std::sin(2.0 * std::numbers::pi * k / 100.0));
  CompareOptions options;
  options.models = {"pi", "kp"};
  options.fit_options["pi"] = {{"thresholds", kThresholds}};
  options.fit_options["kp"] = {{"levels", 8}};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, pi_output(v), options);
  std::size_t beyond = 0, first = v.size();
  for (std::size_t k = 600; k < v.size(); ++k) {
    if (std::abs(v[k]) > 1.1) {
      ++beyond;
      first = std::min(first, k - 600);
    }
  }
  for (const auto& row : comparison.ranking) {
    SCOPED_TRACE(row.model + ": " + row.error);
    ASSERT_TRUE(row.ok);
    EXPECT_FALSE(row.held_out_domain.inside());
    std::size_t counted = 0;
    for (const auto& excursion : row.held_out_domain.excursions) {
      counted += excursion.samples;
      EXPECT_GE(excursion.first, first);
    }
    EXPECT_EQ(counted, beyond);
  }
  const auto line = held_out_domain_line(comparison);
  // One group: both models leave their domains alike (named in the ranking's order).
  const auto group = comparison.ranking.front().model + ", " + comparison.ranking.back().model;
  EXPECT_NE(line.find(group + ": "), std::string::npos) << line;
  EXPECT_NE(model_comparison_markdown(comparison).find(line), std::string::npos);

  // Same amplitude throughout: inside, no line.
  std::vector<double> steady(v.begin(), v.begin() + 600);
  steady.insert(steady.end(), v.begin(), v.begin() + 200);
  const auto inside = compare_models(steady, pi_output(steady), options);
  for (const auto& row : inside.ranking)
    EXPECT_TRUE(row.held_out_domain.inside()) << row.model;
  EXPECT_EQ(held_out_domain_line(inside), "");
}

TEST(CompareModels, PiRecordRanksPiFirst) {
  const auto v = test::random_walk(1200, 5);
  const auto y = pi_output(v);
  CompareOptions options;
  options.models = {"bouc_wen", "narx", "pi"};
  options.fit_options["pi"] = {{"thresholds", kThresholds}};
  options.fit_options["narx"] = {{"hidden_sizes", {4}}, {"max_iterations", 20}};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, y, options);
  ASSERT_EQ(comparison.ranking.size(), 3u);
  EXPECT_EQ(comparison.split.validation_size(), 300u);
  for (const auto& row : comparison.ranking) {
    SCOPED_TRACE(row.model + ": " + row.error);
    EXPECT_TRUE(row.ok);
    EXPECT_EQ(row.simulated.size(), v.size());
    EXPECT_GT(row.ns_per_sample, 0.0);
    EXPECT_GT(row.parameters, 0u);
  }
  // The generating model with its own thresholds reproduces the record to rounding.
  EXPECT_EQ(comparison.ranking.front().model, "pi");
  EXPECT_LT(comparison.ranking.front().validation.nrmse_percent, 1e-7);
  EXPECT_EQ(comparison.ranking.front().parameters, 5u);  // 4 weights and the offset
  EXPECT_LE(comparison.ranking[1].validation.nrmse_percent,
            comparison.ranking[2].validation.nrmse_percent);
}

TEST(CompareModels, BoucWenRecordRanksBoucWenFirst) {
  const BoucWen model(
      {.a = 1.0, .beta = 0.6, .gamma = 0.3, .n = 1.0, .stiffness = 2.0, .alpha_k = 0.3});
  const auto v = test::random_walk(800, 6);
  auto state = model.initial_state();
  const auto y = simulate(model, state, v);
  CompareOptions options;
  options.models = {"pi", "bouc_wen"};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, y, options);
  ASSERT_EQ(comparison.ranking.size(), 2u);
  EXPECT_EQ(comparison.ranking.front().model, "bouc_wen") << model_comparison_markdown(comparison);
  EXPECT_LT(comparison.ranking.front().validation.nrmse_percent, 0.01);
}

TEST(CompareModels, FailingFitIsReportedAndOthersRun) {
  // 40 samples: enough for the PI weights, too few for the NARX network.
  const auto v = test::random_walk(40, 7);
  const auto y = pi_output(v);
  CompareOptions options;
  options.models = {"narx", "pi"};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, y, options);
  ASSERT_EQ(comparison.ranking.size(), 2u);
  EXPECT_EQ(comparison.ranking[0].model, "pi");
  EXPECT_TRUE(comparison.ranking[0].ok);
  const auto& narx = row_of(comparison, "narx");
  EXPECT_FALSE(narx.ok);
  EXPECT_NE(narx.error.find("too few for"), std::string::npos) << narx.error;

  const auto markdown = model_comparison_markdown(comparison);
  EXPECT_NE(markdown.find("| 1 | pi |"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| - | narx | - |"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("Yardstick (reference predictors"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("failed: NARX fit:"), std::string::npos) << markdown;
  const auto csv = model_comparison_csv(comparison);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3 + 4);  // header, 2 models, 4 references
  EXPECT_NE(csv.find("\n1,pi,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n-,narx,failed,,,,,,,,\"NARX fit:"), std::string::npos) << csv;
}

// Before each model (also one whose fit fails) and once at the end, in the order given.
TEST(CompareModels, ProgressIsToldBeforeEachModelAndAtTheEnd) {
  const auto v = test::random_walk(40, 7);
  const auto y = pi_output(v);
  CompareOptions options;
  options.models = {"narx", "pi"};
  options.timing_seconds = 0.0;
  std::vector<std::tuple<std::string, std::size_t, std::size_t, std::string>> told;
  options.progress = [&](const Progress& progress) {
    told.emplace_back(progress.task, progress.done, progress.total, progress.current);
  };
  compare_models(v, y, options);
  const std::vector<std::tuple<std::string, std::size_t, std::size_t, std::string>> expected{
      {"models", 0, 2, "narx"}, {"models", 1, 2, "pi"}, {"models", 2, 2, ""}};
  EXPECT_EQ(told, expected);
}

TEST(CompareModels, BadDataIsReportedForEveryModel) {
  const auto v = test::random_walk(300, 8);
  auto y = pi_output(v);
  CompareOptions options;
  options.models = {"pi", "narx"};
  options.timing_seconds = 0.0;
  y[10] = NAN;
  auto comparison = compare_models(v, y, options);
  for (const auto& row : comparison.ranking) {
    EXPECT_FALSE(row.ok);
    EXPECT_NE(row.error.find("[10] = nan is not finite"), std::string::npos) << row.error;
  }
  const std::vector<double> constant(300, 0.5);
  comparison = compare_models(constant, pi_output(v), options);
  for (const auto& row : comparison.ranking) {
    EXPECT_FALSE(row.ok);
    EXPECT_NE(row.error.find("constant"), std::string::npos) << row.model << ": " << row.error;
  }
}

TEST(CompareModels, LongHoldAtTheEndIsWonByTheHeldValue) {
  // A PI record whose input stops at sample 600 and holds to the end, while the output creeps
  // towards a level 0.3 higher with a time constant of 50 samples (no rate-independent model has
  // creep). The held-out part (samples 750..999) lies in the hold, where the output has nearly
  // settled: holding the last fitted value is off by at most 0.3 exp(-3) = 0.015, a model that
  // cannot creep by the part of the creep it averaged over in the fit part.
  auto v = test::random_walk(600, 12);
  v.resize(1000, v.back());
  auto y = pi_output(v);
  for (std::size_t k = 600; k < y.size(); ++k)
    y[k] += 0.3 * (1.0 - std::exp(-static_cast<double>(k - 600) / 50.0));
  CompareOptions options;
  options.models = {"pi", "bouc_wen"};
  options.fit_options["pi"] = {{"thresholds", kThresholds}};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, y, options);
  const auto markdown = model_comparison_markdown(comparison);
  SCOPED_TRACE(markdown);
  const auto* yardstick = best_reference(comparison.references);
  ASSERT_NE(yardstick, nullptr);
  EXPECT_EQ(yardstick->name, "last value held");
  for (const auto& row : comparison.ranking) {
    ASSERT_TRUE(row.ok) << row.model << ": " << row.error;
    EXPECT_FALSE(row.beats_yardstick) << row.model;
    EXPECT_GT(row.validation.nrmse_percent, yardstick->validation->nrmse_percent);
  }
  EXPECT_NE(markdown.find("Best reference: last value held"), std::string::npos);
  EXPECT_NE(markdown.find("Models that do not beat it: "), std::string::npos);
  EXPECT_NE(markdown.find("| 1 | " + comparison.ranking.front().model + " | "), std::string::npos);
  const auto csv = model_comparison_csv(comparison);
  EXPECT_NE(csv.find("\nreference,\"reference: last value held\",reference,"), std::string::npos)
      << csv;
  for (const auto& row : comparison.ranking) {
    EXPECT_NE(markdown.find("| " + row.model + " | "), std::string::npos);
    EXPECT_NE(csv.find(row.model + ","), std::string::npos);
  }
}

TEST(CompareModels, ButterflyRecordGetsTheNoFitVerdict) {
  // The output is the square of a sine input: on every branch it falls to 0 and rises again (a
  // butterfly). A model with monotone branches misses half of each branch; the best constant
  // is off by the standard deviation of sin^2, sqrt(3/8 - 1/4) = 35 % of the range 1.
  std::vector<double> v(800);
  std::vector<double> y(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    v[k] = std::sin(2.0 * std::numbers::pi * static_cast<double>(k) / 100.0);
    y[k] = v[k] * v[k];
  }
  CompareOptions options;
  options.models = {"pi", "bouc_wen"};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, y, options);
  const auto markdown = model_comparison_markdown(comparison);
  SCOPED_TRACE(markdown);
  ASSERT_TRUE(comparison.ranking.front().ok);
  EXPECT_GT(comparison.ranking.front().validation.nrmse_percent, 20.0);
  ASSERT_TRUE(comparison.no_fit);
  EXPECT_TRUE(comparison.no_fit->butterfly);
  EXPECT_NE(markdown.find("No model describes this record: the best held-out NRMSE is "),
            std::string::npos);
  EXPECT_NE(markdown.find("above 20 %. Seen: butterfly"), std::string::npos);
  // With a threshold above the best NRMSE there is no verdict.
  options.no_fit_percent = 1000.0;
  const auto lenient = compare_models(v, y, options);
  EXPECT_FALSE(lenient.no_fit);
  EXPECT_EQ(model_comparison_markdown(lenient).find("No model describes"), std::string::npos);
}

TEST(CompareModels, RejectsWhatConcernsEveryModel) {
  const auto v = test::random_walk(100, 9);
  const auto y = pi_output(v);
  CompareOptions options;
  options.models = {"pi", "no_such_model"};
  EXPECT_HYST_ERROR(compare_models(v, y, options), "no_such_model");
  options.models = {"pi", "pi"};
  EXPECT_HYST_ERROR(compare_models(v, y, options), "compare: model 'pi' is listed twice");
  options.models = {"pi"};
  options.fit_options["gpi"] = nlohmann::json::object();
  EXPECT_HYST_ERROR(compare_models(v, y, options),
                    "fit options given for 'gpi', which is not compared");
  options.fit_options.clear();
  options.validate_fraction = 1.0;
  EXPECT_HYST_ERROR(compare_models(v, y, options), "validate_fraction = 1 must be > 0 and < 1");
  options.validate_fraction = 0.25;
  options.no_fit_percent = 0.0;
  EXPECT_HYST_ERROR(compare_models(v, y, options), "no_fit_percent = 0 must be finite and > 0");
  options.no_fit_percent = 20.0;
  const std::vector<double> one = {1.0};
  EXPECT_HYST_ERROR(compare_models(one, one, options), "compare: 1 samples");
  const std::vector<double> shorter(v.begin(), v.begin() + 50);
  EXPECT_HYST_ERROR(compare_models(v, shorter, options), "input");
}

}  // namespace
}  // namespace hyst
