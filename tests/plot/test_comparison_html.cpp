// The HTML page of a model comparison and the SVG figures in it: the table has one row per model
// (a failed one with its escaped reason), each fitted model has a curve in both figures (drawn by
// gnuplot), and long curves are thinned so that the page stays small.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/plot/comparison_html.hpp"
#include "hyst/plot/gnuplot.hpp"

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
  // Two SVG figures drawn by gnuplot, each curve with its legend entry. Loops: measured and pi;
  // errors: pi.
  EXPECT_EQ(count(html, "<svg"), 2u);
  EXPECT_EQ(count(html, "<?xml"), 0u);  // inline elements, not documents
  EXPECT_EQ(count(html, "<text>measured</text>"), 1u);
  EXPECT_EQ(count(html, "<text>pi</text>"), 2u);
  EXPECT_EQ(count(html, "<script"), 0u);  // self-contained, nothing to run
}

// gnuplot's SVG of a figure: an <svg> element of the figure's size with one group per series;
// long curves are thinned for the page, so the loop of 40 000 samples stays small.
TEST(ComparisonHtml, FiguresAreGnuplotSvgOfBoundedSize) {
  plot::Figure figure{.title = "line", .x_label = "x", .y_label = "y", .width = 400, .height = 300};
  figure.series.push_back({.label = "a<b", .x = {0.0, 1.0, 2.0}, .y = {0.0, 2.0, 1.0}});
  const auto svg = plot::svg_element(figure);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("width=\"400\" height=\"300\""), std::string::npos);
  EXPECT_NE(svg.find("<g id=\"gnuplot_plot_1\""), std::string::npos);
  EXPECT_EQ(svg.find("<g id=\"gnuplot_plot_2\""), std::string::npos);
  EXPECT_EQ(count(svg, "<text>a&lt;b</text>"), 1u);

  const auto v = test::random_walk(40000, 5);
  const PrandtlIshlinskii pi({.thresholds = {0.0, 0.5}, .weights = {1.0, 0.5}});
  auto state = pi.initial_state();
  const auto y = simulate(pi, state, v);
  CompareOptions options;
  options.models = {"pi"};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, y, options);
  const auto html = plot::model_comparison_html(comparison, v, y, "long record");
  // 10 000 held-out samples per curve, 3 curves: about 40 bytes per point unthinned.
  EXPECT_LT(html.size(), 400'000u);
  EXPECT_EQ(count(html, "<text>measured</text>"), 1u);
  EXPECT_EQ(count(html, "<text>pi</text>"), 2u);

  plot::Figure empty;
  EXPECT_HYST_ERROR(plot::svg_element(empty), "figure has no series to plot");
}

}  // namespace
}  // namespace hyst
