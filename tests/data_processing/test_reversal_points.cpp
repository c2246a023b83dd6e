// Reversal points: exact on clean signals (hand-counted indices), noise, glitches and plateaus
// below the band ignored, wiping-out of the Preisach memory, and the same reversals on measured
// data with seeded noise added.

#include "hyst/data/reversal_points.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/io/aixacct.hpp"
#include "synthetic_records.hpp"

namespace hyst::data {
namespace {

using test::through_nodes;
using test::triangle;

TEST(ReversalPoints, CleanTriangleGivesEveryPeakAtItsSample) {
  const auto input = triangle(10, 3);  // 121 samples
  const auto points = reversal_points(input, 1.5);
  ASSERT_EQ(points.size(), 6U);  // 3 maxima, 3 minima; the last sample (0, rising) is none
  for (std::size_t j = 0; j < points.size(); ++j) {
    EXPECT_EQ(points[j].index, 10 + 20 * j);
    EXPECT_EQ(points[j].kind, j % 2 == 0 ? Extremum::maximum : Extremum::minimum);
    EXPECT_EQ(points[j].value, j % 2 == 0 ? 10.0 : -10.0);
  }
}

TEST(ReversalPoints, PlateausRippleAndDipsBelowTheBandAreIgnored) {
  // Rises to a rippled plateau (peak 3.2 at index 6), falls to a noisy floor (min -1.1 at 15),
  // rises again. Every wiggle is <= 0.3, the band 0.5.
  const std::vector<double> input{0, 1, 2, 3,  3,  3,    3.2, 3, 2.9, 3.1,
                                  2, 1, 0, -1, -1, -1.1, -1,  0, 1,   2};
  const auto points = reversal_points(input, 0.5);
  ASSERT_EQ(points.size(), 2U);
  EXPECT_EQ(points[0].index, 6U);
  EXPECT_EQ(points[0].kind, Extremum::maximum);
  EXPECT_EQ(points[1].index, 15U);
  EXPECT_EQ(points[1].value, -1.1);
  // The derivative changes sign 7 times here; only 2 are reversals.
}

TEST(ReversalPoints, FlatTopReportsItsFirstSample) {
  const std::vector<double> input{0, 1, 2, 2, 2, 2, 1, 0};
  const auto points = reversal_points(input, 0.5);
  ASSERT_EQ(points.size(), 1U);
  EXPECT_EQ(points[0].index, 2U);
}

TEST(ReversalPoints, GlitchCountsOnlyWhenLargerThanTheBand) {
  auto input = through_nodes({0, 20});
  input[10] = 8.6;  // dips 0.4 below the sample before it (9), then the ramp goes on: 11, 12
  EXPECT_TRUE(reversal_points(input, 0.5).empty());
  input[10] = 8.4;  // falls 0.6 below the maximum 9 at sample 9, then rises again
  const auto points = reversal_points(input, 0.5);
  ASSERT_EQ(points.size(), 2U);
  EXPECT_EQ(points[0].index, 9U);
  EXPECT_EQ(points[1].index, 10U);
  EXPECT_TRUE(reversal_points(input, 0.7).empty());
}

TEST(ReversalPoints, StartAndEndAreNotReversals) {
  // Starts falling within the band, then rises; the running minimum at the start is no reversal.
  const std::vector<double> input{0, -0.2, -0.1, 1, 2, 3};
  EXPECT_TRUE(reversal_points(input, 0.5).empty());
}

TEST(ReversalPoints, RejectsInvalidInput) {
  const std::vector<double> input{0, 1, 0};
  EXPECT_HYST_ERROR(reversal_points(input, 0.0), "hysteresis band = 0 must be finite and > 0");
  EXPECT_HYST_ERROR(reversal_points(input, -1.0), "hysteresis band = -1");
  EXPECT_HYST_ERROR(reversal_points(input, std::nan("")), "hysteresis band = nan");
  EXPECT_HYST_ERROR(reversal_points(std::vector<double>{1.0}, 0.1), "input has 1 samples");
  const std::vector<double> with_nan{0, 1, std::nan(""), 0};
  EXPECT_HYST_ERROR(reversal_points(with_nan, 0.1), "input[2] = nan");
}

TEST(PreisachMemory, WipingOutDeletesDominatedPairs) {
  // Verification section 4: history 0.6, -0.2, 0.3, 0.1, 0.6 leaves the memory of 0.6 alone.
  const std::vector<ReversalPoint> history{{0, 0.6, Extremum::maximum},
                                           {1, -0.2, Extremum::minimum},
                                           {2, 0.3, Extremum::maximum},
                                           {3, 0.1, Extremum::minimum},
                                           {4, 0.6, Extremum::maximum}};
  const auto memory = preisach_memory(history);
  ASSERT_EQ(memory.size(), 1U);
  EXPECT_EQ(memory[0].value, 0.6);
  EXPECT_EQ(memory[0].index, 4U);

  // Nested extrema stay; a new minimum -0.8 wipes the minimum -0.5 and the maximum 0.2 after it.
  const std::vector<ReversalPoint> nested{
      {0, 1.0, Extremum::maximum},  {1, -1.0, Extremum::minimum}, {2, 0.5, Extremum::maximum},
      {3, -0.5, Extremum::minimum}, {4, 0.2, Extremum::maximum},  {5, -0.8, Extremum::minimum}};
  const auto reduced = preisach_memory(nested);
  ASSERT_EQ(reduced.size(), 4U);
  EXPECT_EQ(reduced[0].value, 1.0);
  EXPECT_EQ(reduced[1].value, -1.0);
  EXPECT_EQ(reduced[2].value, 0.5);
  EXPECT_EQ(reduced[3].value, -0.8);
}

TEST(PreisachMemory, RejectsASequenceThatDoesNotAlternate) {
  const std::vector<ReversalPoint> twice{{0, 1.0, Extremum::maximum}, {1, 2.0, Extremum::maximum}};
  EXPECT_HYST_ERROR(preisach_memory(twice), "both maximum");
}

TEST(DefaultBand, IsAFractionOfTheRange) {
  const std::vector<double> input{-1, 3, 0};
  EXPECT_DOUBLE_EQ(default_band(input), 0.08);
  EXPECT_DOUBLE_EQ(default_band(input, 0.25), 1.0);
  EXPECT_HYST_ERROR(default_band(input, 1.0), "band fraction = 1");
  EXPECT_HYST_ERROR(default_band(std::vector<double>{2, 2}), "input is constant");
}

// Four periods of the measured 800 V triangle (aixACCT tables 7-10, one period each), joined.
std::vector<double> measured_voltage() {
  const auto file =
      io::read_aixacct(HYST_SHARED_DATA_DIR "/piezo_pzt_aixacct_butterfly/RMN_TRAP_SLOW.dat");
  std::vector<double> voltage;
  for (std::size_t table = 7; table <= 10; ++table) {
    const auto& column = file.measurement(table).column("V+").values;
    voltage.insert(voltage.end(), column.begin(), column.end());
  }
  return voltage;
}

TEST(ReversalPoints, MeasuredDataWithNoiseGivesTheSameReversals) {
  const auto clean = measured_voltage();
  const double band = default_band(clean, 0.05);  // 5 % of 1594 V = 80 V
  const auto expected = reversal_points(clean, band);
  // One maximum and one minimum per period.
  ASSERT_EQ(expected.size(), 8U);

  // Noise uniform in [-4, 4] V: the triangle moves about 8 V per sample near its peaks, so a noisy
  // sample 3 or more steps from the peak cannot win; the found value is within 4 V of the peak.
  constexpr double kNoise = 4.0;
  for (const std::uint64_t seed : {1U, 2U, 3U, 42U}) {
    SCOPED_TRACE(seed);
    std::mt19937_64 generator(seed);
    std::uniform_real_distribution<double> noise(-kNoise, kNoise);
    auto noisy = clean;
    for (auto& v : noisy)
      v += noise(generator);
    const auto found = reversal_points(noisy, band);
    ASSERT_EQ(found.size(), expected.size());
    for (std::size_t j = 0; j < found.size(); ++j) {
      EXPECT_EQ(found[j].kind, expected[j].kind);
      EXPECT_LE(
          std::abs(static_cast<double>(found[j].index) - static_cast<double>(expected[j].index)),
          2.0);
      EXPECT_LE(std::abs(found[j].value - expected[j].value), kNoise);
    }
    // The Preisach memory starts with the dominant extreme, within the noise of the clean one
    // (the four periods peak within 0.3 V of each other, so which later peaks survive the
    // wiping-out depends on the noise).
    const auto memory = preisach_memory(found);
    const auto expected_memory = preisach_memory(expected);
    EXPECT_EQ(memory.front().kind, expected_memory.front().kind);
    EXPECT_LE(std::abs(memory.front().value - expected_memory.front().value), kNoise);
  }
}

}  // namespace
}  // namespace hyst::data
