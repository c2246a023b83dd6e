// The MicroMag FORC reader: the measured example file (Series 0015, structure and counts from its
// PROVENANCE.md), the Series 0016 test file (tests/data/micromag/series_0016.forc: counts by
// construction, see make_series_0016_forc.py, and lines counted in the file), small hand-made
// files of both layouts, drift correction, malformed files and the input limits.

#include "hyst/io/micromag_forc.hpp"

#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/limits.hpp"

namespace hyst::io {
namespace {

const char* const kForcFile =
    HYST_SHARED_DATA_DIR "/pmagpy_forc_micromag_agm/conventional_example.forc";
const char* const kVsmFile = HYST_TEST_DATA_DIR "/micromag/series_0016.forc";

// A small file in the same layout: calibration, curve, calibration, curve, end marker.
std::string small_forc_file(std::string_view data, std::string_view ndata = "5") {
  return fmt::format(
      "MicroMag 2900/3900 Data File (Series 0015)\r\n"
      "First-order reversal curves\r\n"
      "Configuration   :  AGM\r\n"
      "Units of measure:  Hybrid SI\r\n"
      "04/13/2016  13:20\r\n"
      "\"\"\r\n"
      "\r\n"
      "HCal           = +2.350512E-01\r\n"
      "NCrv           = 2\r\n"
      "NData          = {}\r\n"
      "\r\n"
      "{}"
      "\r\n"
      "MicroMag 2900/3900 Data File ends\r\n",
      ndata, data);
}

constexpr std::string_view kData =
    "+2.0E-01,+1.0E-06\r\n"
    "\r\n"
    "+1.0E-01,+5.0E-07\r\n"
    "\r\n"
    "+2.0E-01,+9.0E-07\r\n"
    "\r\n"
    "-1.0E-01,-5.0E-07\r\n"
    "+0.0E+00,+1.0E-07\r\n";

TEST(MicromagForc, ReadsTheMeasuredExampleFile) {
  if (!std::filesystem::exists(kForcFile)) GTEST_SKIP() << "no " << kForcFile;
  const auto file = read_micromag_forc(kForcFile);
  EXPECT_EQ(file.format, "MicroMag 2900/3900 Data File (Series 0015)");
  EXPECT_EQ(file.title, "First-order reversal curves");
  EXPECT_EQ(file.header_text("Units of measure"), "Hybrid SI");
  EXPECT_EQ(file.header_text("Configuration"), "AGM");
  EXPECT_EQ(file.header_number("HSat"), 0.3);
  EXPECT_EQ(file.header_number("HCal"), 0.2350512);
  EXPECT_EQ(file.header_number("NCrv"), 120.0);
  EXPECT_EQ(file.header_number("NData"), 8514.0);
  // PROVENANCE.md: 121 calibration points... as parsed, 120 blocks of (calibration, FORC), the
  // first FORC a single point at H_r = 0.118 T, 8393 FORC points, H_r down to -0.218 T, the last
  // FORC 85 points.
  ASSERT_EQ(file.curves.size(), 120U);
  EXPECT_FALSE(file.final_calibration.has_value());
  EXPECT_EQ(file.points(), 8514U - 120U);
  EXPECT_EQ(file.curves.front().field.size(), 1U);
  EXPECT_EQ(file.curves.front().field.front(), 0.1182822);
  EXPECT_EQ(file.curves.front().first_line, 37U);
  EXPECT_EQ(file.curves.back().field.size(), 85U);
  EXPECT_EQ(file.curves.back().field.front(), -0.218002);
  EXPECT_EQ(file.curves.back().moment.back(), 1.480875e-07);
  EXPECT_EQ(file.curves.front().calibration_moment, 7.842043e-07);
  std::size_t multi_point = 0;
  for (const auto& curve : file.curves) {
    multi_point += curve.field.size() > 1 ? 1 : 0;
    for (std::size_t i = 1; i < curve.field.size(); ++i)
      ASSERT_GT(curve.field[i], curve.field[i - 1]);  // every FORC sweeps up from H_r
    EXPECT_NEAR(curve.calibration_field, 0.237, 1e-3);
  }
  EXPECT_EQ(multi_point, 119U);
  // The calibration moment drifts down by 1.3 % over the run.
  EXPECT_NEAR(file.curves.back().calibration_moment / file.curves.front().calibration_moment,
              0.9871, 1e-4);
}

TEST(MicromagForc, ParsesASmallFile) {
  const auto file = parse_micromag_forc(small_forc_file(kData), "small.forc");
  ASSERT_EQ(file.curves.size(), 2U);
  EXPECT_EQ(file.curves[0].field, (std::vector<double>{0.1}));
  EXPECT_EQ(file.curves[1].field, (std::vector<double>{-0.1, 0.0}));
  EXPECT_EQ(file.curves[1].moment, (std::vector<double>{-5e-7, 1e-7}));
  EXPECT_EQ(file.curves[1].calibration_moment, 9e-7);
  EXPECT_EQ(file.curves[1].first_line, 18U);
  EXPECT_EQ(file.header_number("Configuration"), std::nullopt);
  EXPECT_EQ(file.header_text("Missing"), std::nullopt);
  // LF line ends and a trailing calibration point are fine too.
  std::string lf = small_forc_file(std::string(kData) + "\r\n+2.0E-01,+8.0E-07\r\n", "6");
  std::erase(lf, '\r');
  const auto with_final = parse_micromag_forc(lf, "lf.forc");
  ASSERT_TRUE(with_final.final_calibration.has_value());
  EXPECT_EQ(with_final.final_calibration->second, 8e-7);
}

TEST(MicromagForc, CorrectsDrift) {
  const auto file = parse_micromag_forc(small_forc_file(kData), "small.forc");
  // Curve 1 (2 points) between the calibrations 9e-7 (before) and 9e-7 (none after: before).
  const auto scaled = correct_drift(file, ForcDriftCorrection::multiplicative);
  EXPECT_DOUBLE_EQ(scaled.curves[1].moment[0], -5e-7 * 1e-6 / 9e-7);
  EXPECT_DOUBLE_EQ(scaled.curves[1].calibration_moment, 1e-6);
  // Curve 0 (1 point) between 1e-6 and 9e-7: drift at 1/2 of the way = 9.5e-7.
  EXPECT_DOUBLE_EQ(scaled.curves[0].moment[0], 5e-7 * 1e-6 / 9.5e-7);
  const auto shifted = correct_drift(file, ForcDriftCorrection::additive);
  EXPECT_DOUBLE_EQ(shifted.curves[0].moment[0], 5e-7 + 0.5e-7);
  EXPECT_DOUBLE_EQ(shifted.curves[1].moment[1], 1e-7 + 1e-7);
  EXPECT_EQ(correct_drift(file, ForcDriftCorrection::none).curves[1].moment, file.curves[1].moment);
  for (auto c : {ForcDriftCorrection::none, ForcDriftCorrection::multiplicative,
                 ForcDriftCorrection::additive}) {
    EXPECT_EQ(forc_drift_correction_from_string(to_string(c)), c);
  }
  EXPECT_HYST_ERROR(forc_drift_correction_from_string("linear"),
                    "unknown FORC drift correction 'linear'");
}

TEST(MicromagForc, ErrorsNameTheFileAndLine) {
  EXPECT_HYST_ERROR(parse_micromag_forc("Field,Moment\n1,2\n", "x.forc"),
                    "x.forc:1: not a MicroMag data file (the first line is 'Field,Moment'");
  std::string bad(kData);
  bad.replace(bad.find("+1.0E-01"), 8, "x.1E-01");
  EXPECT_HYST_ERROR(
      parse_micromag_forc(small_forc_file(bad), "bad.forc"),
      "bad.forc:14: 'x.1E-01,+5.0E-07' is not 'field,moment' with two finite numbers");
  bad = kData;
  bad.replace(bad.find("+1.0E-01,+5.0E-07"), 17, "+1.0E-01");
  EXPECT_HYST_ERROR(parse_micromag_forc(small_forc_file(bad), "bad.forc"),
                    "bad.forc:14: '+1.0E-01' is not 'field,moment'");
  bad = kData;
  bad.replace(bad.find("+1.0E-01,+5.0E-07"), 17, "+1.0E-01,nan");
  EXPECT_HYST_ERROR(parse_micromag_forc(small_forc_file(bad), "bad.forc"),
                    "bad.forc:14: '+1.0E-01,nan' is not 'field,moment' with two finite numbers");
  std::string truncated = small_forc_file(kData);
  truncated.resize(truncated.find("MicroMag 2900/3900 Data File ends"));
  EXPECT_HYST_ERROR(parse_micromag_forc(truncated, "cut.forc"),
                    "cut.forc:20: the file ends without the line 'MicroMag 2900/3900 Data File "
                    "ends' (truncated?)");
  EXPECT_HYST_ERROR(parse_micromag_forc(small_forc_file(kData, "7"), "n.forc"),
                    "n.forc:21: the header says NData = 7 but the file has 5 data points");
  bad = kData;
  bad.insert(0, "+2.0E-01,+1.0E-06\r\n");
  EXPECT_HYST_ERROR(parse_micromag_forc(small_forc_file(bad, "6"), "cal.forc"),
                    "cal.forc:12: a calibration block has 2 points; expected 1");
  EXPECT_HYST_ERROR(
      parse_micromag_forc("MicroMag 2900/3900 Data File (Series 0015)\nFORC\nA = 1\n", "h.forc"),
      "h.forc:3: the file ends in its header, before any data (truncated?)");
  EXPECT_HYST_ERROR(read_micromag_forc("/nonexistent/file.forc"),
                    "cannot open '/nonexistent/file.forc'");
  auto zero = parse_micromag_forc(small_forc_file(kData), "z.forc");
  zero.curves[1].calibration_moment = 0.0;
  EXPECT_HYST_ERROR(correct_drift(zero, ForcDriftCorrection::multiplicative),
                    "z.forc: calibration moment before curve 1 is 0");
}

TEST(MicromagForc, ReadsTheSeries0016TestFile) {
  const auto file = read_micromag_forc(kVsmFile);
  EXPECT_EQ(file.layout, MicromagForcLayout::series_0016);
  EXPECT_EQ(file.format, "MicroMag 2900/3900 Data File (Series 0016.002)");
  EXPECT_EQ(file.title, "First-order reversal curves");
  EXPECT_EQ(file.header_text("Configuration"), "VSM");
  EXPECT_EQ(file.header_text("Units of measure"), "Hybrid SI");
  EXPECT_EQ(file.header_number("HCal"), 0.3);
  EXPECT_EQ(file.header_number("HSat"), 0.5);
  EXPECT_EQ(file.header_number("NForc"), 16.0);
  EXPECT_EQ(file.header_number("Number of data"), 169.0);
  EXPECT_EQ(file.columns, (std::vector<std::string>{"Field", "Moment", "Normalized Moment"}));
  // "(Am\xB2)" in Latin-1 in the file; UTF-8 here.
  EXPECT_EQ(file.units, (std::vector<std::string>{"T", "Am\u00b2", "Am\u00b2/kg"}));
  // 16 curves of 2, 3, ..., 17 points; 16 + 1 calibration points.
  ASSERT_EQ(file.curves.size(), 16U);
  EXPECT_EQ(file.points(), 152U);
  EXPECT_EQ(file.calibration_points(), 17U);
  ASSERT_TRUE(file.final_calibration.has_value());
  EXPECT_EQ(file.final_calibration->first, 0.3004);
  EXPECT_EQ(file.final_calibration->second, 40.194e-6);
  for (std::size_t k = 0; k < file.curves.size(); ++k) {
    const auto& curve = file.curves[k];
    ASSERT_EQ(curve.field.size(), k + 2) << "curve " << k;
    ASSERT_EQ(curve.more_columns.size(), 1U);
    ASSERT_EQ(curve.more_columns[0].size(), k + 2);
    for (std::size_t i = 1; i < curve.field.size(); ++i)
      ASSERT_GT(curve.field[i], curve.field[i - 1]);
    EXPECT_NEAR(curve.calibration_field, 0.3, 5e-4);
  }
  // Lines 58-61 of the file: the first calibration point, a blank line, the first FORC.
  const auto& first = file.curves.front();
  EXPECT_EQ(first.first_line, 60U);
  EXPECT_EQ(first.calibration_field, 0.3004);
  EXPECT_EQ(first.calibration_moment, 40.6e-6);
  EXPECT_EQ(first.field, (std::vector<double>{70.03e-3, 79.97e-3}));
  EXPECT_EQ(first.moment, (std::vector<double>{40.14e-6, 40.16e-6}));
  EXPECT_EQ(first.more_columns[0], (std::vector<double>{2.007, 2.008}));
  EXPECT_EQ(file.curves.back().first_line, 240U);
  EXPECT_EQ(file.curves.back().field.front(), -79.97e-3);
  // The calibration moment falls by 1 % over the run (the file's construction).
  EXPECT_NEAR(file.final_calibration->second / first.calibration_moment, 0.99, 1e-6);
  EXPECT_TRUE(looks_like_micromag_forc(read_file(kVsmFile)));
}

// A small Series 0016 file: sections, stacked titles, three columns.
std::string vsm_file(
    std::string_view data, std::string_view count = "5",
    std::string_view units = "     (T)           (Am\xB2)          (Am\xB2/kg)\r\n") {
  return fmt::format(
      "MicroMag 2900/3900 Data File (Series 0016.002)\r\n"
      "First-order reversal curves\r\n"
      "\r\n"
      "INSTRUMENT\r\n"
      "Configuration                   VSM\r\n"
      "Units of measure                Hybrid SI\r\n"
      "A key nobody knows             +1.5E+00\r\n"
      "\r\n"
      "\r\n"
      "SCRIPT\r\n"
      "HCal                           +300.0000E-03\r\n"
      "Number of data                  {}\r\n"
      "\r\n"
      "                                      Normalized\r\n"
      "    Field          Moment               Moment\r\n"
      "{}"
      "{}"
      "\r\n"
      "MicroMag 2900/3900 Data File ends\r\n",
      count, units, data);
}

constexpr std::string_view kVsmData =
    "+3.0E-01,+1.0E-05,+1.0E+00\r\n"
    "\r\n"
    "+1.0E-01,+5.0E-06,+5.0E-01\r\n"
    "\r\n"
    "+3.0E-01,+9.0E-06,+9.0E-01\r\n"
    "\r\n"
    "-1.0E-01,-5.0E-06,-5.0E-01\r\n"
    "+0.0E+00,+1.0E-06,+1.0E-01\r\n";

TEST(MicromagForc, ParsesSmallSeries0016Files) {
  const auto file = parse_micromag_forc(vsm_file(kVsmData), "v.forc");
  EXPECT_EQ(file.layout, MicromagForcLayout::series_0016);
  EXPECT_EQ(file.header_number("A key nobody knows"), 1.5);
  EXPECT_EQ(file.columns, (std::vector<std::string>{"Field", "Moment", "Normalized Moment"}));
  EXPECT_EQ(file.units[1], "Am\u00b2");
  ASSERT_EQ(file.curves.size(), 2U);
  EXPECT_EQ(file.curves[1].field, (std::vector<double>{-0.1, 0.0}));
  EXPECT_EQ(file.curves[1].calibration_moment, 9e-6);
  EXPECT_EQ(file.curves[1].more_columns[0], (std::vector<double>{-0.5, 0.1}));
  EXPECT_EQ(file.curves[1].first_line, 23U);
  // "Number of data" may count the FORC points only (3 here) as well as every row (5).
  EXPECT_EQ(parse_micromag_forc(vsm_file(kVsmData, "3"), "v.forc").points(), 3U);
  // A units line already in UTF-8 stays as it is; without one, the units follow "Hybrid SI".
  EXPECT_EQ(
      parse_micromag_forc(vsm_file(kVsmData, "5", "  (T)  (Am\u00b2)  (Am\u00b2/kg)\r\n"), "u.forc")
          .units[1],
      "Am\u00b2");
  EXPECT_EQ(parse_micromag_forc(vsm_file(kVsmData, "5", ""), "n.forc").units,
            (std::vector<std::string>{"T", "A m\u00b2", ""}));
  // LF line ends, blank lines doubled.
  std::string lf = vsm_file(kVsmData);
  std::erase(lf, '\r');
  const auto doubled = lf.replace(lf.find("\n\n-1.0E-01"), 2, "\n\n\n");
  EXPECT_EQ(parse_micromag_forc(doubled, "lf.forc").curves.size(), 2U);
  // The calibration point may open the block of its curve (the field falls from HCal to H_r).
  constexpr std::string_view kInline =
      "+3.0E-01,+1.0E-05,+1.0E+00\r\n"
      "+1.0E-01,+5.0E-06,+5.0E-01\r\n"
      "\r\n"
      "+3.0E-01,+9.0E-06,+9.0E-01\r\n"
      "-1.0E-01,-5.0E-06,-5.0E-01\r\n"
      "+0.0E+00,+1.0E-06,+1.0E-01\r\n";
  const auto inline_file = parse_micromag_forc(vsm_file(kInline), "i.forc");
  ASSERT_EQ(inline_file.curves.size(), 2U);
  EXPECT_EQ(inline_file.curves[0].field, (std::vector<double>{0.1}));
  EXPECT_EQ(inline_file.curves[1].calibration_moment, 9e-6);
  EXPECT_EQ(inline_file.curves[1].first_line, 21U);
  EXPECT_FALSE(inline_file.final_calibration.has_value());
  // Drift correction leaves the further columns as measured.
  const auto corrected = correct_drift(file, ForcDriftCorrection::multiplicative);
  EXPECT_EQ(corrected.curves[1].more_columns, file.curves[1].more_columns);
  EXPECT_DOUBLE_EQ(corrected.curves[1].moment[0], -5e-6 * 1e-5 / 9e-6);
}

TEST(MicromagForc, MalformedSeries0016FilesNameFileAndLine) {
  std::string bad(kVsmData);
  bad.replace(bad.find("+5.0E-01"), 8, "x");
  EXPECT_HYST_ERROR(parse_micromag_forc(vsm_file(bad), "b.forc"),
                    "b.forc:19: column 3 ('Normalized Moment'): 'x' is not a finite number");
  bad = kVsmData;
  bad.replace(bad.find(",+5.0E-01"), 9, "");
  EXPECT_HYST_ERROR(parse_micromag_forc(vsm_file(bad), "b.forc"),
                    "b.forc:19: '+1.0E-01,+5.0E-06' has 2 comma-separated fields; the data rows "
                    "have 3 (Field, Moment, Normalized Moment)");
  EXPECT_HYST_ERROR(parse_micromag_forc(vsm_file(kVsmData, "7"), "b.forc"),
                    "b.forc:26: the header says 'Number of data 7' but the file has 5 data rows "
                    "(3 FORC points and 2 calibration points)");
  std::string cut = vsm_file(kVsmData);
  cut.resize(cut.find("MicroMag 2900/3900 Data File ends"));
  EXPECT_HYST_ERROR(parse_micromag_forc(cut, "c.forc"),
                    "c.forc:25: the file ends without the line 'MicroMag 2900/3900 Data File "
                    "ends' (truncated?)");
  // A block of two points whose field does not fall is no calibration point.
  bad = kVsmData;
  bad.insert(0, "+3.0E-01,+1.0E-05,+1.0E+00\r\n");
  EXPECT_HYST_ERROR(parse_micromag_forc(vsm_file(bad, "6"), "d.forc"),
                    "d.forc:17: a calibration block has 2 points; expected 1");
  const std::string header_only = vsm_file(kVsmData).substr(0, vsm_file(kVsmData).find("+3.0E-01"));
  EXPECT_HYST_ERROR(parse_micromag_forc(header_only, "h.forc"),
                    "h.forc:16: the file ends in its header, before any data (truncated?)");
  EXPECT_HYST_ERROR(
      parse_micromag_forc(header_only + "MicroMag 2900/3900 Data File ends\r\n", "e.forc"),
      "e.forc:17: the end marker follows the header: the file has no data rows");
  EXPECT_HYST_ERROR(parse_micromag_forc(vsm_file("+3.0E-01,+1.0E-05,+1.0E+00\r\n", "1"), "o.forc"),
                    "o.forc:19: the file has no FORC (only calibration points)");
  // A loop file is pointed to its reader.
  std::string loop = vsm_file(kVsmData);
  loop.replace(loop.find("First-order reversal curves"), 27,
               "Direct moment vs. field; Hysteresis loop");
  EXPECT_HYST_ERROR(parse_micromag_forc(loop, "l.forc"),
                    "l.forc:2: a MicroMag hysteresis loop file, not a FORC file");
}

// The case a measured VSM FORC file was refused for ("forc_vsm.001:89: the header says 'Number of
// segments 100' but the segment table has 1 rows"): the script's segment count in the header, no
// segment table. It reads; the count is not checked against anything.
TEST(MicromagForc, NumberOfSegmentsWithoutASegmentTableReads) {
  std::string text = vsm_file(kVsmData);
  text.insert(text.find("Number of data"), "Number of segments              100\r\n");
  const auto file = parse_micromag_forc(text, "forc_vsm.001");
  EXPECT_EQ(file.layout, MicromagForcLayout::series_0016);
  EXPECT_EQ(file.header_number("Number of segments"), 100.0);
  ASSERT_EQ(file.curves.size(), 2U);
  EXPECT_EQ(file.curves[0].field, (std::vector<double>{0.1}));
  EXPECT_EQ(file.curves[1].field, (std::vector<double>{-0.1, 0.0}));
  EXPECT_EQ(file.curves[1].calibration_moment, 9e-6);
  // The data moved one line down: the last curve starts on line 24.
  EXPECT_EQ(file.curves[1].first_line, 24U);
  // Without the line (the workaround that made the file read) the curves are the same.
  const auto without = parse_micromag_forc(vsm_file(kVsmData), "v.forc");
  EXPECT_EQ(without.curves[1].moment, file.curves[1].moment);
  EXPECT_FALSE(without.header_text("Number of segments"));
}

// A FORC file may carry a segment table like a loop file (its titles "Segment ... Number"): it
// is skipped, and checked against 'Number of segments' only then.
TEST(MicromagForc, ASegmentTableIsSkippedAndCounted) {
  const auto with_table = [](std::string_view segments) {
    std::string text = vsm_file(kVsmData);
    text.replace(text.find("\r\n                                      Normalized"), 2,
                 fmt::format("Number of segments              {}\r\n"
                             "\r\n"
                             "Segment   Averaging      Initial\r\n"
                             " Number      Time         Field \r\n"
                             "0000001,+100.0000E-03,+300.0000E-03\r\n"
                             "0000002,+100.0000E-03,+100.0000E-03\r\n"
                             "\r\n",
                             segments));
    return text;
  };
  const auto file = parse_micromag_forc(with_table("2"), "t.forc");
  EXPECT_EQ(file.columns, (std::vector<std::string>{"Field", "Moment", "Normalized Moment"}));
  ASSERT_EQ(file.curves.size(), 2U);
  EXPECT_EQ(file.curves[1].field, (std::vector<double>{-0.1, 0.0}));
  // Lines 13-19: the count, a blank line, 2 title and 2 table rows, a blank line; 20-22 the
  // column titles, 23 the calibration point, 24 blank, 25 the first curve.
  EXPECT_EQ(file.curves[0].first_line, 25U);
  EXPECT_HYST_ERROR(parse_micromag_forc(with_table("3"), "t.forc"),
                    "t.forc:19: the header says 'Number of segments 3' but the segment table "
                    "has 2 rows");
}

// Series 0015 with the header keys in another order (NData first, 'Units of measure' last) and
// no blank line before the data: the NData line is an entry, not a column title.
TEST(MicromagForc, Series0015KeysInAnyOrder) {
  const auto text = [](std::string_view ndata, std::string_view units) {
    return fmt::format(
        "MicroMag 2900/3900 Data File (Series 0015)\n"
        "First-order reversal curves\n"
        "NData          = {}\n"
        "HCal           = +2.000000E-01\n"
        "Configuration   :  AGM\n"
        "Units of measure:  {}\n"
        "+2.0E+03,+1.0E-03\n"
        "\n"
        "+1.0E+03,+5.0E-04\n"
        "\n"
        "+2.0E+03,+9.0E-04\n"
        "\n"
        "-1.0E+03,-5.0E-04\n"
        "+0.0E+00,+1.0E-04\n"
        "MicroMag 2900/3900 Data File ends\n",
        ndata, units);
  };
  const auto file = parse_micromag_forc(text("5", "Cgs"), "r.forc");
  EXPECT_EQ(file.layout, MicromagForcLayout::series_0015);
  EXPECT_EQ(file.header_number("NData"), 5.0);
  EXPECT_EQ(file.header_number("HCal"), 0.2);
  EXPECT_EQ(file.header_text("Configuration"), "AGM");
  // cgs: field in Oe, moment in emu.
  EXPECT_EQ(file.units, (std::vector<std::string>{"Oe", "emu"}));
  ASSERT_EQ(file.curves.size(), 2U);
  EXPECT_EQ(file.curves[0].calibration_field, 2000.0);
  EXPECT_EQ(file.curves[1].field, (std::vector<double>{-1000.0, 0.0}));
  EXPECT_EQ(file.curves[1].first_line, 13U);
  EXPECT_EQ(parse_micromag_forc(text("5", "Hybrid SI"), "r.forc").units,
            (std::vector<std::string>{"T", "A m\u00b2"}));
  // NData is still checked where it stands.
  EXPECT_HYST_ERROR(parse_micromag_forc(text("6", "Cgs"), "r.forc"),
                    "r.forc:15: the header says NData = 6 but the file has 5 data points");
}

// The older exports: the format line without a series, the title, then the data (no header).
// A title naming FORCs after the measurement kind reads too.
TEST(MicromagForc, TwoLineHeaderReads) {
  const std::string text =
      "MicroMag 2900/3900 Data File\r\n"
      "Direct moment vs. field; First-order reversal curves\r\n"
      "+2.0E-01,+1.0E-06\r\n"
      "\r\n"
      "+1.0E-01,+5.0E-07\r\n"
      "+1.5E-01,+6.0E-07\r\n"
      "MicroMag 2900/3900 Data File ends\r\n";
  EXPECT_TRUE(looks_like_micromag_forc(text));
  const auto file = parse_micromag_forc(text, "old.frc");
  EXPECT_EQ(file.layout, MicromagForcLayout::no_header);
  EXPECT_EQ(to_string(file.layout), "no_header");
  EXPECT_TRUE(file.header.empty());
  EXPECT_EQ(file.columns, (std::vector<std::string>{"Field", "Moment"}));
  // No 'Units of measure': the units are unknown.
  EXPECT_EQ(file.units, (std::vector<std::string>{"", ""}));
  ASSERT_EQ(file.curves.size(), 1U);
  EXPECT_EQ(file.curves[0].calibration_moment, 1e-6);
  EXPECT_EQ(file.curves[0].field, (std::vector<double>{0.1, 0.15}));
  EXPECT_EQ(file.curves[0].first_line, 5U);
  // A row of one number is named by file and line.
  std::string bad = text;
  bad.replace(bad.find("+1.5E-01,+6.0E-07"), 17, "+1.5E-01,+6.0E-07,+1.0");
  EXPECT_HYST_ERROR(parse_micromag_forc(bad, "old.frc"),
                    "old.frc:6: '+1.5E-01,+6.0E-07,+1.0' has 3 comma-separated fields; the data "
                    "rows have 2 (Field, Moment)");
}

TEST(MicromagForc, CurveCountIsLimited) {
  // One calibration point and one single-point curve per FORC, a few bytes each.
  std::string data;
  for (std::size_t k = 0; k <= limits::kMaxForcCurves; ++k)
    data += "2,1\n\n1,1\n\n";
  EXPECT_HYST_ERROR(parse_micromag_forc(small_forc_file(data, "0"), "many.forc"),
                    "more than 100000 FORCs; the limit is 100000 curves per file");
}

}  // namespace
}  // namespace hyst::io
