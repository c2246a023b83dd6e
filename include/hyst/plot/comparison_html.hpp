#pragma once
//! \file
//! A model comparison (identify/compare.hpp) as one self-contained, interactive HTML page: the
//! ranking table (sortable by column) and three figures over the whole record with the held-out
//! part shaded or in full colour: the loops, the outputs and the errors. The figures are drawn in
//! the browser by Chart.js, which the page carries inline (read from Debian's libjs-chart.js when
//! the page is written), so the page opens without network and can be mailed as it is; zoom,
//! pan, curves shown or hidden from the legend and values on hover. The measurement is drawn in
//! black on top of the models, each model in a colour and dash of its own (20 colours, 4 dashes),
//! the best kComparisonPageShownModels shown when the page opens. Curves longer than 2000 points
//! are thinned to evenly spaced samples. Static figures for papers: comparison_plots.hpp.

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "hyst/identify/compare.hpp"

namespace hyst::plot {

//! How the page names the record's signals and its time axis.
struct ComparisonPageLabels {
  std::string input = "input";    //!< the input's axis label with its unit, e.g. "V+ [V]"
  std::string output = "output";  //!< the output's, e.g. "D1 [nm]"
  //! The output's unit alone ("nm"), for the error axis and the RMSE and max-error columns; ""
  //! when the record names none.
  std::string output_unit;
  //! The record's time [s] at every sample: the output and error figures are drawn over it
  //! ("time [s]"); empty: over the sample number.
  std::vector<double> time;
};

//! How many models the page's figures show when it opens: the best ones of the ranking; the
//! others are one click on their legend entry away.
inline constexpr std::size_t kComparisonPageShownModels = 5;

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
