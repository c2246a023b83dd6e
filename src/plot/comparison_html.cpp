#include "hyst/plot/comparison_html.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "hyst/io/atomic_file.hpp"
#include "hyst/plot/comparison_plots.hpp"
#include "hyst/plot/gnuplot.hpp"

namespace hyst::plot {
namespace {

// Curves longer than this are thinned for the page (evenly spaced points): the page stays small,
// and a loop drawn with 2000 points looks the same as one drawn with 40 000.
constexpr std::size_t kMaxPagePoints = 2000;

std::string xml_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::vector<double> every_nth(const std::vector<double>& values, std::size_t stride) {
  std::vector<double> kept;
  for (std::size_t k = 0; k < values.size(); k += stride)
    kept.push_back(values[k]);
  if ((values.size() - 1) % stride != 0) kept.push_back(values.back());  // keep the last point
  return kept;
}

//! The figure as an SVG element drawn by gnuplot, its curves thinned to kMaxPagePoints.
std::string page_svg(Figure figure) {
  for (auto& series : figure.series) {
    if (series.x.size() <= kMaxPagePoints) continue;
    const std::size_t stride = (series.x.size() + kMaxPagePoints - 1) / kMaxPagePoints;
    series.x = every_nth(series.x, stride);
    series.y = every_nth(series.y, stride);
  }
  return svg_element(figure);
}

std::string table(const ModelComparison& comparison) {
  std::string html =
      "<table id=\"ranking\">\n<thead><tr><th>rank</th><th>model</th><th>validation NRMSE "
      "[%]</th><th>validation RMSE</th><th>max error</th><th>beats yardstick</th>"
      "<th>parameters</th><th>fit time [s]</th><th>simulation [ns/sample]</th><th>status</th>"
      "</tr></thead>\n<tbody>\n";
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      html += fmt::format(
          "<tr class=\"fitted\"><td>{}</td><td>{}</td><td>{:.4g}</td><td>{:.4g}</td><td>{:.4g}"
          "</td><td>{}</td><td>{}</td><td>{:.3g}</td><td>{:.3g}</td><td>{}</td></tr>\n",
          ++rank, xml_escaped(row.model), row.validation.nrmse_percent, row.validation.rmse,
          row.validation.max_error, row.beats_yardstick ? "yes" : "no", row.parameters,
          row.fit_seconds, row.ns_per_sample, xml_escaped(row.report->status()));
    } else {
      html += fmt::format(
          "<tr class=\"failed\"><td>-</td><td>{}</td><td colspan=\"7\"></td><td>failed: {}</td>"
          "</tr>\n",
          xml_escaped(row.model), xml_escaped(row.error));
    }
  }
  return html + "</tbody>\n</table>\n";
}

}  // namespace

std::string model_comparison_html(const ModelComparison& comparison, std::span<const double> input,
                                  std::span<const double> output, const std::string& title) {
  std::string html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{0}</title>\n"
      "<style>body{{font-family:sans-serif;margin:2em}}table{{border-collapse:collapse}}"
      "td,th{{border:1px solid #aaa;padding:3px 8px;text-align:right}}"
      "td:nth-child(2),td:last-child{{text-align:left}}tr.failed{{color:#a00}}"
      "figure{{margin:1.5em "
      "0}}h1{{overflow-wrap:anywhere}}</style>\n</head>\n<body>\n<h1>{0}</h1>\n"
      "<p>Every model was fitted on samples {1}..{2} and run in free run over the whole record; "
      "the ranking is by the NRMSE on the held-out samples {3}..{4}.</p>\n",
      xml_escaped(title), comparison.split.fit_begin, comparison.split.fit_end - 1,
      comparison.split.validation_begin, comparison.split.validation_end - 1);
  if (const auto verdict = no_fit_line(comparison); !verdict.empty()) {
    html += fmt::format("<p id=\"no-fit\"><strong>{}</strong></p>\n", xml_escaped(verdict));
  }
  html += fmt::format("<p id=\"yardstick\">{}</p>\n", xml_escaped(yardstick_line(comparison)));
  html += table(comparison);
  const bool any_fitted = std::any_of(comparison.ranking.begin(), comparison.ranking.end(),
                                      [](const ComparedModel& row) { return row.ok; });
  if (any_fitted) {
    html += "<figure id=\"loops\">\n" +
            page_svg(model_comparison_loop_figure(comparison, input, output)) +
            "<figcaption>Held-out part: measured and simulated loops.</figcaption>\n</figure>\n";
    html += "<figure id=\"errors\">\n" +
            page_svg(model_comparison_error_figure(comparison, output)) +
            "<figcaption>Held-out part: error measured - simulated.</figcaption>\n</figure>\n";
  }
  return html + "</body>\n</html>\n";
}

void write_model_comparison_html(const std::filesystem::path& path,
                                 const ModelComparison& comparison, std::span<const double> input,
                                 std::span<const double> output, const std::string& title) {
  io::write_file_atomically(path, model_comparison_html(comparison, input, output, title));
}

}  // namespace hyst::plot
