// The domain of a fit part by hand, the samples of another record that leave it, and the domain
// as a model file holds it (info.domain), written by the fit of a model by name.

#include "hyst/identify/fitted_domain.hpp"

#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/registry/fitted_domain_file.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

TEST(FittedDomain, OfAFitPartByHand) {
  // Steps +1 +1 -1 0 -1 -1 +4: rising for 3 samples, then falling (the 0 step keeps the
  // direction) for 5 (indices 2 to 6), then rising again.
  const std::vector<double> input{0, 1, 2, 1, 1, 0, -1, 3};
  const std::vector<double> output{5, 6, 7, 6, 6, 5, 4, 9};
  const auto domain = fitted_domain(input, output, 0.01);
  EXPECT_EQ(domain.input_min, -1.0);
  EXPECT_EQ(domain.input_max, 3.0);
  EXPECT_EQ(domain.output_min, 4.0);
  EXPECT_EQ(domain.output_max, 9.0);
  EXPECT_EQ(domain.samples, 8u);
  EXPECT_EQ(domain.largest_input_step, 4.0);
  EXPECT_EQ(domain.longest_hold_samples, 5u);
  EXPECT_EQ(domain.sample_time, 0.01);
  EXPECT_EQ(fitted_domain(std::vector<double>{2.0}, std::vector<double>{1.0}).longest_hold_samples,
            1u);
  EXPECT_HYST_ERROR(fitted_domain(input, std::vector<double>{1.0}), "input");
}

TEST(FittedDomain, SamplesBeyondFivePercentOfTheWidthLeaveIt) {
  FittedDomain domain;
  domain.input_min = -1.0;  // width 4: a margin of 0.2 on each side
  domain.input_max = 3.0;
  domain.output_min = 0.0;
  domain.output_max = 10.0;
  const std::vector<double> input{3.2, -1.2,  3.3,
                                  0.0, -1.25, std::numeric_limits<double>::quiet_NaN()};
  const auto check = check_inputs(domain, input);
  ASSERT_EQ(check.excursions.size(), 2u);
  EXPECT_EQ(check.excursions[0].samples, 2u);  // -1.25 and NaN
  EXPECT_EQ(check.excursions[0].first, 4u);
  EXPECT_EQ(check.excursions[1].samples, 1u);  // 3.3
  EXPECT_EQ(check.excursions[1].first, 2u);
  EXPECT_EQ(check.message(6),
            "2 of 6 samples: inputs below the fitted range [-1, 3] by more than 5 % of its width "
            "(first at sample 4); 1 of 6 samples: inputs above the fitted range [-1, 3] by more "
            "than 5 % of its width (first at sample 2)");
  EXPECT_TRUE(check_inputs(domain, std::vector<double>{-1.2, 3.2}).inside());
  // Targets are checked against the outputs: 10.6 is beyond 10 + 0.5.
  const auto targets = check_targets(domain, std::vector<double>{10.4, 10.6});
  ASSERT_EQ(targets.excursions.size(), 1u);
  EXPECT_EQ(targets.excursions[0].first, 1u);
}

TEST(FittedDomain, RatesAndHoldsAtTheRecordsSampleTime) {
  // Fitted at 0.01 s: largest step 4 (400 per s), longest hold 5 samples (0.05 s), lags up to
  // 0.02 s: holds count beyond max(0.05, 0.02) s plus 5 %.
  const std::vector<double> fit_input{0, 1, 2, 1, 1, 0, -1, 3};
  auto domain = fitted_domain(fit_input, fit_input, 0.01);
  domain.largest_time_constant = 0.02;
  EXPECT_DOUBLE_EQ(*domain.duration(), 0.08);
  EXPECT_DOUBLE_EQ(*domain.largest_input_rate(), 400.0);
  EXPECT_DOUBLE_EQ(*domain.longest_hold(), 0.05);
  // The fit record itself stays inside.
  EXPECT_TRUE(check_timing(domain, fit_input, 0.01).inside());
  // The same steps 10 times faster (0.001 s): rates of up to 4000 per s, above 400 from the
  // first step (1 / 0.001 = 1000 per s at sample 1).
  const auto fast = check_timing(domain, fit_input, 0.001);
  ASSERT_EQ(fast.excursions.size(), 1u);
  EXPECT_EQ(fast.excursions[0].first, 1u);
  EXPECT_EQ(fast.excursions[0].samples, 6u);  // every step but the one of 0
  EXPECT_NE(fast.excursions[0].what.find("input rates above the fitted largest 400 per s"),
            std::string::npos);
  // A ramp of 10 samples at 0.01 s (0.1 s without a reversal, steps of 0.1): from sample 5 on
  // the run has lasted 6 x 0.01 = 0.06 s > 0.05 x 1.05.
  std::vector<double> ramp;
  for (int k = 0; k < 10; ++k)
    ramp.push_back(0.1 * k);
  const auto long_hold = check_timing(domain, ramp, 0.01);
  ASSERT_EQ(long_hold.excursions.size(), 1u);
  EXPECT_EQ(long_hold.excursions[0].first, 5u);
  EXPECT_EQ(long_hold.excursions[0].samples, 5u);
  EXPECT_NE(long_hold.excursions[0].what.find("longer than the longest fitted one (0.05 s)"),
            std::string::npos);
  // Non-uniform steps: the same ramp with steps of 0.005 s lasts 0.05 s in all: inside.
  const std::vector<double> half(10, 0.005);
  EXPECT_TRUE(check_timing(domain, ramp, std::nullopt, half).inside());
  // A rate-independent model's domain (no sample time) is never checked for timing.
  EXPECT_TRUE(check_timing(fitted_domain(fit_input, fit_input), ramp, 1e-9).inside());
  EXPECT_HYST_ERROR(check_timing(domain, ramp, 0.01, std::vector<double>(3, 0.01)), "steps");
}

