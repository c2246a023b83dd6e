// The looks at a record behind the no-fit verdict, on synthetic records built to show each one.

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/identify/record_diagnosis.hpp"

namespace hyst {
namespace {

constexpr std::size_t kPeriod = 100;

std::vector<double> sine(std::size_t samples, double amplitude = 1.0) {
  std::vector<double> v(samples);
  for (std::size_t k = 0; k < samples; ++k)
    v[k] = amplitude * std::sin(2.0 * std::numbers::pi * static_cast<double>(k) / kPeriod);
  return v;
}

TEST(RecordDiagnosis, PlainLoopRaisesNoFlag) {
  const auto v = sine(400);
  std::vector<double> y(v.size());
  for (std::size_t k = 0; k < v.size(); ++k)  // a monotone loop: output lags the input
    y[k] = std::sin(2.0 * std::numbers::pi * static_cast<double>(k) / kPeriod - 0.3);
  const auto diagnosis = diagnose_record(v, y, {0, 300, 300, 400});
  EXPECT_FALSE(diagnosis.butterfly);
  EXPECT_FALSE(diagnosis.drift);
  EXPECT_FALSE(diagnosis.extrapolation);
  EXPECT_TRUE(diagnosis.findings.empty());
}

TEST(RecordDiagnosis, ButterflyOutputTurnsBackOnEveryBranch) {
  // y = v^2: on every branch from -1 to 1 (and back) the output falls to 0 and rises again.
  const auto v = sine(400);
  std::vector<double> y;
  for (const double x : v)
    y.push_back(x * x);
  const auto diagnosis = diagnose_record(v, y, {0, 300, 300, 400});
  EXPECT_TRUE(diagnosis.butterfly);
  EXPECT_FALSE(diagnosis.extrapolation);
  ASSERT_FALSE(diagnosis.findings.empty());
  EXPECT_NE(diagnosis.findings.front().find("butterfly"), std::string::npos);
}

TEST(RecordDiagnosis, DriftAtTheRepeatedInputValue) {
  // y = v + a ramp of 0.5 over the record: the rising crossings of v = 0 see y go 0 -> ~0.4,
  // 20 % of the output range of about 2.5.
  const auto v = sine(500);
  std::vector<double> y(v.size());
  for (std::size_t k = 0; k < v.size(); ++k)
    y[k] = v[k] + 0.5 * static_cast<double>(k) / static_cast<double>(v.size());
  const auto diagnosis = diagnose_record(v, y, {0, 400, 400, 500});
  EXPECT_TRUE(diagnosis.drift);
  EXPECT_FALSE(diagnosis.butterfly);
  // A ramp of 0.1 (4 % of the range) is below the 10 % threshold.
  for (std::size_t k = 0; k < v.size(); ++k)
    y[k] = v[k] + 0.1 * static_cast<double>(k) / static_cast<double>(v.size());
  EXPECT_FALSE(diagnose_record(v, y, {0, 400, 400, 500}).drift);
}

TEST(RecordDiagnosis, HeldOutInputBeyondTheFittedRange) {
  auto v = sine(400);
  for (std::size_t k = 300; k < 400; ++k)
    v[k] *= 1.5;  // held-out amplitude 1.5, fitted range -1..1
  const auto diagnosis = diagnose_record(v, v, {0, 300, 300, 400});
  EXPECT_TRUE(diagnosis.extrapolation);
  EXPECT_NE(diagnosis.findings.back().find("beyond the fitted input range"), std::string::npos);
  EXPECT_HYST_ERROR(diagnose_record(v, v, {0, 300, 300, 401}), "lies outside the 400 samples");
}

}  // namespace
}  // namespace hyst
