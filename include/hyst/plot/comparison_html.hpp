#pragma once
//! \file
//! A model comparison (identify/compare.hpp) as one self-contained HTML page: the ranking table
//! and the two figures (loops of the held-out part, error time series) as inline SVG drawn by
//! gnuplot (its `svg` terminal; curves longer than 2000 points are thinned to evenly spaced
//! points) - no scripts, no external files, so the page opens anywhere and can be mailed as it is.

#include <filesystem>
#include <span>
#include <string>

#include "hyst/identify/compare.hpp"

namespace hyst::plot {

//! The page: <table id="ranking"> with one row per model (failed ones with their reason) and,
//! when at least one model was fitted, <figure id="loops"> and <figure id="errors"> with an <svg>
//! each. `title` heads the page (escaped). Throws hyst::Error when gnuplot is missing or fails.
std::string model_comparison_html(const ModelComparison& comparison, std::span<const double> input,
                                  std::span<const double> output, const std::string& title);

//! Writes the page atomically.
void write_model_comparison_html(const std::filesystem::path& path,
                                 const ModelComparison& comparison, std::span<const double> input,
                                 std::span<const double> output, const std::string& title);

}  // namespace hyst::plot
