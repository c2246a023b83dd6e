// Python bindings of the model comparison: hyst.compare() and its result.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/identify/compare.hpp"
#include "hyst/plot/comparison_html.hpp"
#include "hyst/plot/comparison_plots.hpp"

namespace hyst::python {

void bind_compare(py::module_& module) {
  py::class_<ComparedModel>(module, "ComparedModel",
                            "One row of a model comparison (see hyst.compare).")
      .def_readonly("model", &ComparedModel::model)
      .def_readonly("ok", &ComparedModel::ok, "True when fitted and evaluated.")
      .def_readonly("error", &ComparedModel::error, "Why not, when ok is False.")
      .def_readonly("report", &ComparedModel::report, "The fitter's FitReport, or None.")
      .def_readonly("validation", &ComparedModel::validation,
                    "ErrorMetrics of the free run on the held-out part.")
      .def_readonly("beats_yardstick", &ComparedModel::beats_yardstick,
                    "True when the validation NRMSE is below the best reference predictor's.")
      .def_readonly("parameters", &ComparedModel::parameters)
      .def_readonly("fit_seconds", &ComparedModel::fit_seconds)
      .def_readonly("ns_per_sample", &ComparedModel::ns_per_sample)
      .def_property_readonly(
          "simulated", [](const ComparedModel& row) { return readonly_copy(row.simulated); },
          "Free run over the whole record (empty when the model failed).")
      .def("__repr__", [](const ComparedModel& row) {
        return row.ok ? fmt::format("ComparedModel(model='{}', nrmse_percent={:.4g})", row.model,
                                    row.validation.nrmse_percent)
                      : fmt::format("ComparedModel(model='{}', failed)", row.model);
      });

  py::class_<ModelComparison>(module, "ModelComparison",
                              "Models fitted to one record, ranked on its held-out part.")
      .def_readonly("split", &ModelComparison::split)
      .def_readonly("ranking", &ModelComparison::ranking, "Best first; failed models last.")
      .def_readonly("references", &ModelComparison::references,
                    "The yardstick: ReferenceScore of each reference predictor.")
      .def_readonly("no_fit_percent", &ModelComparison::no_fit_percent,
                    "Threshold of the no-fit verdict [%].")
      .def_property_readonly(
          "no_fit", [](const ModelComparison& comparison) { return no_fit_line(comparison); },
          "The no-fit verdict in one line, or '' when the best model is below the threshold.")
      .def_property_readonly(
          "yardstick", [](const ModelComparison& comparison) { return yardstick_line(comparison); },
          "One line: every reference predictor's held-out NRMSE and the best of them.")
      .def("markdown", &model_comparison_markdown, "The ranking as a Markdown table.")
      .def("csv", &model_comparison_csv, "The ranking as CSV text.")
      .def(
          "write_plots",
          [](const ModelComparison& comparison, const InputArray& input, const InputArray& output,
             const std::filesystem::path& loop_png, const std::filesystem::path& error_png) {
            plot::write_model_comparison_plots(comparison, as_span(input, "input"),
                                               as_span(output, "output"), loop_png, error_png);
          },
          "input"_a, "output"_a, "loop_png"_a, "error_png"_a,
          "Writes the loops of the held-out part and the error time series as PNG (gnuplot).")
      .def(
          "html",
          [](const ModelComparison& comparison, const InputArray& input, const InputArray& output,
             const std::string& title) {
            return plot::model_comparison_html(comparison, as_span(input, "input"),
                                               as_span(output, "output"), title);
          },
          "input"_a, "output"_a, "title"_a = "Model comparison",
          "One self-contained HTML page: the ranking table and both figures as inline SVG.");

  module.def(
      "compare",
      [](const InputArray& input, const InputArray& output,
         const std::optional<std::vector<std::string>>& models, double validate_fraction,
         const std::optional<py::dict>& options, double timing_seconds, double no_fit_percent) {
        CompareOptions compare;
        if (models) compare.models = *models;
        compare.validate_fraction = validate_fraction;
        compare.timing_seconds = timing_seconds;
        compare.no_fit_percent = no_fit_percent;
        if (options) {
          for (const auto& [name, value] : *options) {
            const auto model = py::cast<std::string>(name);
            compare.fit_options[model] = python_to_json(value, model);
          }
        }
        const auto v = as_span(input, "input");
        const auto y = as_span(output, "output");
        py::gil_scoped_release release;
        return compare_models(v, y, compare);
      },
      "input"_a, "output"_a, "models"_a = py::none(), py::kw_only(), "validate_fraction"_a = 0.25,
      "options"_a = py::none(), "timing_seconds"_a = 0.05, "no_fit_percent"_a = 20.0,
      "Fits the models (default: every model with a fitter) to the first part of the record, "
      "runs each in free run over the whole record and ranks them by NRMSE on the held-out last "
      "part. options: {model name: {fit option: value}}. A model whose fit fails gets a row "
      "with the reason (ok False); the others still run. Returns a ModelComparison.");
}

}  // namespace hyst::python
