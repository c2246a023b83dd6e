// The HTML page of a model comparison: the table has one row per model (a failed one with its
// escaped reason); the page's data holds the whole record and each fitted model's free run,
// thinned for long records; Chart.js and the page's script are inline. What the page does in a
// browser is tested by ctest cli_compare_html (headless Chromium).

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

#include <nlohmann/json.hpp>

namespace hyst {
namespace {

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
    ++n;
  return n;
}

//! The JSON of <script id="comparison-data">.
nlohmann::json page_data(const std::string& html) {
  const std::string open = "<script id=\"comparison-data\" type=\"application/json\">";
  const auto begin = html.find(open);
  EXPECT_NE(begin, std::string::npos);
  const auto end = html.find("</script>", begin);
  return nlohmann::json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

TEST(ComparisonHtml, TableFiguresAndTheDataOfEveryFittedModel) {
  // 40 samples: PI fits, the NARX network has too many weights for them.
  const auto v = test::random_walk(40, 3);
  const PrandtlIshlinskii pi({.thresholds = {0.0, 0.5}, .weights = {1.0, 0.5}});
  auto state = pi.initial_state();
  const auto y = simulate(pi, state, v);
  CompareOptions options;
  options.models = {"pi", "narx"};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, y, options);
  std::vector<double> time;
  for (std::size_t k = 0; k < v.size(); ++k)
    time.push_back(0.5 + 0.01 * static_cast<double>(k));
  const auto html = plot::model_comparison_html(
      comparison, v, y, "PI <test> & more",
      {.input = "V+ [V]", .output = "y </script> [m]", .output_unit = "m", .time = time});

  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<h1>PI &lt;test&gt; &amp; more</h1>"), std::string::npos);
  EXPECT_EQ(count(html, "<table id=\"ranking\">"), 1u);
  EXPECT_EQ(count(html, "<tr class=\"fitted\"><td>1</td><td>pi</td>"), 1u);
  EXPECT_EQ(count(html, "<tr class=\"failed\"><td>-</td><td>narx</td>"), 1u);
  EXPECT_NE(html.find("failed: NARX fit:"), std::string::npos);
  for (const std::string id : {"loops", "outputs", "errors"}) {
    EXPECT_EQ(count(html, "<figure id=\"" + id + "\">"), 1u) << id;
  }
  EXPECT_EQ(count(html, "<canvas>"), 3u);
  EXPECT_EQ(count(html, "<svg"), 0u);
  // Chart.js, the page's script and its data are inline: nothing is fetched.
  EXPECT_NE(html.find("Chart.js v3"), std::string::npos);
  EXPECT_NE(html.find("heldOutShading"), std::string::npos);
  EXPECT_EQ(count(html, " src="), 0u);
  EXPECT_EQ(count(html, "y </script> [m]"), 0u);  // a label cannot end the data's element
  // The error columns carry the output's unit.
  EXPECT_EQ(count(html, "<th>validation RMSE [m]</th><th>max error [m]</th>"), 1u);

  const auto data = page_data(html);
  EXPECT_EQ(data["input_label"], "V+ [V]");
  EXPECT_EQ(data["output_label"], "y </script> [m]");
  EXPECT_EQ(data["validation_begin"], comparison.split.validation_begin);
  EXPECT_EQ(data["sample"].size(), 40u);  // the whole record, not only the held-out part
  EXPECT_EQ(data["input"].get<std::vector<double>>(), v);
  EXPECT_EQ(data["measured"].get<std::vector<double>>(), y);
  ASSERT_EQ(data["models"].size(), 1u);  // the failed NARX has no curve
  EXPECT_EQ(data["models"][0]["name"], "pi");
  EXPECT_EQ(data["models"][0]["simulated"].get<std::vector<double>>(),
            comparison.ranking[0].simulated);
  // The time axis, and where the held-out part starts on it.
  EXPECT_EQ(data["time"].get<std::vector<double>>(), time);
  EXPECT_EQ(data["validation_begin_time"], time[comparison.split.validation_begin]);
  EXPECT_EQ(data["output_unit"], "m");
  EXPECT_EQ(data["shown"], plot::kComparisonPageShownModels);
  // Without a time axis, none; a time axis of another length is refused.
  EXPECT_FALSE(page_data(plot::model_comparison_html(comparison, v, y, "t")).contains("time"));
  plot::ComparisonPageLabels short_time;
  short_time.time = time;
  short_time.time.pop_back();
  EXPECT_THROW(plot::model_comparison_html(comparison, v, y, "t", short_time), Error);
}

// Long records are thinned to evenly spaced samples, the last one kept, so the page stays small.
TEST(ComparisonHtml, LongRecordsAreThinnedForThePage) {
  const auto v = test::random_walk(40001, 5);
  const PrandtlIshlinskii pi({.thresholds = {0.0, 0.5}, .weights = {1.0, 0.5}});
  auto state = pi.initial_state();
  const auto y = simulate(pi, state, v);
  CompareOptions options;
  options.models = {"pi"};
  options.timing_seconds = 0.0;
  const auto comparison = compare_models(v, y, options);
  const auto html = plot::model_comparison_html(comparison, v, y, "long record");
  const auto data = page_data(html);
  const auto samples = data["sample"].get<std::vector<std::size_t>>();
  ASSERT_LE(samples.size(), 2001u);
  EXPECT_EQ(samples.front(), 0u);
  EXPECT_EQ(samples.back(), 40000u);
  EXPECT_EQ(samples[1] - samples[0], samples[2] - samples[1]);
  EXPECT_EQ(data["input"][1], v[samples[1]]);
  EXPECT_LT(html.size(), 600'000u);  // Chart.js is about 200 kB of it
}

// gnuplot's SVG of a figure (the static figures for papers): an <svg> element of the figure's
// size with one group per series.
TEST(ComparisonHtml, StaticFiguresAreGnuplotSvg) {
  plot::Figure figure{.title = "line", .x_label = "x", .y_label = "y", .width = 400, .height = 300};
  figure.series.push_back({.label = "a<b", .x = {0.0, 1.0, 2.0}, .y = {0.0, 2.0, 1.0}});
  const auto svg = plot::svg_element(figure);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("width=\"400\" height=\"300\""), std::string::npos);
  EXPECT_NE(svg.find("<g id=\"gnuplot_plot_1\""), std::string::npos);
  EXPECT_EQ(svg.find("<g id=\"gnuplot_plot_2\""), std::string::npos);
  EXPECT_EQ(count(svg, "<text>a&lt;b</text>"), 1u);
  plot::Figure empty;
  EXPECT_HYST_ERROR(plot::svg_element(empty), "figure has no series to plot");
}

}  // namespace
}  // namespace hyst
