// The judgement behind the status "degenerate" / "unstable", on hand-made simulations.

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/identify/fit_quality.hpp"
#include "hyst/identify/fit_report.hpp"

namespace hyst {
namespace {

// measured: 0, 1, 0, 1, ... (range 1, mid 0.5, standard deviation 0.5).
std::vector<double> square_wave(std::size_t samples) {
  std::vector<double> values(samples);
  for (std::size_t k = 0; k < samples; ++k)
    values[k] = static_cast<double>(k % 2);
  return values;
}

TEST(FitQuality, FollowingSimulationIsSound) {
  const auto measured = square_wave(20);
  auto simulated = measured;
  for (auto& y : simulated)
    y = 0.9 * y + 0.05;
  const auto verdict = judge_simulation(measured, simulated, 10);
  EXPECT_EQ(verdict.quality, FitQuality::sound);
  EXPECT_TRUE(verdict.reason.empty());
}

TEST(FitQuality, NearlyConstantHeldOutPredictionIsDegenerate) {
  const auto measured = square_wave(20);
  auto simulated = measured;  // follows on the fit part ...
  for (std::size_t k = 10; k < 20; ++k)
    simulated[k] = 0.5 + 0.004 * static_cast<double>(k % 2);  // ... std 0.002 = 0.4 % of 0.5
  const auto verdict = judge_simulation(measured, simulated, 10);
  EXPECT_EQ(verdict.quality, FitQuality::degenerate);
  EXPECT_NE(verdict.reason.find("held-out prediction is nearly constant"), std::string::npos)
      << verdict.reason;
  // 2 % of the measured std is not degenerate.
  for (std::size_t k = 10; k < 20; ++k)
    simulated[k] = 0.5 + 0.02 * static_cast<double>(k % 2);
  EXPECT_EQ(judge_simulation(measured, simulated, 10).quality, FitQuality::sound);
}

TEST(FitQuality, LeavingTheBandOrNotFiniteIsUnstable) {
  const auto measured = square_wave(20);
  auto simulated = measured;
  simulated[7] = 5.4;  // band: mid 0.5 +- 5 ranges = -4.5..5.5
  EXPECT_EQ(judge_simulation(measured, simulated).quality, FitQuality::sound);
  simulated[7] = 5.6;
  const auto verdict = judge_simulation(measured, simulated);
  EXPECT_EQ(verdict.quality, FitQuality::unstable);
  EXPECT_NE(verdict.reason.find("at sample 7"), std::string::npos) << verdict.reason;
  simulated[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(judge_simulation(measured, simulated).quality, FitQuality::unstable);
  EXPECT_HYST_ERROR(judge_simulation(measured, simulated, 20), "judged_begin = 20");
}

TEST(FitQuality, StatusNeverSaysConvergedForADegenerateFit) {
  FitReport report;
  report.termination = Termination::converged;
  EXPECT_EQ(report.status(), "converged");
  report.quality = FitQuality::degenerate;
  EXPECT_EQ(report.status(), "degenerate");
  report.quality = FitQuality::unstable;
  EXPECT_EQ(report.status(), "unstable");
  report.quality = FitQuality::sound;
  report.termination = Termination::max_iterations;
  EXPECT_EQ(report.status(), "iteration limit");
  report.termination = Termination::failed;
  EXPECT_EQ(report.status(), "failed");
}

}  // namespace
}  // namespace hyst
