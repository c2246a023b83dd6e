#include "hyst/plot/svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::plot {
namespace {

constexpr double kLeft = 80.0;
constexpr double kRight = 170.0;  // room for the legend
constexpr double kTop = 40.0;
constexpr double kBottom = 55.0;
constexpr std::array<std::string_view, 8> kPalette = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                                      "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};

void validate(const Figure& figure) {
  if (figure.series.empty()) throw Error("SVG figure: no series to draw");
  for (std::size_t s = 0; s < figure.series.size(); ++s) {
    const auto& series = figure.series[s];
    if (series.x.empty() || series.x.size() != series.y.size()) {
      throw Error(
          fmt::format("SVG figure: series {} '{}' has {} x and {} y values (need the "
                      "same number, at least one)",
                      s, series.label, series.x.size(), series.y.size()));
    }
    for (std::size_t k = 0; k < series.x.size(); ++k) {
      if (!std::isfinite(series.x[k]) || !std::isfinite(series.y[k])) {
        throw Error(fmt::format("SVG figure: series {} '{}' point [{}] = ({}, {}) is not finite", s,
                                series.label, k, series.x[k], series.y[k]));
      }
    }
  }
  if (figure.width < 16 || figure.height < 16 || figure.width > 20000 || figure.height > 20000) {
    throw Error(fmt::format("SVG figure: size {} x {} must be within 16..20000 pixels",
                            figure.width, figure.height));
  }
}

struct Range {
  double low = 0.0;
  double high = 0.0;
};

// The range of the values, widened when empty so that the mapping stays defined.
Range padded(Range range) {
  if (range.high - range.low <= 0.0) {
    const double half = std::max(1.0, std::abs(range.low)) * 0.5;
    return {range.low - half, range.high + half};
  }
  const double margin = 0.03 * (range.high - range.low);
  return {range.low - margin, range.high + margin};
}

}  // namespace

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

std::string svg(const Figure& figure, std::size_t max_points) {
  validate(figure);
  Range x{figure.series[0].x[0], figure.series[0].x[0]};
  Range y{figure.series[0].y[0], figure.series[0].y[0]};
  for (const auto& series : figure.series) {
    const auto [x_low, x_high] = std::minmax_element(series.x.begin(), series.x.end());
    const auto [y_low, y_high] = std::minmax_element(series.y.begin(), series.y.end());
    x = {std::min(x.low, *x_low), std::max(x.high, *x_high)};
    y = {std::min(y.low, *y_low), std::max(y.high, *y_high)};
  }
  x = padded(x);
  y = padded(y);
  const double width = figure.width;
  const double height = figure.height;
  const double plot_width = std::max(1.0, width - kLeft - kRight);
  const double plot_height = std::max(1.0, height - kTop - kBottom);
  const auto px = [&](double value) {
    return kLeft + (value - x.low) / (x.high - x.low) * plot_width;
  };
  const auto py = [&](double value) {
    return kTop + (y.high - value) / (y.high - y.low) * plot_height;
  };

  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect x=\"0\" y=\"0\" width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
      "<text x=\"{2}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">{3}</text>\n"
      "<rect x=\"{4}\" y=\"{5}\" width=\"{6}\" height=\"{7}\" fill=\"none\" stroke=\"#444\"/>\n",
      figure.width, figure.height, kLeft + plot_width / 2, xml_escaped(figure.title), kLeft, kTop,
      plot_width, plot_height);
  for (int i = 0; i <= 4; ++i) {
    const double xv = x.low + (x.high - x.low) * i / 4.0;
    const double yv = y.low + (y.high - y.low) * i / 4.0;
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#ddd\"/>"
        "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4:.4g}</text>\n",
        px(xv), kTop, kTop + plot_height, kTop + plot_height + 16, xv);
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#ddd\"/>"
        "<text x=\"{3:.1f}\" y=\"{4:.1f}\" text-anchor=\"end\">{5:.4g}</text>\n",
        kLeft, py(yv), kLeft + plot_width, kLeft - 6, py(yv) + 4, yv);
  }
  out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n",
                     kLeft + plot_width / 2, height - 12, xml_escaped(figure.x_label));
  out += fmt::format(
      "<text x=\"16\" y=\"{0:.1f}\" text-anchor=\"middle\" transform=\"rotate(-90 16 {0:.1f})\">{1}"
      "</text>\n",
      kTop + plot_height / 2, xml_escaped(figure.y_label));

  for (std::size_t s = 0; s < figure.series.size(); ++s) {
    const auto& series = figure.series[s];
    const std::string color =
        series.color.empty() ? std::string(kPalette[s % kPalette.size()]) : series.color;
    const std::size_t n = series.x.size();
    const std::size_t stride =
        std::max<std::size_t>(1, (n + max_points - 1) / std::max<std::size_t>(1, max_points));
    const bool dots = series.style == Series::Style::points;
    std::string points;
    for (std::size_t k = 0; k < n; k += stride) {
      if (dots) {
        out += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"1.5\" fill=\"{}\"/>",
                           px(series.x[k]), py(series.y[k]), xml_escaped(color));
      } else {
        points += fmt::format("{:.1f},{:.1f} ", px(series.x[k]), py(series.y[k]));
      }
    }
    if (!dots) {
      out += fmt::format(
          "<polyline class=\"series\" data-label=\"{}\" fill=\"none\" stroke=\"{}\" "
          "stroke-width=\"1.2\" points=\"{}\"/>\n",
          xml_escaped(series.label), xml_escaped(color), points);
    }
    const double legend_y = kTop + 14 + 18.0 * static_cast<double>(s);
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" "
        "stroke-width=\"2\"/><text x=\"{4:.1f}\" y=\"{5:.1f}\">{6}</text>\n",
        kLeft + plot_width + 12, legend_y, kLeft + plot_width + 36, xml_escaped(color),
        kLeft + plot_width + 42, legend_y + 4, xml_escaped(series.label));
  }
  out += "</svg>\n";
  return out;
}

}  // namespace hyst::plot
