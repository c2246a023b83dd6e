#pragma once
//! \file
//! A model comparison (identify/compare.hpp) as one self-contained, interactive HTML page: the
//! ranking table (sortable by column) and three figures over the whole record with the held-out
//! part shaded or in full colour: the loops, the outputs and the errors. The figures are drawn in
//! the browser by Chart.js, which the page carries inline (read from Debian's libjs-chart.js when
//! the page is written), so the page opens without network and can be mailed as it is; zoom,
//! pan, curves shown or hidden from the legend and values on hover. Curves longer than 2000
//! points are thinned to evenly spaced samples. Static figures for papers: comparison_plots.hpp.

#include <filesystem>
#include <span>
#include <string>

#include "hyst/identify/compare.hpp"

namespace hyst::plot {

//! How the page names the record's signals on its axes, with their units, e.g. "V+ [V]".
struct ComparisonPageLabels {
  std::string input = "input";
  std::string output = "output";
};

//! The page: <table id="ranking"> with one row per model (failed ones with their reason) and,
//! when at least one model was fitted, <figure id="loops">, <figure id="outputs"> and
//! <figure id="errors">, each a <canvas> drawn from the JSON data of <script
//! id="comparison-data">. `title` heads the page (escaped). Script errors show in
//! <pre id="page-errors">; opened with "#selftest" the page exercises its controls and writes
//! what it saw into <pre id="selftest">. Throws hyst::Error when Chart.js is missing.
std::string model_comparison_html(const ModelComparison& comparison, std::span<const double> input,
                                  std::span<const double> output, const std::string& title,
                                  const ComparisonPageLabels& labels = {});

//! Writes the page atomically.
void write_model_comparison_html(const std::filesystem::path& path,
                                 const ModelComparison& comparison, std::span<const double> input,
                                 std::span<const double> output, const std::string& title,
                                 const ComparisonPageLabels& labels = {});

}  // namespace hyst::plot
