// record_info(): what 'hyst data info' and hyst.data.info() report about a data file, on a CSV
// file with exactly known figures and on the aixACCT export against the instrument's metadata.

#include "hyst/data/record_info.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/temp_folder_test.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/io/csv.hpp"
#include "synthetic_records.hpp"

namespace hyst::data {
namespace {

class RecordInfoTest : public test::TempFolderTest {
 protected:
  // v: triangle of peak 10, two periods (81 samples); y = 2 v; c: constant.
  std::filesystem::path write_triangle() {
    io::Table table;
    const auto v = test::triangle(10, 2);
    std::vector<double> y, c(v.size(), 3.0);
    for (const double value : v)
      y.push_back(2.0 * value);
    table.add_column("v", v);
    table.add_column("y", y);
    table.add_column("c", c);
    const auto path = dir_ / "t.csv";
    io::write_csv(path, table);
    return path;
  }
};

TEST_F(RecordInfoTest, CsvColumnsWithKnownFigures) {
  const auto path = write_triangle();
  RecordInfoOptions options;
  options.band_fraction = 0.1;
  options.loop.emplace("v", "y");
  const auto info = record_info(path, options);
  EXPECT_EQ(info.format, "CSV, 3 columns");
  ASSERT_EQ(info.tables.size(), 1U);
  const auto& table = info.tables.front();
  EXPECT_EQ(table.title, "table");
  EXPECT_EQ(table.rows, 81U);
  ASSERT_EQ(table.columns.size(), 3U);
  const auto& v = table.columns[0];
  EXPECT_EQ(v.samples, 81U);
  EXPECT_EQ(v.min, -10.0);
  EXPECT_EQ(v.max, 10.0);
  EXPECT_EQ(v.reversals, 4U);  // maxima at 10, 50, minima at 30, 70
  EXPECT_EQ(v.cycles, 2U);
  EXPECT_EQ(table.columns[1].max, 20.0);
  EXPECT_FALSE(table.columns[2].reversals);  // constant: no band from its range
  // y = 2 v encloses no area; one loop per period.
  ASSERT_EQ(table.loops.size(), 2U);
  EXPECT_EQ(table.loops[1].first, 40U);
  EXPECT_EQ(table.loops[1].last, 80U);
  EXPECT_EQ(table.loops[0].area, 0.0);

  const auto json = record_info_json(info);
  EXPECT_EQ(json["band_fraction"], 0.1);
  EXPECT_EQ(json["tables"][0]["columns"][0]["reversals"], 4);
  EXPECT_TRUE(json["tables"][0]["columns"][2]["cycles"].is_null());
  EXPECT_EQ(json["tables"][0]["loops"].size(), 2U);
  EXPECT_FALSE(json["tables"][0].contains("metadata"));

  options.loop.emplace("v", "missing");  // no such column: no loop figures, no error
  EXPECT_TRUE(record_info(path, options).tables.front().loops.empty());
}

TEST_F(RecordInfoTest, TimeAxisRatesAndLongestRuns) {
  // The triangle of write_triangle() (steps of 1 per sample, reversals at 10, 30, 50, 70) at
  // 0.5 s per sample: rate 2 per s, longest run 20 samples = 10 s, duration 40 s.
  io::Table table;
  const auto v = test::triangle(10, 2);
  std::vector<double> t;
  for (std::size_t k = 0; k < v.size(); ++k)
    t.push_back(0.5 * static_cast<double>(k));
  table.add_column("t", t);
  table.add_column("v", v);
  io::write_csv(dir_ / "timed.csv", table);
  RecordInfoOptions options;
  options.time = "t";
  const auto info = record_info(dir_ / "timed.csv", options);
  const auto& timed = info.tables.front();
  ASSERT_TRUE(timed.time.has_value());
  EXPECT_EQ(timed.time->column, "t");
  EXPECT_TRUE(timed.time->uniform);
  EXPECT_DOUBLE_EQ(timed.time->sample_time, 0.5);
  EXPECT_DOUBLE_EQ(timed.time->duration, 40.0);
  EXPECT_FALSE(timed.columns[0].largest_rate);  // the time column itself
  ASSERT_TRUE(timed.columns[1].largest_rate);
  EXPECT_DOUBLE_EQ(*timed.columns[1].largest_rate, 2.0);
  EXPECT_DOUBLE_EQ(*timed.columns[1].longest_run, 10.0);
  const auto json = record_info_json(info);
  EXPECT_EQ(json["tables"][0]["time"]["sample_time"], 0.5);
  EXPECT_EQ(json["tables"][0]["columns"][1]["longest_run"], 10.0);
  // Without the option a CSV has no time axis.
  EXPECT_FALSE(record_info(dir_ / "timed.csv", {}).tables.front().time);

  // One step of 1 s among steps of 0.5 s: not uniform; each rate is over its own step.
  for (std::size_t k = 5; k < t.size(); ++k)
    t[k] += 0.5;
  table.columns[0] = t;
  io::write_csv(dir_ / "gap.csv", table);
  const auto gap = record_info(dir_ / "gap.csv", options).tables.front();
  EXPECT_FALSE(gap.time->uniform);
  EXPECT_DOUBLE_EQ(gap.time->min_step, 0.5);
  EXPECT_DOUBLE_EQ(gap.time->max_step, 1.0);
  EXPECT_DOUBLE_EQ(*gap.columns[1].largest_rate, 2.0);

  options.time = "time";
  EXPECT_HYST_ERROR(record_info(dir_ / "timed.csv", options),
                    "timed.csv: no table has the time column 'time'");
  options.time = "v";  // not increasing
  EXPECT_HYST_ERROR(record_info(dir_ / "timed.csv", options), "time column 'v'");
}

TEST_F(RecordInfoTest, Errors) {
  const auto path = write_triangle();
  RecordInfoOptions options;
  options.band_fraction = 0.0;
  EXPECT_HYST_ERROR(record_info(path, options), "band fraction 0 must be > 0 and < 1");
  options.band_fraction = 0.02;
  options.table = 2;
  EXPECT_HYST_ERROR(record_info(path, options), "chooses a table of an aixACCT export");
  EXPECT_HYST_ERROR(record_info(dir_ / "none.csv", {}), "none.csv");
}

TEST(RecordInfo, AixacctTableAgainstTheInstrumentsFigures) {
  const std::string file = HYST_SHARED_DATA_DIR "/piezo_pzt_aixacct_butterfly/RMN_TRAP_SLOW.dat";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  RecordInfoOptions options;
  options.table = 6;
  options.loop.emplace("V+ [V]", "P1");
  const auto info = record_info(file, options);
  ASSERT_EQ(info.tables.size(), 1U);
  const auto& table = info.tables.front();
  EXPECT_EQ(table.title, "table 6");
  ASSERT_FALSE(table.metadata.empty());
  EXPECT_EQ(table.metadata.front().first, "SampleName");
  const auto metadata = io::read_aixacct(file).measurement(6);
  const auto& voltage = table.columns[1];
  EXPECT_EQ(voltage.name, "V+");
  EXPECT_NEAR(voltage.max, *metadata.metadata_number("Vmax+ [V]"), 0.005);
  EXPECT_EQ(voltage.reversals, 2U);
  EXPECT_EQ(voltage.cycles, 1U);
  ASSERT_EQ(table.loops.size(), 1U);
  EXPECT_NEAR(table.loops[0].area, *metadata.metadata_number("Wloss [uJ/cm2]"), 0.05);
}

TEST(RecordInfo, ForcFileShowsItsCurves) {
  const std::filesystem::path path =
      HYST_SHARED_DATA_DIR "/pmagpy_forc_micromag_agm/conventional_example.forc";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  const auto info = record_info(path, {});
  EXPECT_TRUE(info.tables.empty());
  ASSERT_TRUE(info.forc.has_value());
  const auto& f = *info.forc;
  // PROVENANCE.md: 120 FORCs (the first a single point), 8514 data rows of which 120 are
  // calibration points, the last FORC 85 points, H_r from +0.118 T down to -0.218 T,
  // HCal = 0.2350512 T in the header, calibration points at about 0.237 T.
  EXPECT_EQ(f.layout, "Series 0015");
  EXPECT_EQ(f.curves, 120U);
  EXPECT_EQ(f.points, 8514U - 120U);
  EXPECT_EQ(f.calibration_points, 120U);
  EXPECT_EQ(f.fewest_points, 1U);
  EXPECT_EQ(f.reversal_max, 0.1182822);
  EXPECT_EQ(f.reversal_min, -0.218002);
  EXPECT_EQ(f.calibration_field, 0.2350512);
  EXPECT_NEAR(f.calibration_field_min, 0.237, 1e-3);
  EXPECT_NEAR(f.calibration_field_max, 0.237, 1e-3);
  EXPECT_NEAR(f.calibration_drift_percent, -1.29, 0.01);
  EXPECT_EQ(f.field_unit, "T");
  EXPECT_EQ(f.moment_unit, "A m\u00b2");
  const auto json = record_info_json(info);
  EXPECT_EQ(json["forc"]["curves"], 120);
  EXPECT_EQ(json["tables"].size(), 0U);
}

TEST_F(RecordInfoTest, LoopCyclesOfAMicromagLoopFileStartAfterTheInitialCurve) {
  // 0 -> 0.5 initial curve (rows 0-2), then 0.5 -> -0.5 -> 0.5 (rows 3-12) and down again (rows
  // 13-17): one cycle of the loop, from row 3 to the 0.5 it returns to (row 12, or row 13, the
  // same field, where the field turns down again). Taken from row 0 instead, the first cycle
  // would start on the initial curve at 0.
  const auto path = dir_ / "virgin.hys";
  std::ofstream(path) << "MicroMag 2900/3900 Data File (Series 0016.002)\n"
                         "Direct moment vs. field; Hysteresis loop\n"
                         "\n"
                         "SCRIPT\n"
                         "Units of measure                Hybrid SI\n"
                         "Initial magnetization?          Yes\n"
                         "\n"
                         "    Field         Moment\n"
                         "0.0,0.0\n0.25,0.5\n0.5,1.0\n\n"
                         "0.5,1.0\n0.25,0.9\n0.0,0.6\n-0.25,-0.5\n-0.5,-1.0\n\n"
                         "-0.5,-1.0\n-0.25,-0.9\n0.0,-0.6\n0.25,0.5\n0.5,1.0\n\n"
                         "0.5,1.0\n0.25,0.9\n0.0,0.6\n-0.25,-0.5\n-0.5,-1.0\n"
                         "\n"
                         "MicroMag 2900/3900 Data File ends\n";
  RecordInfoOptions options;
  options.loop.emplace("Field", "Moment");
  const auto info = record_info(path, options);
  ASSERT_EQ(info.tables.size(), 1U);
  const auto& table = info.tables.front();
  EXPECT_EQ(table.columns[0].unit, "T");
  EXPECT_EQ(table.columns[1].unit, "A m\u00b2");
  ASSERT_EQ(table.loops.size(), 1U);
  EXPECT_EQ(table.loops[0].first, 3U);
  EXPECT_TRUE(table.loops[0].last == 12U || table.loops[0].last == 13U) << table.loops[0].last;
  bool initial_listed = false;
  for (const auto& [key, value] : table.metadata)
    initial_listed = initial_listed || (key == "initial curve" && value.find("rows 0..2") == 0);
  EXPECT_TRUE(initial_listed);
}

}  // namespace
}  // namespace hyst::data
