#pragma once
//! \file
//! A figure (hyst::plot::Figure, gnuplot.hpp) as an SVG document, drawn by hyst itself, so that
//! it can be embedded in an HTML page without an external program: axes with five ticks each,
//! one polyline (or dots, for points) per series, a legend and the title. Long series are thinned
//! to at most `max_points` evenly spaced points each (the page stays small; a loop drawn with
//! 2000 points looks the same). Text is escaped for XML.

#include <cstddef>
#include <string>
#include <string_view>

#include "hyst/plot/gnuplot.hpp"

namespace hyst::plot {

//! The figure as a standalone <svg> element of figure.width x figure.height pixels. Throws
//! hyst::Error for the same invalid figures as write_png() (no series, empty or mismatched
//! series, non-finite values), naming the series and the index.
std::string svg(const Figure& figure, std::size_t max_points = 2000);

//! `text` with &, <, >, " and ' replaced by XML entities.
std::string xml_escaped(std::string_view text);

}  // namespace hyst::plot
