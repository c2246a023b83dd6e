#include "hyst/plot/heat_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "gnuplot_render.hpp"
#include "hyst/core/error.hpp"

namespace hyst::plot {
namespace {

namespace fs = std::filesystem;

void check_axis(const std::vector<double>& centres, char name) {
  if (centres.empty()) throw Error(fmt::format("heat map {} has no cell centres", name));
  for (std::size_t k = 0; k < centres.size(); ++k) {
    if (!std::isfinite(centres[k])) {
      throw Error(fmt::format("heat map {}[{}] = {} is not finite", name, k, centres[k]));
    }
    if (k > 0 && !(centres[k] > centres[k - 1])) {
      throw Error(fmt::format("heat map {}[{}] = {} must be above {}[{}] = {}", name, k, centres[k],
                              name, k - 1, centres[k - 1]));
    }
  }
}

void validate(const HeatMap& map) {
  detail::check_size(map.width, map.height);
  check_axis(map.x, 'x');
  check_axis(map.y, 'y');
  if (map.z.size() != map.x.size() * map.y.size()) {
    throw Error(fmt::format("heat map z has {} values but x.size() * y.size() = {} * {} = {}",
                            map.z.size(), map.x.size(), map.y.size(), map.x.size() * map.y.size()));
  }
  bool any = false;
  for (std::size_t k = 0; k < map.z.size(); ++k) {
    if (std::isinf(map.z[k])) {
      throw Error(
          fmt::format("heat map z[{}] = {} is infinite (NaN marks a blank cell)", k, map.z[k]));
    }
    any = any || !std::isnan(map.z[k]);
  }
  if (!any) throw Error("heat map z has no finite value to draw");
}

//! Cell edges: halfway between centres, the end cells as wide as their neighbour's half-gap.
std::vector<double> edges(const std::vector<double>& centres) {
  const std::size_t n = centres.size();
  std::vector<double> edge(n + 1);
  if (n == 1) {
    edge = {centres[0] - 0.5, centres[0] + 0.5};
    return edge;
  }
  for (std::size_t k = 1; k < n; ++k)
    edge[k] = 0.5 * (centres[k - 1] + centres[k]);
  edge[0] = centres[0] - (edge[1] - centres[0]);
  edge[n] = centres[n - 1] + (centres[n - 1] - edge[n - 1]);
  return edge;
}

std::string script_for(const HeatMap& map, const fs::path& output, detail::ImageFormat format) {
  using detail::gnuplot_string;
  std::string script = detail::terminal_commands(map.width, map.height, format, output);
  if (!map.title.empty()) script += fmt::format("set title {}\n", gnuplot_string(map.title));
  if (!map.x_label.empty()) script += fmt::format("set xlabel {}\n", gnuplot_string(map.x_label));
  if (!map.y_label.empty()) script += fmt::format("set ylabel {}\n", gnuplot_string(map.y_label));
  if (!map.z_label.empty()) script += fmt::format("set cblabel {}\n", gnuplot_string(map.z_label));
  if (map.equal_axes) script += "set size ratio -1\n";

  const auto x_edge = edges(map.x);
  const auto y_edge = edges(map.y);
  double low = 0.0;
  double high = 0.0;
  bool first = true;
  // One filled rectangle per run of equal cells in a row (a piecewise constant map, such as a
  // table drawn on a finer grid, gives few of them); blank cells are left out, so any grid, even
  // a single cell, draws the same way.
  script += "$cells << EOD\n";
  const std::size_t nx = map.x.size();
  for (std::size_t iy = 0; iy < map.y.size(); ++iy) {
    for (std::size_t ix = 0; ix < nx;) {
      const double z = map.z[iy * nx + ix];
      std::size_t end = ix + 1;
      while (end < nx && map.z[iy * nx + end] == z)
        ++end;
      if (!std::isnan(z)) {
        low = first ? z : std::min(low, z);
        high = first ? z : std::max(high, z);
        first = false;
        script += fmt::format("{:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n", x_edge[ix], x_edge[end],
                              y_edge[iy], y_edge[iy + 1], z);
      }
      ix = end;
    }
  }
  script += "EOD\n";
  // White at the bottom of the scale: at 0 for non-negative data (an empty region of a density
  // stays white); a constant map gets a non-empty range.
  if (low >= 0.0) low = 0.0;
  if (!(high > low)) high = low + 1.0;
  script += fmt::format("set cbrange [{:.17g}:{:.17g}]\n", low, high);
  script += fmt::format("set xrange [{:.17g}:{:.17g}]\n", x_edge.front(), x_edge.back());
  script += fmt::format("set yrange [{:.17g}:{:.17g}]\n", y_edge.front(), y_edge.back());
  script +=
      "set palette defined (0 '#ffffff', 0.1 '#c6dbef', 0.3 '#3182bd', 0.55 '#31a354', "
      "0.75 '#fec44f', 1 '#d7301f')\n"
      // A fixed right margin keeps the colour bar's label inside the image.
      "set rmargin at screen 0.84\nset tics out\nset grid front\nunset key\n"
      "set style fill solid 1.0 noborder\n"
      "plot $cells using (($1+$2)/2):(($3+$4)/2):1:2:3:4:5 with boxxyerror fc palette\n"
      "unset output\n";
  return script;
}

}  // namespace

void write_png(const HeatMap& map, const fs::path& png) {
  validate(map);
  detail::write_image(
      [&](const fs::path& output) { return script_for(map, output, detail::ImageFormat::png); },
      png, detail::ImageFormat::png);
}

void write_svg(const HeatMap& map, const fs::path& svg) {
  validate(map);
  detail::write_image(
      [&](const fs::path& output) { return script_for(map, output, detail::ImageFormat::svg); },
      svg, detail::ImageFormat::svg);
}

}  // namespace hyst::plot