TEST(FittedDomain, RoundTripsThroughAModelFileAndIsRefusedWhenMalformed) {
  const auto domain = fitted_domain(std::vector<double>{0, 2, 1}, std::vector<double>{1, 3, 2});
  const nlohmann::json document = {{"info", {{"domain", fitted_domain_json(domain)}}}};
  const auto back = fitted_domain_of(document, "m.json");
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->input_max, 2.0);
  EXPECT_EQ(back->longest_hold_samples, 2u);
  EXPECT_FALSE(back->sample_time.has_value());
  EXPECT_FALSE(fitted_domain_of({{"info", nlohmann::json::object()}}, "m.json").has_value());
  EXPECT_HYST_ERROR(fitted_domain_of({{"info", {{"domain", {{"input_min", 1}}}}}}, "m.json"),
                    "m.json: info.domain.input_max");
  auto inverted = fitted_domain_json(domain);
  inverted["input_min"] = 5.0;
  EXPECT_HYST_ERROR(fitted_domain_of({{"info", {{"domain", inverted}}}}, "m.json"),
                    "a minimum above its maximum");
}

TEST(FittedDomain, TheFitOfAModelByNameRecordsItsFitPart) {
  std::vector<double> input, output;
  for (int k = 0; k < 200; ++k) {
    input.push_back(k < 100 ? std::sin(0.1 * k) : 3.0 * std::sin(0.1 * k));
    output.push_back(0.5 * input.back());
  }
  FitRequest request;
  request.input = input;
  request.output = output;
  request.validate_fraction = 0.5;  // the fit part is the first half, of amplitude 1
  const auto outcome = fit_model(ModelRegistry::builtin().find("pi"), request);
  ASSERT_TRUE(outcome.report.domain.has_value());
  EXPECT_EQ(outcome.report.domain->samples, 100u);
  EXPECT_LE(outcome.report.domain->input_max, 1.0);
  EXPECT_GT(outcome.report.domain->input_max, 0.99);
  EXPECT_NE(outcome.report.full().find("fitted domain"), std::string::npos);
}

