// The aixACCT aixPlorer export reader: the measured file (cross-checked against the instrument's
// own figures in its metadata and summary) and malformed texts naming file, line, table, column.

#include "hyst/io/aixacct.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"

namespace hyst::io {
namespace {

const char* const kFile = HYST_SHARED_DATA_DIR "/piezo_pzt_aixacct_butterfly/RMN_TRAP_SLOW.dat";

TEST(Aixacct, ReadsTheMeasuredExport) {
  const auto file = read_aixacct(kFile);
  EXPECT_EQ(file.kind, "PiezoResult");
  ASSERT_EQ(file.titles.size(), 1U);
  EXPECT_EQ(file.titles[0], "Piezo");
  ASSERT_FALSE(file.header.empty());
  EXPECT_EQ(file.header[0].first, "Program");
  EXPECT_EQ(file.header[0].second, "aixPlorer Software version 3.0.44.0");

  // Summary: one row per measurement, 34 columns ("Table No [#]" ... "Delay [s]").
  ASSERT_TRUE(file.summary.has_value());
  EXPECT_EQ(file.summary->columns.size(), 34U);
  EXPECT_EQ(file.summary->rows(), 10U);
  EXPECT_EQ(file.summary->columns[0].name, "Table No");
  EXPECT_EQ(file.summary->columns[0].unit, "#");
  EXPECT_EQ(file.summary->columns.back().header(), "Delay [s]");
  EXPECT_EQ(file.summary->column("Current Range").unit, "");

  // Ten measurement tables of 401 rows and 13 columns (PROVENANCE.md).
  ASSERT_EQ(file.measurements.size(), 10U);
  const auto& summary_table = file.summary->column("Table No").values;
  const auto& summary_vmax = file.summary->column("Vmax+ [V]").values;
  for (std::size_t j = 0; j < file.measurements.size(); ++j) {
    const auto& table = file.measurements[j];
    SCOPED_TRACE(table.number);
    EXPECT_EQ(table.number, j + 1);
    EXPECT_EQ(table.rows(), 401U);
    ASSERT_EQ(table.columns.size(), 13U);
    EXPECT_EQ(summary_table[j], static_cast<double>(table.number));
    // The instrument's own Vmax+ (metadata, 6 digits, and summary) is the column's maximum.
    const auto& voltage = table.column("V+ [V]").values;
    const double peak = *std::max_element(voltage.begin(), voltage.end());
    EXPECT_NEAR(peak, *table.metadata_number("Vmax+ [V]"), 0.01);
    EXPECT_NEAR(peak, summary_vmax[j], 0.01);
  }

  const auto& first = file.measurement(1);
  EXPECT_EQ(first.first_line, 25U);
  EXPECT_EQ(first.metadata_text("SampleName"), "TEST_0.1Hz");
  EXPECT_EQ(first.metadata_text("Timestamp"), "08/23/2019 14:17:12");
  EXPECT_EQ(first.metadata_number("Hysteresis Frequency [Hz]"), 0.1);
  EXPECT_EQ(first.metadata_number("Thickness [nm]"), 800000.0);
  EXPECT_FALSE(first.metadata_number("Waveform").has_value());  // "triangle"
  EXPECT_FALSE(first.metadata_text("No such key").has_value());
  EXPECT_EQ(first.columns[0].header(), "Time [s]");
  EXPECT_EQ(first.column("P1").unit, "uC/cm2");
  // Values as printed in the file (lines 83, 84, 483).
  EXPECT_EQ(first.column("V+").values[0], 79.04505);
  EXPECT_EQ(first.column("D1").values[1], -11.78029);
  EXPECT_EQ(first.column("Time").values[400], 10.0);
  // The sample period is the one PROVENANCE.md gives for 0.1 Hz: 0.025 s.
  EXPECT_DOUBLE_EQ(first.column("Time").values[1], 0.025);
  // Table 7 has an extra "Error: underflow" metadata line.
  EXPECT_EQ(file.measurement(7).metadata_text("Error"), "underflow");

  const auto table = first.to_table("t1");
  EXPECT_EQ(table.names[1], "V+ [V]");
  EXPECT_EQ(table.rows(), 401U);
  EXPECT_HYST_ERROR(file.measurement(11), "no measurement table 11 (tables: 1, 2, 3");
  EXPECT_HYST_ERROR(first.column("V3", file.source), "table 1: no column 'V3' (columns: Time [s]");
}

constexpr std::string_view kSmall =
    "PiezoResult\n"
    "\n"
    "Table 1\n"
    "Table No [#]\tVc+ [V]\t\n"
    "1\t2.5e+002\t\n"
    "\n"
    "Piezo\n"
    "Program: x\n"
    "\n"
    "Table 1\n"
    "SampleName: A\n"
    "Time [s]\tV+ [V]\tD1 [nm]\t\n"
    "0\t1\t+2\t\n"
    "1.0e-003\t-1\t3\t\n";

TEST(Aixacct, ParsesASmallExport) {
  const auto file = parse_aixacct(kSmall, "small.dat");
  ASSERT_TRUE(file.summary);
  EXPECT_EQ(file.summary->column("Vc+").values[0], 250.0);
  ASSERT_EQ(file.measurements.size(), 1U);
  const auto& table = file.measurements[0];
  EXPECT_EQ(table.rows(), 2U);
  EXPECT_EQ(table.column("D1").values[0], 2.0);
  EXPECT_EQ(table.column("Time [s]").values[1], 0.001);
  // CRLF line ends read the same.
  std::string crlf;
  for (const char c : kSmall) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  EXPECT_EQ(parse_aixacct(crlf, "crlf.dat").measurements[0].column("V+").values[1], -1.0);
  // A single column: its header is recognised by the trailing tab.
  const auto single = parse_aixacct("XResult\n\nT\nTable 1\nA: b\nTime [s]\t\n1\t\n2\t\n", "x");
  ASSERT_EQ(single.measurements.size(), 1U);
  EXPECT_EQ(single.measurements[0].column("Time").values[1], 2.0);
  EXPECT_TRUE(looks_like_aixacct(kSmall));
  EXPECT_FALSE(looks_like_aixacct("t,v\n1,2\n"));
  EXPECT_FALSE(looks_like_aixacct("PiezoResult\n\nt,v\n"));
}

std::string replaced(std::string_view from, std::string_view to) {
  std::string text(kSmall);
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(Aixacct, ErrorsNameFileLineTableAndColumn) {
  EXPECT_HYST_ERROR(parse_aixacct(replaced("-1\t3", "-1\tabc"), "s.dat"),
                    "s.dat:14: table 1: column 3 ('D1 [nm]'): 'abc' is not a finite number");
  EXPECT_HYST_ERROR(parse_aixacct(replaced("-1\t3", "-1\tnan"), "s.dat"), "'nan' is not a finite");
  EXPECT_HYST_ERROR(parse_aixacct(replaced("-1\t3\t", "-1"), "s.dat"),
                    "s.dat:14: table 1: row has 2 fields but the header has 3");
  EXPECT_HYST_ERROR(parse_aixacct(replaced("1\t2.5e+002", "1\tx"), "s.dat"),
                    "s.dat:5: table 1 (summary): column 2 ('Vc+ [V]')");
  EXPECT_HYST_ERROR(parse_aixacct(replaced("PiezoResult", "Hello world"), "s.dat"),
                    "s.dat:1: not an aixACCT export");
  EXPECT_HYST_ERROR(parse_aixacct(replaced("SampleName: A", "SampleName A"), "s.dat"),
                    "s.dat:11: table 1: 'SampleName A' is neither 'key: value' metadata");
  EXPECT_HYST_ERROR(parse_aixacct(replaced("Time [s]\tV+ [V]", "Time [s]\tTime [s]"), "s.dat"),
                    "column 2 ('Time [s]') has the same name as column 1");
  EXPECT_HYST_ERROR(parse_aixacct(std::string(kSmall) + "\nTable 1\nTime [s]\tx\n1\t2\n", "s.dat"),
                    "s.dat:16: table 1: table number 1 was already used on line 10");
  EXPECT_HYST_ERROR(parse_aixacct(std::string(kSmall) + "\nTable 2\nA: b\n", "s.dat"),
                    "table 2: the table ends before its column header line");
  EXPECT_HYST_ERROR(parse_aixacct(std::string(kSmall) + "\nTable 2\nTime [s]\tx\n", "s.dat"),
                    "s.dat:16: table 2: the table has a column header but no data rows");
  EXPECT_HYST_ERROR(parse_aixacct("PiezoResult\n\nPiezo\nA: b\n", "s.dat"),
                    "s.dat: the file has no measurement table");
  EXPECT_HYST_ERROR(read_aixacct("/nonexistent/x.dat"), "/nonexistent/x.dat");
}

}  // namespace
}  // namespace hyst::io
