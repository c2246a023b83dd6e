#pragma once
//! \file
//! Line and scatter plots written as PNG (or SVG) files by gnuplot (an external program, looked up
//! on the PATH; Debian package `gnuplot-nox`).
//!
//! hyst does not draw anything itself: write_png() validates the figure, writes a gnuplot script
//! with the data inline (datablocks) to gnuplot's standard input, lets gnuplot render into a
//! temporary file next to the target and renames it over the target, so a reader never sees a
//! half-written image. The `pngcairo` terminal is used when gnuplot has it, else `png`.
//!
//!     hyst::plot::Figure figure{.title = "PI loop", .x_label = "v [V]", .y_label = "y [nm]"};
//!     figure.series.push_back({.label = "measured", .x = v, .y = y});
//!     hyst::plot::write_png(figure, "loop.png");
//!
//! Text (titles, labels, series labels) is printed literally: gnuplot's "enhanced" markup is off,
//! so "Vplus_19kv" keeps its underscore instead of becoming a subscript.

#include <filesystem>
#include <string>
#include <vector>

namespace hyst::plot {

//! One curve: points (x[k], y[k]) in order.
struct Series {
  std::string label{};  //!< legend entry; empty: no legend entry
  std::vector<double> x{};
  std::vector<double> y{};  //!< same length as x, at least one point, every value finite
  enum class Style { lines, points, lines_points } style = Style::lines;
  //! "#rrggbb" or a gnuplot colour name (letters, digits, '-'); empty: gnuplot's next colour.
  std::string color{};
};

//! A figure with one pair of axes. (The `{}` initializers let designated initializers leave
//! members out without -Wmissing-field-initializers warnings.)
struct Figure {
  std::string title{};
  std::string x_label{};
  std::string y_label{};
  std::vector<Series> series{};  //!< at least one
  int width = 1000;              //!< [pixels], 16..20000
  int height = 650;              //!< [pixels], 16..20000
  bool equal_axes = false;       //!< one unit has the same length on both axes
};

//! True if a program `gnuplot` is on the PATH and runs (`gnuplot --version` succeeds).
bool gnuplot_available();

//! Renders the figure into the PNG file `png` (replaced atomically; the folder must exist).
//! Throws hyst::Error when the figure is invalid (no series; a series that is empty, has x and y
//! of different lengths or a non-finite value — the message names the series and the index;
//! a size out of range), when the folder does not exist, or when gnuplot is missing or fails
//! (the message then includes what gnuplot wrote to its standard error).
void write_png(const Figure& figure, const std::filesystem::path& png);

//! The same as SVG (gnuplot's `svg` terminal), replaced atomically; same errors as write_png().
void write_svg(const Figure& figure, const std::filesystem::path& svg);

//! The figure rendered by gnuplot as an SVG document, from its `<svg` element on (without the
//! XML declaration), ready to be placed inside an HTML page. Same errors as write_png().
std::string svg_element(const Figure& figure);

}  // namespace hyst::plot
