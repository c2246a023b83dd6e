#include "hyst/identify/fit_report.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/identify/data_split.hpp"

namespace hyst {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ErrorMetrics, HandCalculated) {
  // errors e = (0, 1, -2, 1): sum e^2 = 6, RMSE = sqrt(6/4), range of measured = 4 - 0 = 4,
  // NRMSE = 100 % * RMSE / range.
  const std::vector<double> measured{0, 1, 4, 2};
  const std::vector<double> predicted{0, 0, 6, 1};
  const ErrorMetrics metrics = error_metrics(measured, predicted);
  EXPECT_EQ(metrics.samples, 4u);
  EXPECT_DOUBLE_EQ(metrics.rmse, std::sqrt(1.5));
  EXPECT_DOUBLE_EQ(metrics.nrmse_percent, 100.0 * std::sqrt(1.5) / 4.0);  // in %
  EXPECT_EQ(metrics.max_error, 2.0);
}

TEST(ErrorMetrics, PerfectPredictionIsZero) {
  const std::vector<double> measured{-1, 3, 2};
  const ErrorMetrics metrics = error_metrics(measured, measured);
  EXPECT_EQ(metrics.rmse, 0.0);
  EXPECT_EQ(metrics.nrmse_percent, 0.0);
  EXPECT_EQ(metrics.max_error, 0.0);
}

TEST(ErrorMetrics, RejectsInvalidInput) {
  const std::vector<double> three{1, 2, 3};
  EXPECT_HYST_ERROR(error_metrics(three, std::vector<double>{1, 2}),
                    "measured has 3 values but predicted has 2");
  EXPECT_HYST_ERROR(error_metrics(std::vector<double>{}, std::vector<double>{}),
                    "measured is empty");
  EXPECT_HYST_ERROR(error_metrics(std::vector<double>{1, NAN, 3}, three),
                    "measured[1] = nan is not finite");
  EXPECT_HYST_ERROR(error_metrics(three, std::vector<double>{1, 2, INFINITY}),
                    "predicted[2] = inf is not finite");
  EXPECT_HYST_ERROR(error_metrics(std::vector<double>{2, 2, 2}, three),
                    "measured is constant (every one of its 3 samples = 2)");
}

TEST(Termination, ConvertsToAndFromText) {
  for (const Termination t : {Termination::converged, Termination::max_iterations,
                              Termination::no_progress, Termination::failed}) {
    EXPECT_EQ(termination_from_string(to_string(t)), t);
  }
  EXPECT_EQ(to_string(Termination::max_iterations), "max_iterations");
  EXPECT_HYST_ERROR(termination_from_string("done"),
                    "unknown termination 'done' (expected converged, max_iterations, "
                    "no_progress or failed)");
  EXPECT_HYST_ERROR(termination_from_string("Converged"), "unknown termination 'Converged'");
}

FitReport example_report() {
  FitReport report;
  report.model = "pi";
  report.method = "nnls (Lawson-Hanson)";
  report.termination = Termination::converged;
  report.message = "KKT conditions hold";
  report.iterations = 17;
  report.initial_cost = 123456.0;
  report.final_cost = 789.5;
  report.parameters = 11;
  report.fit = {401, 12.25, 1.25, 40.5};  // NRMSE in %
  report.seconds = 0.00125;
  return report;
}

TEST(FitReport, BriefHasTheFigures) {
  FitReport report = example_report();
  std::string brief = report.brief();
  for (const std::string part :
       {"pi fitted by nnls (Lawson-Hanson)", "converged after 17 iterations", "0.00125 s",
        "KKT conditions hold", "123456 -> 789.5", "11 parameters",
        "Fit: RMSE 12.25, NRMSE 1.25 %, max error 40.5 on 401 samples."}) {
    EXPECT_TRUE(contains(brief, part)) << "missing \"" << part << "\" in\n" << brief;
  }
  EXPECT_FALSE(contains(brief, "Validation"));
  EXPECT_EQ(brief.find('\n'), std::string::npos) << "one paragraph";

  report.validation = ErrorMetrics{1604, 20.5, 2.0, 75.25};
  brief = report.brief();
  EXPECT_TRUE(contains(brief, "Validation: RMSE 20.5, NRMSE 2 %, max error 75.25 on 1604 samples."))
      << brief;
}

TEST(FitReport, StatusAndYardstickAreStated) {
  FitReport report = example_report();
  report.validation = ErrorMetrics{1604, 20.5, 2.0, 75.25};
  report.quality = FitQuality::degenerate;
  report.quality_note = "the held-out prediction is nearly constant";
  ReferenceScore held{"last value held", ErrorMetrics{1604, 10.0, 1.5, 30.0}, "", {}};
  ReferenceScore mean{"mean", ErrorMetrics{1604, 50.0, 9.0, 90.0}, "", {}};
  report.references = {mean, held};
  const auto brief = report.brief();
  EXPECT_TRUE(contains(brief,
                       "pi fitted by nnls (Lawson-Hanson): degenerate (the method: "
                       "converged; the held-out prediction is nearly constant) after 17"))
      << brief;
  EXPECT_FALSE(contains(brief, ": converged after")) << brief;
  // 2 % against the held value's 1.5 %: the model does not beat the yardstick.
  EXPECT_EQ(report.beats_yardstick(), false);
  EXPECT_TRUE(contains(brief,
                       "the best reference predictor on the held-out part is 'last value "
                       "held' with NRMSE 1.5 %; the model does not beat it."))
      << brief;
  const auto full = report.full();
  EXPECT_TRUE(contains(full, "status                    degenerate")) << full;
  EXPECT_TRUE(contains(full, "mean")) << full;
  report.references = {mean};
  EXPECT_EQ(report.beats_yardstick(), true);
  report.validation.reset();
  EXPECT_EQ(report.beats_yardstick(), std::nullopt);
}

