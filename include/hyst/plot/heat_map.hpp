#pragma once
//! \file
//! Heat maps (a value z over a regular x-y grid, drawn as coloured cells with a colour bar)
//! written as PNG or SVG by gnuplot, like the line plots of gnuplot.hpp (same program, same
//! atomic replacement of the target, same literal text).
//!
//!     hyst::plot::HeatMap map{.title = "FORC diagram", .x_label = "Hc [mT]",
//!                             .y_label = "Hu [mT]", .z_label = "density"};
//!     map.x = hc;  map.y = hu;          // cell centres, increasing
//!     map.z = density;                  // z[iy * x.size() + ix]; NaN: no cell (left blank)
//!     hyst::plot::write_png(map, "forc.png");
//!
//! The colour scale runs from white (the smallest value, or 0 if all values are >= 0, so that an
//! empty region of a density stays white) through blue, green and yellow to red (the largest).

#include <filesystem>
#include <string>
#include <vector>

namespace hyst::plot {

struct HeatMap {
  std::string title{};
  std::string x_label{};
  std::string y_label{};
  std::string z_label{};  //!< colour bar label
  //! Cell centres, finite and strictly increasing, at least one each. A cell reaches halfway to
  //! its neighbours (the end cells as far out as in; a single cell is 1 wide).
  std::vector<double> x{};
  std::vector<double> y{};
  //! x.size() * y.size() values, row by row: z[iy * x.size() + ix] is the cell at (x[ix], y[iy]).
  //! NaN: no value (drawn blank); +-inf is refused. At least one value must be finite.
  std::vector<double> z{};
  int width = 900;          //!< [pixels], 16..20000
  int height = 700;         //!< [pixels], 16..20000
  bool equal_axes = false;  //!< one unit has the same length on both axes
};

//! Renders the heat map into the PNG file `png` (replaced atomically; the folder must exist).
//! Throws hyst::Error when the map is invalid (the message names the field and index), when the
//! folder does not exist, or when gnuplot is missing or fails (gnuplot_available()).
void write_png(const HeatMap& map, const std::filesystem::path& png);

//! The same as SVG; same errors as write_png().
void write_svg(const HeatMap& map, const std::filesystem::path& svg);

}  // namespace hyst::plot
