#include "hyst/plot/comparison_html.hpp"

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "comparison_page_script.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/xml_text.hpp"

namespace hyst::plot {
namespace {

// Curves longer than this are thinned for the page (evenly spaced points): the page stays small,
// and a loop drawn with 2000 points looks the same as one drawn with 40 000.
constexpr std::size_t kMaxPagePoints = 2000;

//! Every stride-th sample number of n, and the last: the points a page draws.
std::vector<std::size_t> page_samples(std::size_t n) {
  const std::size_t stride = std::max<std::size_t>(1, (n + kMaxPagePoints - 1) / kMaxPagePoints);
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < n; k += stride)
    kept.push_back(k);
  if (n > 0 && kept.back() != n - 1) kept.push_back(n - 1);
  return kept;
}

std::vector<double> at(std::span<const double> values, const std::vector<std::size_t>& samples) {
  std::vector<double> kept;
  kept.reserve(samples.size());
  for (const auto k : samples)
    kept.push_back(values[k]);
  return kept;
}

//! The page's data: the whole record and every fitted model's free run, thinned alike.
std::string page_data(const ModelComparison& comparison, std::span<const double> input,
                      std::span<const double> output, const ComparisonPageLabels& labels) {
  const auto samples = page_samples(input.size());
  if (!labels.time.empty() && labels.time.size() != input.size()) {
    throw Error(
        fmt::format("comparison page: {} times for {} samples", labels.time.size(), input.size()));
  }
  nlohmann::json data = {{"input_label", labels.input},
                         {"output_label", labels.output},
                         {"output_unit", labels.output_unit},
                         {"validation_begin", comparison.split.validation_begin},
                         {"shown", kComparisonPageShownModels},
                         {"sample", samples},
                         {"input", at(input, samples)},
                         {"measured", at(output, samples)},
                         {"models", nlohmann::json::array()}};
  if (!labels.time.empty()) {
    data["time"] = at(labels.time, samples);
    data["validation_begin_time"] = labels.time[comparison.split.validation_begin];
  }
  for (const auto& row : comparison.ranking) {
    if (!row.ok || row.simulated.size() != input.size()) continue;
    data["models"].push_back({{"name", row.model}, {"simulated", at(row.simulated, samples)}});
  }
  // "</" would end the <script> element that holds the JSON.
  std::string text = data.dump();
  for (auto at = text.find("</"); at != std::string::npos; at = text.find("</", at + 2))
    text.replace(at, 2, "<\\/");
  return text;
}

//! Chart.js, read where the set-up put it, to be inlined (the page needs no network).
std::string plotting_library() {
  std::error_code error;
  if (!std::filesystem::is_regular_file(HYST_CHARTJS_FILE, error)) {
    throw Error(
        fmt::format("the HTML comparison page needs Chart.js, not found at '{}' "
                    "(Debian package libjs-chart.js; make deps installs it)",
                    HYST_CHARTJS_FILE));
  }
  return io::read_file(HYST_CHARTJS_FILE);
}

std::string table(const ModelComparison& comparison, const std::string& output_unit) {
  const std::string unit =
      output_unit.empty() ? std::string() : " [" + io::xml_escaped(output_unit) + "]";
  std::string html = fmt::format(
      "<table id=\"ranking\">\n<thead><tr><th>rank</th><th>model</th><th>validation NRMSE "
      "[%]</th><th>validation RMSE{0}</th><th>max error{0}</th><th>beats yardstick</th>"
      "<th>parameters</th><th>fit time [s]</th><th>simulation [ns/sample]</th><th>status</th>"
      "</tr></thead>\n<tbody>\n",
      unit);
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      html += fmt::format(
          "<tr class=\"fitted\"><td>{}</td><td>{}</td><td>{:.4g}</td><td>{:.4g}</td><td>{:.4g}"
          "</td><td>{}</td><td>{}</td><td>{:.3g}</td><td>{:.3g}</td><td>{}</td></tr>\n",
          ++rank, io::xml_escaped(row.model), row.validation.nrmse_percent, row.validation.rmse,
          row.validation.max_error, row.beats_yardstick ? "yes" : "no", row.parameters,
          row.fit_seconds, row.ns_per_sample, io::xml_escaped(row.report->status()));
    } else {
      html += fmt::format(
          "<tr class=\"failed\"><td>-</td><td>{}</td><td colspan=\"7\"></td><td>failed: {}</td>"
          "</tr>\n",
          io::xml_escaped(row.model), io::xml_escaped(row.error));
    }
  }
  return html + "</tbody>\n</table>\n";
}

}  // namespace

