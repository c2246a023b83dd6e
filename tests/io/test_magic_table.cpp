// The MagIC table reader and its hysteresis loops: the measured PmagPy example (loop sizes from
// PROVENANCE.md, the row count from a plain text scan), MagIC 3 column names, and malformed
// tables.

#include "hyst/io/magic_table.hpp"

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"

namespace hyst::io {
namespace {

const char* const kMagicFile =
    HYST_SHARED_DATA_DIR "/pmagpy_forc_micromag_agm/hysteresis_magic_example.dat";

TEST(MagicTable, PmagpyExampleGivesEightLoops) {
  const auto table = read_magic_table(kMagicFile);
  EXPECT_EQ(table.name, "magic_measurements");
  EXPECT_EQ(table.columns.size(), 16u);
  EXPECT_EQ(table.rows.size(), 3516u);  // PROVENANCE.md
  EXPECT_EQ(table.row_lines.front(), 3u);

  const auto loops = magic_hysteresis_loops(table);
  ASSERT_EQ(loops.size(), 8u);
  EXPECT_EQ(loops[0].specimen, "IS06a-1");
  EXPECT_EQ(loops[0].experiment, "IS06a-1:LP-HYS");
  EXPECT_EQ(loops[0].field.size(), 283u);
  EXPECT_EQ(loops[0].first_line, 3u);
  // The first row as printed in the file: field 1.196e+00, moment 6.298e+01.
  EXPECT_EQ(loops[0].field[0], 1.196);
  EXPECT_EQ(loops[0].moment[0], 62.98);
  for (std::size_t k = 1; k < loops.size(); ++k) {
    EXPECT_EQ(loops[k].field.size(), 403u) << loops[k].specimen;
    EXPECT_EQ(loops[k].moment.size(), 403u);
  }
  EXPECT_EQ(loops.back().specimen, "IS06a-9");

  // Second count: lines whose method-code cell is LP-HYS, by a plain text scan.
  std::ifstream stream(kMagicFile);
  std::string line;
  std::size_t loop_rows = 0;
  while (std::getline(stream, line))
    loop_rows += line.find("\tLP-HYS\t") != std::string::npos;
  std::size_t read_rows = 0;
  for (const auto& loop : loops)
    read_rows += loop.field.size();
  EXPECT_EQ(read_rows, loop_rows);
}

TEST(MagicTable, Magic3NamesAndCombinedMethodCodes) {
  const auto table = parse_magic_table(
      "tab\tmeasurements\n"
      "specimen\texperiment\tmethod_codes\tmeas_field_dc\tmagn_moment\n"
      "s1\ts1-hys\tLP-HYS:FS-FD\t1.0\t2.0\n"
      "s1\ts1-dcd\tLP-IRM-DCD\t0.0\t1.5\n"
      "s1\ts1-hys\tLP-HYS:FS-FD\t-1.0\t-2.0\n"
      "s2\ts2-hys\tLP-HYS\t0.5\t0.25\t\t\n",
      "m3.txt");
  EXPECT_EQ(table.name, "measurements");
  const auto loops = magic_hysteresis_loops(table);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_EQ(loops[0].field, (std::vector<double>{1.0, -1.0}));
  EXPECT_EQ(loops[0].moment, (std::vector<double>{2.0, -2.0}));
  EXPECT_EQ(loops[1].specimen, "s2");
  EXPECT_EQ(loops[1].first_line, 6u);
}

TEST(MagicTable, MalformedTablesNameFileLineAndColumn) {
  EXPECT_HYST_ERROR(parse_magic_table("a,b\n1,2\n", "x.dat"), "x.dat:1: not a MagIC table");
  EXPECT_HYST_ERROR(parse_magic_table("tab\tmeasurements\n", "x.dat"),
                    "x.dat:2: no column names after the table name");
  EXPECT_HYST_ERROR(parse_magic_table("tab\tmeasurements\na\tb\ta\n", "x.dat"),
                    "x.dat:2: column 'a' appears twice");
  EXPECT_HYST_ERROR(parse_magic_table("tab\tmeasurements\na\tb\n1\t2\t3\n", "x.dat"),
                    "x.dat:3: 3 cells, but the table has 2 columns");
  const std::string header =
      "tab\tmeasurements\nspecimen\texperiment\tmethod_codes\tmeas_field_dc\tmagn_moment\n";
  EXPECT_HYST_ERROR(
      magic_hysteresis_loops(parse_magic_table(header + "s\te\tLP-HYS\t1\tabc\n", "x.dat")),
      "x.dat:3: column 'magn_moment': 'abc' is not a finite number");
  EXPECT_HYST_ERROR(
      magic_hysteresis_loops(parse_magic_table(header + "s\te\tLP-HYS\t\t1\n", "x.dat")),
      "x.dat:3: column 'meas_field_dc': '' is not a finite number");
  EXPECT_HYST_ERROR(magic_hysteresis_loops(parse_magic_table(
                        "tab\tmeasurements\nspecimen\texperiment\tmethod_codes\n", "x.dat")),
                    "x.dat: no column for the applied field (looked for "
                    "'measurement_lab_field_dc' or 'meas_field_dc')");
  // Rows of other experiments are not read as numbers.
  EXPECT_TRUE(
      magic_hysteresis_loops(parse_magic_table(header + "s\te\tLP-DIR\tx\ty\n", "x.dat")).empty());
  EXPECT_HYST_ERROR(read_magic_table("no_such_file.dat"), "no_such_file.dat");
}

}  // namespace
}  // namespace hyst::io
