#pragma once
//! \file
//! Figures of a model comparison (identify/compare.hpp), as PNG files through gnuplot: the
//! measured loop of the held-out part with each fitted model's loop, and each model's error
//! (measured - simulated) over the held-out samples.

#include <filesystem>
#include <span>

#include "hyst/identify/compare.hpp"
#include "hyst/plot/gnuplot.hpp"

namespace hyst::plot {

//! Output against input on the held-out part: "measured" and one curve per fitted model.
Figure model_comparison_loop_figure(const ModelComparison& comparison,
                                    std::span<const double> input, std::span<const double> output);
//! measured - simulated against the sample index on the held-out part, one curve per model.
Figure model_comparison_error_figure(const ModelComparison& comparison,
                                     std::span<const double> output);

//! Writes both figures (see write_png()); throws hyst::Error when no model was fitted or
//! gnuplot fails.
void write_model_comparison_plots(const ModelComparison& comparison, std::span<const double> input,
                                  std::span<const double> output,
                                  const std::filesystem::path& loop_png,
                                  const std::filesystem::path& error_png);

}  // namespace hyst::plot
