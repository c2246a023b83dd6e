#include "hyst/plot/heat_map.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/temp_folder_test.hpp"
#include "hyst/plot/gnuplot.hpp"

namespace hyst::plot {
namespace {

namespace fs = std::filesystem;

class HeatMapTest : public test::TempFolderTest {
 protected:
  // A Gaussian bump on a 30 x 20 grid, the upper-left triangle blank (NaN), as a FORC diagram's
  // region alpha < beta is.
  static HeatMap bump() {
    HeatMap map{.title = "a 'quoted' title, Hc_mT",
                .x_label = "x",
                .y_label = "y",
                .z_label = "z [1/mT^2]"};
    for (int i = 0; i < 30; ++i)
      map.x.push_back(0.5 * i);
    for (int j = 0; j < 20; ++j)
      map.y.push_back(-5.0 + 0.5 * j);
    for (const double y : map.y) {
      for (const double x : map.x) {
        map.z.push_back(y > x ? std::numeric_limits<double>::quiet_NaN()
                              : std::exp(-0.1 * ((x - 5) * (x - 5) + y * y)));
      }
    }
    return map;
  }
};

TEST_F(HeatMapTest, WritesPngAndSvgAndLeavesNoTemporaryFile) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  write_png(bump(), dir_ / "map.png");
  write_svg(bump(), dir_ / "map.svg");
  const auto png = slurp(dir_ / "map.png");
  ASSERT_GE(png.size(), 1000u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const auto svg = slurp(dir_ / "map.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("z [1/mT^2]"), std::string::npos);  // the colour bar label, literally
  EXPECT_EQ(entries(), (std::vector<std::string>{"map.png", "map.svg"}));
}

TEST_F(HeatMapTest, DrawsASingleCellAndAConstantMap) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  write_png({.x = {1}, .y = {2}, .z = {3}, .width = 200, .height = 150}, dir_ / "one.png");
  write_png({.x = {1, 2}, .y = {2, 3}, .z = {-1, -1, -1, -1}}, dir_ / "flat.png");
  EXPECT_EQ(entries(), (std::vector<std::string>{"flat.png", "one.png"}));
}

TEST_F(HeatMapTest, RejectsInvalidMapsNamingTheField) {
  auto map = bump();
  map.z.pop_back();
  EXPECT_HYST_ERROR(write_png(map, dir_ / "p.png"),
                    "heat map z has 599 values but x.size() * y.size() = 30 * 20 = 600");
  map = bump();
  map.x[4] = map.x[3];
  EXPECT_HYST_ERROR(write_png(map, dir_ / "p.png"), "heat map x[4] = 1.5 must be above x[3]");
  map = bump();
  map.y[2] = std::numeric_limits<double>::infinity();
  EXPECT_HYST_ERROR(write_png(map, dir_ / "p.png"), "heat map y[2] = inf is not finite");
  map = bump();
  map.z[7] = -std::numeric_limits<double>::infinity();
  EXPECT_HYST_ERROR(write_png(map, dir_ / "p.png"), "heat map z[7] = -inf is infinite");
  map = bump();
  for (auto& z : map.z)
    z = std::numeric_limits<double>::quiet_NaN();
  EXPECT_HYST_ERROR(write_png(map, dir_ / "p.png"), "heat map z has no finite value");
  EXPECT_HYST_ERROR(write_png(HeatMap{}, dir_ / "p.png"), "heat map x has no cell centres");
  map = bump();
  map.width = 10;
  EXPECT_HYST_ERROR(write_svg(map, dir_ / "p.svg"), "figure size 10 x 700 pixels");
  std::ofstream(dir_ / "file") << "x";
  EXPECT_HYST_ERROR(write_png(bump(), dir_ / "file" / "p.png"), "is not a folder");
  EXPECT_EQ(entries(), std::vector<std::string>{"file"});
}

}  // namespace
}  // namespace hyst::plot