TEST(FittedDomain, OfSeveralRecordsAtTheirOwnSampleTimes) {
  // Record a: 10 samples at 0.01 s, steps of 1 (100 per s), one rising run of 10 samples (0.1 s).
  // Record b: 5 samples at 0.1 s, steps of 2 (20 per s), rising for 5 samples (0.5 s).
  FittedDomain a, b;
  a.input_min = -1, a.input_max = 8, a.output_min = 0, a.output_max = 2, a.samples = 10;
  a.largest_input_step = 1, a.longest_hold_samples = 10, a.sample_time = 0.01;
  b.input_min = 0, b.input_max = 9, b.output_min = -3, b.output_max = 1, b.samples = 5;
  b.largest_input_step = 2, b.longest_hold_samples = 5, b.sample_time = 0.1;
  b.largest_time_constant = 4.0;
  const std::vector<FittedDomain> parts{a, b};
  const auto merged = merged_domain(parts);
  EXPECT_EQ(merged.input_min, -1.0);
  EXPECT_EQ(merged.input_max, 9.0);
  EXPECT_EQ(merged.output_min, -3.0);
  EXPECT_EQ(merged.output_max, 2.0);
  ASSERT_TRUE(merged.sample_time.has_value());
  EXPECT_EQ(*merged.sample_time, 0.01);
  EXPECT_NEAR(*merged.largest_input_rate(), 100.0, 1e-9);  // a's, the faster
  EXPECT_NEAR(*merged.longest_hold(), 0.5, 1e-9);          // b's, the longer
  EXPECT_NEAR(*merged.duration(), 0.1 + 0.5, 1e-9);
  EXPECT_EQ(merged.largest_time_constant, 4.0);

  // Without a sample time in one of them: per sample, no time.
  b.sample_time.reset();
  const std::vector<FittedDomain> untimed{a, b};
  const auto per_sample = merged_domain(untimed);
  EXPECT_FALSE(per_sample.sample_time.has_value());
  EXPECT_EQ(per_sample.samples, 15u);
  EXPECT_EQ(per_sample.largest_input_step, 2.0);
  EXPECT_EQ(per_sample.longest_hold_samples, 10u);
  EXPECT_HYST_ERROR(merged_domain(std::span<const FittedDomain>{}), "no fit record");
}

TEST(FittedDomain, ModelsWithTheSameExcursionsAreNamedTogether) {
  FittedDomain domain;
  domain.input_min = 0.0;
  domain.input_max = 1.0;
  const std::vector<double> record{0.5, 2.0, 0.5, 3.0};
  const auto outside = check_inputs(domain, record);
  const std::vector<std::pair<std::string, DomainCheck>> checks{
      {"pi", outside}, {"kp", DomainCheck{}}, {"preisach", outside}};
  const auto text = models_domain_message(checks, record.size());
  EXPECT_EQ(text.rfind("pi, preisach: 2 of 4 samples: inputs above", 0), 0u) << text;
  EXPECT_EQ(text.find("kp"), std::string::npos) << text;
  EXPECT_EQ(models_domain_message(
                std::vector<std::pair<std::string, DomainCheck>>{{"kp", DomainCheck{}}}, 4),
            "");
}

TEST(FittedDomain, AFitOfSeveralRecordsRecordsTheirDomainAtEachSampleTime) {
  // Two ramps with holds, one sampled at 10 ms (0..1 V) and one at 50 ms (-2..0.5 V).
  std::vector<double> fast_input, fast_output, slow_input, slow_output;
  for (int k = 0; k < 300; ++k) {
    fast_input.push_back(std::min(1.0, 0.02 * k));
    fast_output.push_back(0.8 * fast_input.back());
  }
  for (int k = 0; k < 120; ++k) {
    slow_input.push_back(std::max(-2.0, -0.05 * k) + (k >= 100 ? 0.125 * (k - 99) : 0.0));
    slow_output.push_back(0.8 * slow_input.back());
  }
  const std::vector<FitRecord> records{{fast_input, fast_output}, {slow_input, slow_output}};
  const std::vector<double> sample_times{0.01, 0.05};
  const auto& entry = ModelRegistry::builtin().find("pi_creep");
  ASSERT_TRUE(entry.can_fit_records());
  const auto outcome =
      entry.fit_records(records, sample_times, {{"time_constants", {0.1, 1.0}}, {"operators", 4}});
  ASSERT_TRUE(outcome.report.domain.has_value());
  const auto& domain = *outcome.report.domain;
  EXPECT_NEAR(domain.input_min, -2.0, 1e-12);
  EXPECT_NEAR(domain.input_max, 1.0, 1e-12);
  EXPECT_NEAR(domain.output_min, -1.6, 1e-12);
  ASSERT_TRUE(domain.sample_time.has_value());
  EXPECT_EQ(*domain.sample_time, 0.01);
  EXPECT_NEAR(*domain.duration(), 300 * 0.01 + 120 * 0.05, 1e-9);
  // Fastest: the slow record's rise by 0.125 per 50 ms = 2.5 per s (the fast one's 2 per s).
  EXPECT_NEAR(*domain.largest_input_rate(), 2.5, 1e-9);
  // Longest run without reversal: the fast record's, rising then held, 300 samples = 3 s; the
  // slow one falls for 100 samples (5 s) before it turns.
  EXPECT_NEAR(*domain.longest_hold(), 5.0, 1e-9);
  EXPECT_EQ(domain.largest_time_constant, 1.0);
}

}  // namespace
}  // namespace hyst
