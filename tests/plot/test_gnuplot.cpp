#include "hyst/plot/gnuplot.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/temp_folder_test.hpp"

namespace hyst::plot {
namespace {

namespace fs = std::filesystem;

class GnuplotTest : public test::TempFolderTest {
 protected:
  // A loop: y = sin, x = cos, plus a second series with points.
  static Figure loop_figure() {
    Figure figure{.title = "a 'quoted' title with \"double\" quotes, Vplus_19kv, 50% & {x}",
                  .x_label = "v [V]",
                  .y_label = "y [nm]\nsecond line"};
    Series circle{.label = "measured's", .style = Series::Style::lines};
    Series dots{.label = "", .style = Series::Style::points};
    for (int k = 0; k <= 200; ++k) {
      const double phase = 2 * M_PI * k / 200.0;
      circle.x.push_back(std::cos(phase));
      circle.y.push_back(std::sin(phase));
      if (k % 10 == 0) {
        dots.x.push_back(0.5 * std::cos(phase));
        dots.y.push_back(0.5 * std::sin(phase));
      }
    }
    figure.series = {circle, dots};
    return figure;
  }
};

constexpr char kPngSignature[] = "\x89PNG\r\n\x1a\n";

TEST_F(GnuplotTest, WritesAPngAndLeavesNoTemporaryFile) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path png = dir_ / "loop.png";
  auto figure = loop_figure();
  figure.equal_axes = true;
  figure.series.push_back({.label = "line & points",
                           .x = {-1, 0, 1},
                           .y = {-1, 0.2, 1},
                           .style = Series::Style::lines_points,
                           .color = "#d95f02"});
  write_png(figure, png);
  const auto content = slurp(png);
  ASSERT_GE(content.size(), 1000u);
  EXPECT_EQ(content.substr(0, 8), std::string(kPngSignature, 8));
  EXPECT_EQ(entries(), std::vector<std::string>{"loop.png"});
}

TEST_F(GnuplotTest, ReplacesAnExistingFile) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path png = dir_ / "p.png";
  std::ofstream(png) << "old";
  write_png({.series = {{.label = "one point", .x = {1}, .y = {2}}}, .width = 320, .height = 200},
            png);
  EXPECT_EQ(slurp(png).substr(0, 8), std::string(kPngSignature, 8));
  EXPECT_EQ(entries(), std::vector<std::string>{"p.png"});
}

TEST_F(GnuplotTest, RejectsColoursThatWouldBreakTheScript) {
  Figure figure = loop_figure();
  figure.series.push_back({.label = "model", .x = {1, 2}, .y = {1, 2}, .color = "red' lw 9"});
  EXPECT_HYST_ERROR(write_png(figure, dir_ / "p.png"),
                    "series 2 ('model'): colour 'red' lw 9' must be \"#rrggbb\" or a gnuplot");
  EXPECT_TRUE(entries().empty());
}

TEST_F(GnuplotTest, RejectsMismatchedSeriesNamingIt) {
  Figure figure = loop_figure();
  figure.series.push_back({.label = "model", .x = {1, 2, 3}, .y = {1, 2}});
  EXPECT_HYST_ERROR(write_png(figure, dir_ / "p.png"),
                    "series 2 ('model'): x has 3 values but y has 2");
  EXPECT_TRUE(entries().empty());
}

TEST_F(GnuplotTest, RejectsNonFiniteValuesWithTheirIndex) {
  Figure figure = loop_figure();
  figure.series[1].y[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_HYST_ERROR(write_png(figure, dir_ / "p.png"), "series 1: y[3] = nan is not finite");
  figure = loop_figure();
  figure.series[0].x[7] = std::numeric_limits<double>::infinity();
  EXPECT_HYST_ERROR(write_png(figure, dir_ / "p.png"),
                    "series 0 ('measured's'): x[7] = inf is not finite");
  EXPECT_TRUE(entries().empty());
}

TEST_F(GnuplotTest, RejectsEmptyFiguresAndSeriesAndBadSizes) {
  EXPECT_HYST_ERROR(write_png(Figure{}, dir_ / "p.png"), "figure has no series");
  EXPECT_HYST_ERROR(write_png({.series = {{.label = "empty"}}}, dir_ / "p.png"),
                    "series 0 ('empty') has no points");
  Figure figure = loop_figure();
  figure.width = 0;
  EXPECT_HYST_ERROR(write_png(figure, dir_ / "p.png"), "figure size 0 x 650 pixels");
}

TEST_F(GnuplotTest, RejectsAFileAsFolder) {
  std::ofstream(dir_ / "file") << "x";
  EXPECT_HYST_ERROR(write_png(loop_figure(), dir_ / "file" / "p.png"),
                    "'" + (dir_ / "file").string() + "' is not a folder");
  EXPECT_HYST_ERROR(write_png(loop_figure(), dir_ / "file" / "sub" / "p.png"), "is not a folder");
  EXPECT_HYST_ERROR(write_png(loop_figure(), dir_ / ".."), "does not name a file");
  EXPECT_EQ(entries(), std::vector<std::string>{"file"});
}

TEST_F(GnuplotTest, ReportsGnuplotMissingFromThePath) {
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path ? old_path : "";
  ::setenv("PATH", dir_.c_str(), 1);
  const bool available = gnuplot_available();
  std::string message;
  try {
    write_png(loop_figure(), dir_ / "p.png");
  } catch (const Error& error) {
    message = error.what();
  }
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_FALSE(available);
  EXPECT_NE(message.find("gnuplot is not installed or not on the PATH"), std::string::npos)
      << message;
  EXPECT_TRUE(entries().empty());
}

TEST_F(GnuplotTest, ReportsGnuplotFailureWithItsMessages) {
  // A fake gnuplot that complains and fails, first on the PATH.
  const fs::path fake = dir_ / "gnuplot";
  std::ofstream(fake) << "#!/bin/sh\ncat > /dev/null\necho 'line 3: something broke' >&2\n"
                         "exit 3\n";
  fs::permissions(fake, fs::perms::owner_all);
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path ? old_path : "";
  ::setenv("PATH", (dir_.string() + ":" + saved).c_str(), 1);
  std::string message;
  try {
    write_png(loop_figure(), dir_ / "p.png");
  } catch (const Error& error) {
    message = error.what();
  }
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_NE(message.find("gnuplot failed (exit status 3): line 3: something broke"),
            std::string::npos)
      << message;
  EXPECT_EQ(entries(), std::vector<std::string>{"gnuplot"});
}

}  // namespace
}  // namespace hyst::plot
