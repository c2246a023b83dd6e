// The MicroMag FORC reader: the measured example file (structure and counts from its
// PROVENANCE.md), small hand-made files, drift correction, and malformed files.

#include "hyst/io/micromag_forc.hpp"

#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"

namespace hyst::io {
namespace {

const char* const kFile =
    HYST_SHARED_DATA_DIR "/pmagpy_forc_micromag_agm/conventional_example.forc";

// A small file in the same layout: calibration, curve, calibration, curve, end marker.
std::string small_file(std::string_view data, std::string_view ndata = "5") {
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
  if (!std::filesystem::exists(kFile)) GTEST_SKIP() << "no " << kFile;
  const auto file = read_micromag_forc(kFile);
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
  const auto file = parse_micromag_forc(small_file(kData), "small.forc");
  ASSERT_EQ(file.curves.size(), 2U);
  EXPECT_EQ(file.curves[0].field, (std::vector<double>{0.1}));
  EXPECT_EQ(file.curves[1].field, (std::vector<double>{-0.1, 0.0}));
  EXPECT_EQ(file.curves[1].moment, (std::vector<double>{-5e-7, 1e-7}));
  EXPECT_EQ(file.curves[1].calibration_moment, 9e-7);
  EXPECT_EQ(file.curves[1].first_line, 18U);
  EXPECT_EQ(file.header_number("Configuration"), std::nullopt);
  EXPECT_EQ(file.header_text("Missing"), std::nullopt);
  // LF line ends and a trailing calibration point are fine too.
  std::string lf = small_file(std::string(kData) + "\r\n+2.0E-01,+8.0E-07\r\n", "6");
  std::erase(lf, '\r');
  const auto with_final = parse_micromag_forc(lf, "lf.forc");
  ASSERT_TRUE(with_final.final_calibration.has_value());
  EXPECT_EQ(with_final.final_calibration->second, 8e-7);
}

TEST(MicromagForc, CorrectsDrift) {
  const auto file = parse_micromag_forc(small_file(kData), "small.forc");
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
      parse_micromag_forc(small_file(bad), "bad.forc"),
      "bad.forc:14: 'x.1E-01,+5.0E-07' is not 'field,moment' with two finite numbers");
  bad = kData;
  bad.replace(bad.find("+1.0E-01,+5.0E-07"), 17, "+1.0E-01");
  EXPECT_HYST_ERROR(parse_micromag_forc(small_file(bad), "bad.forc"),
                    "bad.forc:14: '+1.0E-01' is not 'field,moment'");
  bad = kData;
  bad.replace(bad.find("+1.0E-01,+5.0E-07"), 17, "+1.0E-01,nan");
  EXPECT_HYST_ERROR(parse_micromag_forc(small_file(bad), "bad.forc"),
                    "bad.forc:14: '+1.0E-01,nan' is not 'field,moment' with two finite numbers");
  std::string truncated = small_file(kData);
  truncated.resize(truncated.find("MicroMag 2900/3900 Data File ends"));
  EXPECT_HYST_ERROR(parse_micromag_forc(truncated, "cut.forc"),
                    "cut.forc:20: the file ends without the line 'MicroMag 2900/3900 Data File "
                    "ends' (truncated?)");
  EXPECT_HYST_ERROR(parse_micromag_forc(small_file(kData, "7"), "n.forc"),
                    "n.forc:21: the header says NData = 7 but the file has 5 data points");
  bad = kData;
  bad.insert(0, "+2.0E-01,+1.0E-06\r\n");
  EXPECT_HYST_ERROR(parse_micromag_forc(small_file(bad, "6"), "cal.forc"),
                    "cal.forc:12: a calibration block has 2 points; expected 1");
  EXPECT_HYST_ERROR(
      parse_micromag_forc("MicroMag 2900/3900 Data File (Series 0015)\nFORC\nA = 1\n", "h.forc"),
      "h.forc:3: no 'NData = ...' line");
  EXPECT_HYST_ERROR(read_micromag_forc("/nonexistent/file.forc"),
                    "cannot open MicroMag FORC file '/nonexistent/file.forc'");
  auto zero = parse_micromag_forc(small_file(kData), "z.forc");
  zero.curves[1].calibration_moment = 0.0;
  EXPECT_HYST_ERROR(correct_drift(zero, ForcDriftCorrection::multiplicative),
                    "z.forc: calibration moment before curve 1 is 0");
}

}  // namespace
}  // namespace hyst::io