TEST(FitReport, FullHasEveryField) {
  FitReport report = example_report();
  report.termination = Termination::max_iterations;
  std::string full = report.full();
  for (const std::string part : {"model",        "pi",
                                 "method",       "nnls (Lawson-Hanson)",
                                 "termination",  "max_iterations",
                                 "status",       "iteration limit",
                                 "message",      "KKT conditions hold",
                                 "iterations",   "17",
                                 "parameters",   "11",
                                 "initial cost", "123456",
                                 "final cost",   "789.5",
                                 "time [s]",     "0.00125",
                                 "NRMSE [%]",    "401",
                                 "12.25",        "1.25",
                                 "40.5"}) {
    EXPECT_TRUE(contains(full, part)) << "missing \"" << part << "\" in\n" << full;
  }
  EXPECT_TRUE(contains(full, "validation")) << full;
  EXPECT_TRUE(contains(full, "none")) << full;

  report.validation = ErrorMetrics{1604, 20.5, 2.0, 75.25};
  full = report.full();
  for (const std::string part : {"1604", "20.5", "75.25"}) {
    EXPECT_TRUE(contains(full, part)) << "missing \"" << part << "\" in\n" << full;
  }
  EXPECT_FALSE(contains(full, "none")) << full;
}

TEST(DataSplit, LastFractionIsValidation) {
  const DataSplit split = split_by_fraction(100, 0.25);
  EXPECT_EQ(split.fit_begin, 0u);
  EXPECT_EQ(split.fit_end, 75u);
  EXPECT_EQ(split.validation_begin, 75u);
  EXPECT_EQ(split.validation_end, 100u);
  EXPECT_EQ(split.fit_size(), 75u);
  EXPECT_EQ(split.validation_size(), 25u);
  EXPECT_TRUE(split.has_validation());

  // Rounded to the nearest sample: 0.25 * 401 = 100.25 -> 100, 0.3 * 5 = 1.5 -> 2.
  EXPECT_EQ(split_by_fraction(401, 0.25).validation_size(), 100u);
  EXPECT_EQ(split_by_fraction(5, 0.3).validation_size(), 2u);
  EXPECT_EQ(split_by_fraction(2, 0.5).fit_size(), 1u);
}

TEST(DataSplit, ZeroFractionMeansNoValidation) {
  const DataSplit split = split_by_fraction(10, 0.0);
  EXPECT_EQ(split.fit_begin, 0u);
  EXPECT_EQ(split.fit_end, 10u);
  EXPECT_EQ(split.validation_begin, 10u);
  EXPECT_EQ(split.validation_end, 10u);
  EXPECT_FALSE(split.has_validation());
  EXPECT_EQ(split_by_fraction(1, 0.0).fit_size(), 1u);
}

TEST(DataSplit, RejectsInvalidFractions) {
  EXPECT_HYST_ERROR(split_by_fraction(10, 1.0), "validate_fraction = 1 must be in [0, 1)");
  EXPECT_HYST_ERROR(split_by_fraction(10, -0.1), "validate_fraction = -0.1 must be in [0, 1)");
  EXPECT_HYST_ERROR(split_by_fraction(10, std::numeric_limits<double>::quiet_NaN()),
                    "validate_fraction = nan must be in [0, 1)");
  EXPECT_HYST_ERROR(split_by_fraction(0, 0.2), "cannot split a record of 0 samples");
  EXPECT_HYST_ERROR(split_by_fraction(10, 0.01),
                    "validate_fraction = 0.01 of 10 samples leaves the validation part empty");
  EXPECT_HYST_ERROR(split_by_fraction(10, 0.97),
                    "validate_fraction = 0.97 of 10 samples leaves the fit part empty");
}

}  // namespace
TEST(FitReport, PreprocessingStepsAreListed) {
  FitReport report = example_report();
  EXPECT_FALSE(contains(report.brief(), "Preprocessing"));
  EXPECT_TRUE(contains(report.full(), "the record as measured"));
  report.preprocessing = {"cycles 2-3 of 4 kept (samples 401..1203)",
                          "resampled per branch on an input grid of step 20 (803 -> 321 samples)"};
  EXPECT_TRUE(contains(report.brief(),
                       " Preprocessing: cycles 2-3 of 4 kept (samples 401..1203); resampled per "
                       "branch on an input grid of step 20 (803 -> 321 samples)."))
      << report.brief();
  const auto full = report.full();
  EXPECT_TRUE(contains(full, "preprocessing")) << full;
  EXPECT_TRUE(contains(full, "(803 -> 321 samples)")) << full;
}

}  // namespace hyst
