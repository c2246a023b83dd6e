// The sample time of a time column: uniform columns (also as printed with 7 digits), and the
// refusal of non-uniform, decreasing, too short or non-finite ones; the aixACCT export's tables.

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/io/aixacct.hpp"

namespace hyst::data {
namespace {

TEST(UniformSampleTime, StepOfAUniformColumnAlsoWhenRoundedTo7Digits) {
  std::vector<double> t(401);
  for (std::size_t k = 0; k < t.size(); ++k)
    t[k] = 8.35 + 0.0025 * static_cast<double>(k);
  EXPECT_NEAR(uniform_sample_time(t, "t"), 0.0025, 1e-15);
  for (double& value : t)
    value = std::stod(fmt::format("{:.6e}", value));  // the export's precision
  EXPECT_NEAR(uniform_sample_time(t, "t"), 0.0025, 1e-9);
}

TEST(UniformSampleTime, RefusesWhatIsNotAUniformGrid) {
  EXPECT_HYST_ERROR(uniform_sample_time(std::vector<double>{0.0, 1.0, 2.0, 3.5, 4.0}, "log.csv"),
                    "log.csv: the sampling is not uniform: time[3] - time[2] = 1.5 s");
  EXPECT_HYST_ERROR(uniform_sample_time(std::vector<double>{0.0, 1.0, 1.0}, "t"),
                    "time[2] = 1 is not after time[1] = 1");
  EXPECT_HYST_ERROR(uniform_sample_time(std::vector<double>{0.0}, "t"), "1 time values");
  EXPECT_HYST_ERROR(
      uniform_sample_time(std::vector<double>{0.0, std::numeric_limits<double>::quiet_NaN()}, "t"),
      "time[1] = nan is not finite");
}

TEST(UniformSampleTime, TheAixacctTablesAtThreeRates) {
  const auto file =
      io::read_aixacct(HYST_SHARED_DATA_DIR "/piezo_pzt_aixacct_butterfly/RMN_TRAP_SLOW.dat");
  // PROVENANCE.md: tables 6, 1 and 2 are one 1400 V triangle period at 1, 0.1 and 0.01 Hz in 400
  // intervals.
  for (const auto& [table, expected] :
       std::vector<std::pair<std::size_t, double>>{{6, 0.0025}, {1, 0.025}, {2, 0.25}}) {
    const auto& time = file.measurement(table).column("Time");
    EXPECT_EQ(time.unit, "s");
    EXPECT_NEAR(uniform_sample_time(time.values, "Time"), expected, 1e-9 * expected);
  }
}

}  // namespace
}  // namespace hyst::data