std::string model_comparison_html(const ModelComparison& comparison, std::span<const double> input,
                                  std::span<const double> output, const std::string& title,
                                  const ComparisonPageLabels& labels) {
  std::string html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{0}</title>\n"
      "<style>body{{font-family:sans-serif;margin:2em}}table{{border-collapse:collapse}}"
      "td,th{{border:1px solid #aaa;padding:3px 8px;text-align:right}}"
      "th{{cursor:pointer;user-select:none}}th[data-order=ascending]::after{{content:' \\25B2'}}"
      "th[data-order=descending]::after{{content:' \\25BC'}}"
      "td:nth-child(2),td:last-child{{text-align:left}}tr.failed{{color:#a00}}"
      "figure{{margin:1.5em 0}}.chart{{position:relative;height:420px;width:100%}}"
      ".zoom-box{{position:absolute;display:none;border:1px dashed #333;"
      "background:rgba(80,120,200,0.12);pointer-events:none}}"
      "#page-errors{{color:#a00}}h1{{overflow-wrap:anywhere}}</style>\n</head>\n<body>\n"
      "<h1>{0}</h1>\n"
      "<p>Every model was fitted on samples {1}..{2} and run in free run over the whole record; "
      "the ranking is by the NRMSE on the held-out samples {3}..{4} (shaded in the figures). "
      "Click a column header to sort the table. In the figures: drag a box to zoom, shift-drag "
      "to pan, the mouse wheel zooms, a double click resets; a legend entry shows or hides "
      "that curve in every figure. The measurement is black; the best {5} models are shown "
      "when the page opens, the others' legend entries are struck through until clicked.</p>\n",
      io::xml_escaped(title), comparison.split.fit_begin, comparison.split.fit_end - 1,
      comparison.split.validation_begin, comparison.split.validation_end - 1,
      kComparisonPageShownModels);
  if (const auto verdict = no_fit_line(comparison); !verdict.empty()) {
    html += fmt::format("<p id=\"no-fit\"><strong>{}</strong></p>\n", io::xml_escaped(verdict));
  }
  html += fmt::format("<p id=\"yardstick\">{}</p>\n", io::xml_escaped(yardstick_line(comparison)));
  html += table(comparison, labels.output_unit);
  html += "<pre id=\"page-errors\" hidden></pre>\n<pre id=\"selftest\" hidden></pre>\n";
  const bool any_fitted = std::any_of(comparison.ranking.begin(), comparison.ranking.end(),
                                      [](const ComparedModel& row) { return row.ok; });
  if (!any_fitted) return html + "</body>\n</html>\n";
  const std::pair<const char*, const char*> figures[] = {
      {"loops", "The loops over the whole record: the fit part faded, the held-out part in full."},
      {"outputs", "Measured and simulated output over the whole record."},
      {"errors", "Error, measured minus simulated output, over the whole record."}};
  for (const auto& [id, caption] : figures) {
    html += fmt::format(
        "<figure id=\"{}\">\n<div class=\"chart\"><canvas></canvas></div>\n"
        "<figcaption>{}</figcaption>\n</figure>\n",
        id, caption);
  }
  html += "<script id=\"comparison-data\" type=\"application/json\">" +
          page_data(comparison, input, output, labels) + "</script>\n";
  html += "<script>\n" + plotting_library() + "\n</script>\n";
  html += std::string("<script>\n") + detail::kComparisonPageScript + "</script>\n";
  return html + "</body>\n</html>\n";
}

void write_model_comparison_html(const std::filesystem::path& path,
                                 const ModelComparison& comparison, std::span<const double> input,
                                 std::span<const double> output, const std::string& title,
                                 const ComparisonPageLabels& labels) {
  io::write_file_atomically(path, model_comparison_html(comparison, input, output, title, labels));
}

}  // namespace hyst::plot
