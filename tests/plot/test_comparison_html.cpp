// The HTML page of a model comparison and the SVG figures in it: the table has one row per model
// (a failed one with its escaped reason), each fitted model has a curve in both figures, and
// invalid figures are rejected with a message naming the point.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/plot/comparison_html.hpp"
#include "hyst/plot/svg.hpp"

namespace hyst {
namespace {

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
    ++n;
  return n;
}

TEST(ComparisonHtml, TableAndBothFiguresWithOneCurvePerFittedModel) {
  // 40 samples: PI fits, the NARX network has too many weights for them.
  const auto v = test::random_walk(40, 3);
  const PrandtlIshlinskii pi({.thresholds = {0.0, 0.5}, .weights = {1.0, 0.5}});
  auto state = pi.initial_state();
  const auto y = simulate(pi, state, v);
  CompareOptions options;
  options.models = {"pi", "narx"};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, y, options);
  const auto html = plot::model_comparison_html(comparison, v, y, "PI <test> & more");

  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<h1>PI &lt;test&gt; &amp; more</h1>"), std::string::npos);
  EXPECT_EQ(count(html, "<table id=\"ranking\">"), 1u);
  EXPECT_EQ(count(html, "<tr class=\"fitted\"><td>1</td><td>pi</td>"), 1u);
  EXPECT_EQ(count(html, "<tr class=\"failed\"><td>-</td><td>narx</td>"), 1u);
  EXPECT_NE(html.find("failed: NARX fit:"), std::string::npos);
  EXPECT_EQ(count(html, "<svg "), 2u);
  // Loops: measured and pi; errors: pi.
  EXPECT_EQ(count(html, "<polyline class=\"series\" data-label=\"measured\""), 1u);
  EXPECT_EQ(count(html, "<polyline class=\"series\" data-label=\"pi\""), 2u);
  EXPECT_EQ(count(html, "<script"), 0u);  // self-contained, nothing to run
}

TEST(ComparisonHtml, SvgPointsLieInsideThePlotArea) {
  plot::Figure figure{.title = "line", .x_label = "x", .y_label = "y", .width = 400, .height = 300};
  figure.series.push_back({.label = "a", .x = {0.0, 1.0, 2.0}, .y = {0.0, 2.0, 1.0}});
  const auto text = plot::svg(figure);
  const auto begin = text.find("points=\"") + 8;
  const auto points = text.substr(begin, text.find('"', begin) - begin);
  std::size_t at = 0;
  int pairs = 0;
  while (at < points.size()) {
    const auto comma = points.find(',', at);
    const auto space = points.find(' ', comma);
    const double px = std::stod(points.substr(at, comma - at));
    const double py = std::stod(points.substr(comma + 1, space - comma - 1));
    // Plot area: x in [80, 400 - 170], y in [40, 300 - 55].
    EXPECT_GE(px, 80.0);
    EXPECT_LE(px, 230.0);
    EXPECT_GE(py, 40.0);
    EXPECT_LE(py, 245.0);
    ++pairs;
    at = space + 1;
  }
  EXPECT_EQ(pairs, 3);
}

TEST(ComparisonHtml, SvgRejectsInvalidFigures) {
  plot::Figure figure;
  EXPECT_HYST_ERROR(plot::svg(figure), "SVG figure: no series to draw");
  figure.series.push_back({.label = "a", .x = {0.0, 1.0}, .y = {0.0, NAN}});
  EXPECT_HYST_ERROR(plot::svg(figure), "series 0 'a' point [1] = (1, nan) is not finite");
  EXPECT_EQ(plot::xml_escaped("a<b & 'c'"), "a&lt;b &amp; &#39;c&#39;");
}

}  // namespace
}  // namespace hyst
