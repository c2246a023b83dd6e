#include "hyst/plot/comparison_plots.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "hyst/core/error.hpp"
#include "hyst/io/output_paths.hpp"

namespace hyst::plot {
namespace {

// One colour per model, none black (black is the measurement).
constexpr std::array<const char*, 12> kModelColors = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                                      "#ff7f0e", "#17becf", "#8c564b", "#e377c2",
                                                      "#bcbd22", "#7f7f7f", "#aec7e8", "#98df8a"};

std::string model_color(std::size_t index) {
  return kModelColors[index % kModelColors.size()];
}

std::vector<double> held_out(const ModelComparison& comparison, std::span<const double> samples) {
  const auto part =
      samples.subspan(comparison.split.validation_begin, comparison.split.validation_size());
  return {part.begin(), part.end()};
}

void require_fitted(const ModelComparison& comparison) {
  if (std::none_of(comparison.ranking.begin(), comparison.ranking.end(),
                   [](const ComparedModel& row) { return row.ok; })) {
    throw Error("comparison plots: no model was fitted, there is nothing to plot");
  }
}

}  // namespace

Figure model_comparison_loop_figure(const ModelComparison& comparison,
                                    std::span<const double> input, std::span<const double> output) {
  require_fitted(comparison);
  Figure figure{.title = "Held-out part: measured and simulated (free run)",
                .x_label = "input",
                .y_label = "output"};
  const auto x = held_out(comparison, input);
  figure.series.push_back(
      {.label = "measured", .x = x, .y = held_out(comparison, output), .color = "black"});
  std::size_t fitted = 0;
  for (const auto& row : comparison.ranking) {
    if (!row.ok) continue;
    figure.series.push_back({.label = row.model,
                             .x = x,
                             .y = held_out(comparison, row.simulated),
                             .color = model_color(fitted++)});
  }
  return figure;
}

Figure model_comparison_error_figure(const ModelComparison& comparison,
                                     std::span<const double> output) {
  require_fitted(comparison);
  Figure figure{.title = "Held-out part: error measured - simulated",
                .x_label = "sample",
                .y_label = "error [output units]"};
  std::vector<double> index(comparison.split.validation_size());
  for (std::size_t k = 0; k < index.size(); ++k)
    index[k] = static_cast<double>(comparison.split.validation_begin + k);
  const auto measured = held_out(comparison, output);
  std::size_t fitted = 0;
  for (const auto& row : comparison.ranking) {
    if (!row.ok) continue;
    auto error = held_out(comparison, row.simulated);
    for (std::size_t k = 0; k < error.size(); ++k)
      error[k] = measured[k] - error[k];
    figure.series.push_back(
        {.label = row.model, .x = index, .y = std::move(error), .color = model_color(fitted++)});
  }
  return figure;
}

void write_model_comparison_plots(const ModelComparison& comparison, std::span<const double> input,
                                  std::span<const double> output,
                                  const std::filesystem::path& loop_png,
                                  const std::filesystem::path& error_png) {
  io::check_outputs({}, {{loop_png, "loop_png"}, {error_png, "error_png"}});
  write_png(model_comparison_loop_figure(comparison, input, output), loop_png);
  write_png(model_comparison_error_figure(comparison, output), error_png);
}

}  // namespace hyst::plot
