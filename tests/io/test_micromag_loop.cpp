// The MicroMag hysteresis loop reader: every measured loop of the HystLab example data (counts
// from the files' own headers and PROVENANCE.md, the adjusted moment checked against the slope
// correction the header states), io::DataFile on a loop file, and malformed files.

#include "hyst/io/micromag_loop.hpp"

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/io/data_file.hpp"

namespace hyst::io {
namespace {

namespace fs = std::filesystem;

const fs::path kFolder = HYST_SHARED_DATA_DIR "/hystlab_vsm_hysteresis_loops";

// A small file in the newer layout (series 0016): header, segment table, titles, two segments.
std::string small_loop_file(std::string_view data, std::string_view count = "4",
                            std::string_view segments = "2") {
  return fmt::format(
      "MicroMag 2900/3900 Data File (Series 0016.002)\r\n"
      "Direct moment vs. field; Hysteresis loop\r\n"
      "\r\n"
      "INSTRUMENT\r\n"
      "Configuration                   VSM\r\n"
      "Units of measure                Hybrid SI\r\n"
      "\r\n"
      "SCRIPT\r\n"
      "Field increment                +5.000000E-03\r\n"
      "Number of segments              {}\r\n"
      "Number of data                  {}\r\n"
      "\r\n"
      "Segment   Averaging      Initial\r\n"
      " Number      Time         Field \r\n"
      "0000001,+100.0000E-03,+500.0000E-03\r\n"
      "0000002,+100.0000E-03,-500.0000E-03\r\n"
      "\r\n"
      "                            Adjusted  \r\n"
      "    Field         Moment     Moment   \r\n"
      "     (T)          (Am2)       (Am2)   \r\n"
      "{}"
      "\r\n"
      "MicroMag 2900/3900 Data File ends\r\n",
      segments, count, data);
}

constexpr std::string_view kFourRows =
    "+5.0E-01,+2.0E-06,+1.0E-06\r\n"
    "-5.0E-01,-2.0E-06,-1.0E-06\r\n"
    "\r\n"
    "-5.0E-01,-2.1E-06,-1.1E-06\r\n"
    "+5.0E-01,+2.1E-06,+1.1E-06\r\n";

TEST(MicromagLoop, SmallFileGivesColumnsSegmentsAndHeader) {
  const auto file = parse_micromag_loop(small_loop_file(kFourRows), "small.hys");
  EXPECT_EQ(file.format, "MicroMag 2900/3900 Data File (Series 0016.002)");
  EXPECT_EQ(file.title, "Direct moment vs. field; Hysteresis loop");
  ASSERT_EQ(file.columns, (std::vector<std::string>{"Field", "Moment", "Adjusted Moment"}));
  EXPECT_EQ(file.points(), 4u);
  EXPECT_EQ(file.segments, 2u);
  EXPECT_EQ(file.segment_starts, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(file.first_data_line, 21u);
  EXPECT_EQ(file.field(), (std::vector<double>{0.5, -0.5, -0.5, 0.5}));
  EXPECT_EQ(file.moment(), (std::vector<double>{2e-6, -2e-6, -2.1e-6, 2.1e-6}));
  EXPECT_EQ(file.column("Adjusted Moment")[3], 1.1e-6);
  EXPECT_EQ(file.header_text("Units of measure"), "Hybrid SI");
  EXPECT_EQ(file.header_number("Field increment"), 5e-3);
  // The segment table's titles are not header entries; section names are not either.
  EXPECT_FALSE(file.header_text("Segment"));
  EXPECT_FALSE(file.header_text("INSTRUMENT"));
  EXPECT_EQ(file.header.size(), 5u);
  EXPECT_HYST_ERROR(file.column("Temperature"),
                    "small.hys: no column 'Temperature' (columns: Field, Moment, Adjusted Moment)");
}

TEST(MicromagLoop, LfLineEndsAndUnmatchedTitlesRead) {
  std::string text = small_loop_file(kFourRows);
  std::erase(text, '\r');
  const auto file = parse_micromag_loop(text, "lf.hys");
  EXPECT_EQ(file.points(), 4u);
  // Titles that do not give one name per column: the columns are numbered.
  std::string untitled = small_loop_file(kFourRows);
  untitled.replace(untitled.find("    Field         Moment     Moment"), 35, "    Data");
  const auto numbered = parse_micromag_loop(untitled, "untitled.hys");
  EXPECT_EQ(numbered.columns, (std::vector<std::string>{"Column 1", "Column 2", "Column 3"}));
}

// Every file of the set reads. The reader checks "Number of data" itself; the counts and column
// sets below are those PROVENANCE.md lists.
TEST(MicromagLoop, EveryHystlabFileReads) {
  std::size_t files = 0;
  std::size_t noise_repeats = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kFolder)) {
    const auto extension = entry.path().extension().string();
    if (!entry.is_regular_file() || extension == ".txt" || extension == ".md") continue;
    SCOPED_TRACE(entry.path().string());
    const auto file = read_micromag_loop(entry.path());
    ++files;
    EXPECT_GE(file.columns.size(), 2u);
    EXPECT_EQ(file.segment_starts.size(), 2u);  // down branch, up branch
    if (entry.path().filename().string().starts_with("Noise_test")) {
      ++noise_repeats;
      EXPECT_EQ(file.points(), 402u);
      EXPECT_EQ(file.columns, (std::vector<std::string>{"Field", "Moment"}));
      EXPECT_EQ(file.header_text("Units of measure"), "Hybrid SI");
    }
  }
  EXPECT_EQ(files, 136u);  // 120 repeats + 16 further files (two copies of Conc_40_C2A)
  EXPECT_EQ(noise_repeats, 120u);
}

TEST(MicromagLoop, CP4QColumnsAgreeWithTheStatedSlopeCorrection) {
  const auto file = read_micromag_loop(kFolder / "fig01" / "CP4Q.hyst");
  ASSERT_EQ(file.columns, (std::vector<std::string>{"Raw Field", "Raw Moment", "Adjusted Field",
                                                    "Adjusted Moment"}));
  EXPECT_EQ(file.format, "MicroMag 2900/3900 Data File (Series 0015)");
  EXPECT_EQ(file.points(), 1602u);  // PROVENANCE.md
  EXPECT_EQ(file.segments, 3u);
  // The first data row as printed in the file (line 80).
  EXPECT_EQ(file.first_data_line, 80u);
  EXPECT_EQ(file.field()[0], 7.997968e-01);
  EXPECT_EQ(file.moment()[0], 2.921634e-05);
  // "Slope correction -1.278073E-05", no offset: adjusted = raw + slope * field, to the printed
  // digits: half a unit in the 7th digit of the raw and the adjusted moment (5e-12 each) and of
  // the slope (5e-12 times |field| <= 0.8) add up to at most 1.4e-11.
  const auto slope = file.header_number("Slope correction");
  ASSERT_TRUE(slope);
  EXPECT_EQ(*slope, -1.278073e-05);
  const auto& raw = file.column("Raw Moment");
  const auto& adjusted = file.column("Adjusted Moment");
  for (std::size_t i = 0; i < file.points(); ++i) {
    EXPECT_EQ(file.column("Adjusted Field")[i], file.field()[i]);
    EXPECT_NEAR(adjusted[i], raw[i] + *slope * file.field()[i], 1.4e-11) << "point " << i;
  }
}

TEST(MicromagLoop, DataFileOffersTheColumns) {
  const DataFile data(kFolder / "fig06" / "Conc_40_C3B.hys");
  EXPECT_EQ(data.column_list(), "Field, Moment, Temperature, Adjusted Field, Adjusted Moment");
  EXPECT_EQ(data.column("Adjusted Moment").size(), 242u);
  EXPECT_HYST_ERROR(DataFile(kFolder / "fig06" / "Conc_40_C3B.hys", 2),
                    "this file is a MicroMag loop file");
}

TEST(MicromagLoop, MalformedFilesNameFileLineAndColumn) {
  EXPECT_HYST_ERROR(parse_micromag_loop("Field,Moment\n1,2\n", "x.hys"),
                    "x.hys:1: not a MicroMag data file");
  std::string forc = small_loop_file(kFourRows);
  forc.replace(forc.find("Direct moment vs. field; Hysteresis loop"), 40,
               "First-order reversal curves");
  EXPECT_HYST_ERROR(parse_micromag_loop(forc, "x.hys"), "x.hys:2: a MicroMag FORC file");
  EXPECT_HYST_ERROR(
      parse_micromag_loop(small_loop_file("+5.0E-01,+2.0E-06,+1.x0E-06\r\n", "1"), "x.hys"),
      "x.hys:21: column 3 ('Adjusted Moment'): '+1.x0E-06' is not a finite number");
  EXPECT_HYST_ERROR(parse_micromag_loop(small_loop_file("+5.0E-01,nan,+1.0E-06\r\n", "1"), "x.hys"),
                    "x.hys:21: column 2 ('Moment'): 'nan' is not a finite number");
  EXPECT_HYST_ERROR(
      parse_micromag_loop(
          small_loop_file("+5.0E-01,+2.0E-06,+1.0E-06\r\n+5.0E-01,+2.0E-06\r\n", "2"), "x.hys"),
      "x.hys:22: 2 fields, but the first data row (line 21) has 3");
  EXPECT_HYST_ERROR(parse_micromag_loop(small_loop_file(kFourRows, "5"), "x.hys"),
                    "x.hys: the header says 'Number of data 5' but the file has 4 data rows");
  EXPECT_HYST_ERROR(parse_micromag_loop(small_loop_file(kFourRows, "4", "3"), "x.hys"),
                    "the header says 'Number of segments 3' but the segment table has 2 rows");
  EXPECT_HYST_ERROR(
      parse_micromag_loop(small_loop_file("+5.0E-01,+2.0E-06,+1.0E-06\r\nsome text\r\n", "1"),
                          "x.hys"),
      "x.hys:22: 'some text' is not a data row (3 comma-separated numbers)");
  // Only a line starting "MicroMag" ends the file: a data row holding the marker's words is
  // still a data row (fuzzing found a file whose only data row was one).
  EXPECT_HYST_ERROR(
      parse_micromag_loop(small_loop_file("0000003,+100.0 Data File ends\r\n", "1"), "x.hys"),
      "x.hys:21: column 2 ('Column 2'): '+100.0 Data File ends' is not a finite number");
  const std::string full = small_loop_file(kFourRows);
  const std::string truncated = full.substr(0, full.find("-5.0E-01,-2.1E-06"));
  EXPECT_HYST_ERROR(parse_micromag_loop(truncated, "x.hys"),
                    "the file ends without the line 'MicroMag 2900/3900 Data File ends'");
  const std::string header_only = full.substr(0, full.find("0000001,"));
  EXPECT_HYST_ERROR(parse_micromag_loop(header_only, "x.hys"),
                    "x.hys:15: the file ends in its header, before any data");
  std::string no_data = full.substr(0, full.find("+5.0E-01,+2.0E-06"));
  no_data += "MicroMag 2900/3900 Data File ends\r\n";
  EXPECT_HYST_ERROR(parse_micromag_loop(no_data, "x.hys"),
                    "the file has a segment table but no data rows");
  EXPECT_HYST_ERROR(read_micromag_loop(kFolder / "no_such_file.hys"), "no_such_file.hys");
}

// 'Number of segments' is checked against a segment table only where the file has one; a table
// is known by its titles ("Segment ...") or its numbered rows ("0000001,..."), not by the count.
TEST(MicromagLoop, SegmentTableWithOrWithoutItsCount) {
  // The count without a table: the data follow the column titles.
  std::string no_table = small_loop_file(kFourRows);
  no_table.erase(
      no_table.find("Segment   Averaging"),
      no_table.find("                            Adjusted") - no_table.find("Segment   Averaging"));
  const auto counted = parse_micromag_loop(no_table, "n.hys");
  EXPECT_EQ(counted.segments, 0U);
  EXPECT_EQ(counted.header_number("Number of segments"), 2.0);
  EXPECT_EQ(counted.columns, (std::vector<std::string>{"Field", "Moment", "Adjusted Moment"}));
  EXPECT_EQ(counted.first_data_line, 16U);
  EXPECT_EQ(counted.field(), (std::vector<double>{0.5, -0.5, -0.5, 0.5}));
  // A table without the count: its rows are counted, not checked.
  std::string uncounted = small_loop_file(kFourRows);
  uncounted.erase(uncounted.find("Number of segments"),
                  uncounted.find("Number of data") - uncounted.find("Number of segments"));
  const auto table = parse_micromag_loop(uncounted, "t.hys");
  EXPECT_EQ(table.segments, 2U);
  EXPECT_EQ(table.first_data_line, 20U);
  // A table of numbered rows without its titles is still a table.
  std::string untitled = small_loop_file(kFourRows);
  untitled.erase(untitled.find("Segment   Averaging"),
                 untitled.find("0000001,") - untitled.find("Segment   Averaging"));
  EXPECT_EQ(parse_micromag_loop(untitled, "u.hys").segments, 2U);
  const std::string_view two = "Number of segments              2";
  untitled.replace(untitled.find(two), two.size(), "Number of segments              3");
  EXPECT_HYST_ERROR(parse_micromag_loop(untitled, "u.hys"),
                    "u.hys:15: the header says 'Number of segments 3' but the segment table has "
                    "2 rows");
}

// The older exports: the format and title lines, then the data; the first two columns are the
// field and the moment, units unknown. A cgs header gives Oe and emu.
TEST(MicromagLoop, TwoLineHeaderAndCgsUnits) {
  const std::string old =
      "MicroMag 2900/3900 Data File\n"
      "Direct moment vs. field; Hysteresis loop\n"
      "+5.000E+03,+2.0E-03\n"
      "-5.000E+03,-2.0E-03\n"
      "+5.000E+03,+2.0E-03\n"
      "MicroMag 2900/3900 Data File ends\n";
  EXPECT_TRUE(looks_like_micromag_loop(old));
  const auto file = parse_micromag_loop(old, "old.hys");
  EXPECT_EQ(file.columns, (std::vector<std::string>{"Field", "Moment"}));
  EXPECT_EQ(file.units, (std::vector<std::string>{"", ""}));
  EXPECT_EQ(file.first_data_line, 3U);
  EXPECT_EQ(file.field(), (std::vector<double>{5000.0, -5000.0, 5000.0}));
  EXPECT_TRUE(file.header.empty());
  std::string cgs = small_loop_file(kFourRows);
  cgs.replace(cgs.find("Hybrid SI"), 9, "cgs");
  const std::string_view units_line = "     (T)          (Am2)       (Am2)   \r\n";
  cgs.erase(cgs.find(units_line), units_line.size());
  EXPECT_EQ(parse_micromag_loop(cgs, "c.hys").units,
            (std::vector<std::string>{"Oe", "emu", "emu"}));
}

TEST(MicromagLoop, LooksLikeChecksTheFirstTwoLines) {
  EXPECT_TRUE(looks_like_micromag_loop(small_loop_file(kFourRows)));
  EXPECT_FALSE(
      looks_like_micromag_loop("MicroMag 2900/3900 Data File (Series 0015)\n"
                               "First-order reversal curves\n"));
  EXPECT_FALSE(looks_like_micromag_loop("t,v\n0,1\n"));
  EXPECT_FALSE(looks_like_micromag_loop(""));
}

TEST(MicromagLoop, UnitsFromTheUnitsLineOrTheHeader) {
  // A4.hys writes "(Am\xB2)" in Latin-1 under the moment columns.
  EXPECT_EQ(read_micromag_loop(kFolder / "fig10" / "A4.hys").units,
            (std::vector<std::string>{"T", "Am\u00b2", "T", "Am\u00b2"}));
  // CP4Q.hyst (Series 0015) has no units line: "Units of measure  Hybrid SI".
  EXPECT_EQ(read_micromag_loop(kFolder / "fig01" / "CP4Q.hyst").units,
            (std::vector<std::string>{"T", "A m\u00b2", "T", "A m\u00b2"}));
  EXPECT_EQ(parse_micromag_loop(small_loop_file(kFourRows), "u.hys").units,
            (std::vector<std::string>{"T", "Am2", "Am2"}));
  EXPECT_EQ(read_micromag_loop(kFolder / "fig10" / "A4.hys").initial_curve_points, 0U);
}

// A loop measured after an initial (virgin) curve from the demagnetised state: 0 -> 0.5 (3
// points), then 0.5 -> -0.5 and -0.5 -> 0.5 (5 points each).
std::string loop_with_initial_curve(bool blank_lines, std::string_view initial = "Yes") {
  const std::string gap = blank_lines ? "\r\n" : "";
  return fmt::format(
      "MicroMag 2900/3900 Data File (Series 0016.002)\r\n"
      "Direct moment vs. field; Hysteresis loop\r\n"
      "\r\n"
      "SCRIPT\r\n"
      "Units of measure                Hybrid SI\r\n"
      "Initial magnetization?          {}\r\n"
      "Number of data                  13\r\n"
      "\r\n"
      "    Field         Moment\r\n"
      "0.0,0.0\r\n0.25,0.5\r\n0.5,1.0\r\n{}"
      "0.5,1.0\r\n0.25,0.9\r\n0.0,0.6\r\n-0.25,-0.5\r\n-0.5,-1.0\r\n{}"
      "-0.5,-1.0\r\n-0.25,-0.9\r\n0.0,-0.6\r\n0.25,0.5\r\n0.5,1.0\r\n"
      "\r\n"
      "MicroMag 2900/3900 Data File ends\r\n",
      initial, gap, gap);
}

TEST(MicromagLoop, InitialCurveIsTheFirstBlockOrRunsToTheFirstTurn) {
  EXPECT_EQ(parse_micromag_loop(loop_with_initial_curve(true), "i.hys").initial_curve_points, 3U);
  // Without blank lines: the points before the field first turns back; the turning field 0.5 is
  // measured twice (rows 2 and 3), and the loop starts at the second.
  EXPECT_EQ(parse_micromag_loop(loop_with_initial_curve(false), "i.hys").initial_curve_points, 3U);
  EXPECT_EQ(parse_micromag_loop(loop_with_initial_curve(true, "No"), "i.hys").initial_curve_points,
            0U);
}

}  // namespace
}  // namespace hyst::io
