// Python bindings of the model comparison: hyst.compare() and its result.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/progress.hpp"
#include "hyst/identify/compare.hpp"
#include "hyst/identify/cross_record_compare.hpp"
#include "hyst/plot/comparison_html.hpp"
#include "hyst/plot/comparison_plots.hpp"

namespace hyst::python {
namespace {

// Records of hyst.compare(fit_records=..., validate_records=...): a dict {name: (input, output)}
// or a sequence of (input, output) pairs, named "record 1", "record 2", ... in the tables.
std::vector<NamedRecord> named_records(const py::object& records, std::string_view argument) {
  std::vector<NamedRecord> out;
  auto add = [&](std::string name, const py::handle& pair) {
    const auto items = py::cast<py::sequence>(pair);
    if (py::len(items) != 2) {
      throw Error(fmt::format("{}: record '{}' must be a pair (input, output)", argument, name));
    }
    const std::string what = fmt::format("{} '{}'", argument, name);
    out.push_back({name, as_vector(py::cast<InputArray>(items[0]), what + " input"),
                   as_vector(py::cast<InputArray>(items[1]), what + " output")});
  };
  if (py::isinstance<py::dict>(records)) {
    for (const auto& [name, pair] : py::cast<py::dict>(records))
      add(py::cast<std::string>(name), pair);
  } else {
    std::size_t index = 0;
    for (const auto& pair : py::cast<py::sequence>(records))
      add(fmt::format("record {}", ++index), pair);
  }
  return out;
}

void bind_cross_record(py::module_& module) {
  py::class_<HeldOutScore>(module, "HeldOutScore",
                           "A model's error on one held-out record (see hyst.compare).")
      .def_readonly("record", &HeldOutScore::record)
      .def_readonly("fitted_on", &HeldOutScore::fitted_on, "The records the model was fitted on.")
      .def_readonly("metrics", &HeldOutScore::metrics, "ErrorMetrics on the held-out record.")
      .def_property_readonly(
          "domain",
          [](const HeldOutScore& score) {
            return domain_check_dict(score.domain, score.metrics.samples);
          },
          "{'inside': bool, 'message': str}: the held-out record's inputs against the domain of "
          "the records the model was fitted on.");
  py::class_<CrossRecordRow>(module, "CrossRecordRow",
                             "One row of a comparison on separate records.")
      .def_readonly("model", &CrossRecordRow::model)
      .def_readonly("ok", &CrossRecordRow::ok)
      .def_readonly("error", &CrossRecordRow::error)
      .def_readonly("scores", &CrossRecordRow::scores, "HeldOutScore per held-out record.")
      .def_readonly("mean_nrmse_percent", &CrossRecordRow::mean_nrmse_percent)
      .def_readonly("worst_nrmse_percent", &CrossRecordRow::worst_nrmse_percent)
      .def_readonly("worst_record", &CrossRecordRow::worst_record)
      .def_readonly("parameters", &CrossRecordRow::parameters)
      .def_readonly("fit_seconds", &CrossRecordRow::fit_seconds)
      .def_readonly("status", &CrossRecordRow::status)
      .def_readonly("beats_yardstick", &CrossRecordRow::beats_yardstick,
                    "Mean held-out NRMSE below the best reference predictor's.");
  py::class_<CrossRecordReference>(module, "CrossRecordReference",
                                   "A reference predictor of the yardstick, scored like a model.")
      .def_readonly("name", &CrossRecordReference::name)
      .def_readonly("ok", &CrossRecordReference::ok)
      .def_readonly("error", &CrossRecordReference::error)
      .def_readonly("scores", &CrossRecordReference::scores, "HeldOutScore per held-out record.")
      .def_readonly("mean_nrmse_percent", &CrossRecordReference::mean_nrmse_percent)
      .def_readonly("worst_nrmse_percent", &CrossRecordReference::worst_nrmse_percent)
      .def_readonly("worst_record", &CrossRecordReference::worst_record);
  py::class_<NoFitVerdict>(module, "NoFitVerdict", "A held-out record that no model describes.")
      .def_readonly("record", &NoFitVerdict::record)
      .def_readonly("best_model", &NoFitVerdict::best_model)
      .def_readonly("best_nrmse_percent", &NoFitVerdict::best_nrmse_percent)
      .def_property_readonly(
          "findings", [](const NoFitVerdict& verdict) { return verdict.seen.findings; },
          "What the looks at the record find (butterfly, drift, extrapolation).");
  py::class_<CrossRecordComparison>(
      module, "CrossRecordComparison",
      "Models fitted on some records and ranked on others (or leave-one-out).")
      .def_readonly("leave_one_out", &CrossRecordComparison::leave_one_out)
      .def_readonly("fit_records", &CrossRecordComparison::fit_records)
      .def_readonly("validate_records", &CrossRecordComparison::validate_records)
      .def_readonly("rule", &CrossRecordComparison::rule,
                    "How the held-out records were predicted.")
      .def_readonly("ranking", &CrossRecordComparison::ranking, "Best first; failed models last.")
      .def_readonly("references", &CrossRecordComparison::references,
                    "The yardstick: reference predictors fitted on the same fit records.")
      .def_readonly("no_fit_percent", &CrossRecordComparison::no_fit_percent)
      .def_readonly("no_fit", &CrossRecordComparison::no_fit,
                    "NoFitVerdict per held-out record on which even the best model exceeds "
                    "no_fit_percent.")
      .def("markdown", &cross_record_markdown, "The ranking as a Markdown table.")
      .def("csv", &cross_record_csv, "The ranking as CSV text.");
}

}  // namespace

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
          "held_out_domain",
          [](const ComparedModel& row) {
            return domain_check_dict(row.held_out_domain, row.validation.samples);
          },
          "{'inside': bool, 'message': str}: the held-out inputs against the domain of the fit "
          "part.")
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
             const std::string& title, const std::string& input_label,
             const std::string& output_label, const std::string& output_unit,
             const std::optional<InputArray>& time) {
            plot::ComparisonPageLabels labels{input_label, output_label, output_unit, {}};
            if (time) labels.time = as_vector(*time, "time");
            return plot::model_comparison_html(comparison, as_span(input, "input"),
                                               as_span(output, "output"), title, labels);
          },
          "input"_a, "output"_a, "title"_a = "Model comparison", "input_label"_a = "input",
          "output_label"_a = "output", "output_unit"_a = "", "time"_a = py::none(),
          "One self-contained interactive HTML page (Chart.js inline): the ranking table, sortable "
          "by column, and the loops, outputs and errors over the whole record with the held-out "
          "part shaded; zoom, pan, curves toggled from the legend, values on hover. The labels "
          "name the axes, with units, e.g. 'V+ [V]'; output_unit ('nm') labels the error axis "
          "and the RMSE and max-error columns; time (seconds, one per sample) draws the outputs "
          "and errors over time instead of the sample number.");

  bind_cross_record(module);
  module.def(
      "compare",
      [](const std::optional<InputArray>& input, const std::optional<InputArray>& output,
         const std::optional<std::vector<std::string>>& models, double validate_fraction,
         const std::optional<py::dict>& options, double timing_seconds, double no_fit_percent,
         const std::optional<py::object>& fit_records,
         const std::optional<py::object>& validate_records, bool leave_one_out,
         const std::string& validation_start, const std::string& validation_align,
         const py::object& progress) -> std::variant<ModelComparison, CrossRecordComparison> {
        std::map<std::string, nlohmann::json> fit_options;
        if (options) {
          for (const auto& [name, value] : *options) {
            const auto model = py::cast<std::string>(name);
            fit_options[model] = python_to_json(value, model);
          }
        }
        if (fit_records) {
          if (input || output) {
            throw Error("hyst.compare: input/output and fit_records exclude each other");
          }
          if (leave_one_out == validate_records.has_value()) {
            throw Error(
                "hyst.compare: fit_records needs either validate_records or "
                "leave_one_out=True");
          }
          CrossRecordOptions cross;
          if (models) cross.models = *models;
          cross.fit_options = std::move(fit_options);
          cross.no_fit_percent = no_fit_percent;
          cross.progress = progress_callback(progress);
          cross.validation.start = validation_start_from_string(validation_start);
          cross.validation.align = validation_alignment_from_string(validation_align);
          const auto fit = named_records(*fit_records, "fit_records");
          if (leave_one_out) {
            py::gil_scoped_release release;
            return compare_leave_one_out(fit, cross);
          }
          const auto held_out = named_records(*validate_records, "validate_records");
          py::gil_scoped_release release;
          return compare_across_records(fit, held_out, cross);
        }
        if (!input || !output) {
          throw Error(
              "hyst.compare: give input and output (one record, split in time) or "
              "fit_records");
        }
        if (validate_records || leave_one_out) {
          throw Error("hyst.compare: validate_records and leave_one_out need fit_records");
        }
        CompareOptions compare;
        if (models) compare.models = *models;
        compare.validate_fraction = validate_fraction;
        compare.timing_seconds = timing_seconds;
        compare.no_fit_percent = no_fit_percent;
        compare.fit_options = std::move(fit_options);
        compare.progress = progress_callback(progress);
        const auto v = as_span(*input, "input");
        const auto y = as_span(*output, "output");
        py::gil_scoped_release release;
        return compare_models(v, y, compare);
      },
      "input"_a = py::none(), "output"_a = py::none(), "models"_a = py::none(), py::kw_only(),
      "validate_fraction"_a = 0.25, "options"_a = py::none(), "timing_seconds"_a = 0.05,
      "no_fit_percent"_a = 20.0, "fit_records"_a = py::none(), "validate_records"_a = py::none(),
      "leave_one_out"_a = false, "validation_start"_a = "rest", "validation_align"_a = "none",
      "progress"_a = py::none(),
      "Fits the models (default: every model with a fitter) and ranks them by free-run NRMSE on "
      "data they were not fitted on. With input and output: fitted on the first part of the "
      "record and ranked on the held-out last part (validate_fraction; this measures "
      "extrapolation); returns a ModelComparison. With fit_records and validate_records (each "
      "a dict {name: (input, output)} or a list of (input, output) pairs): fitted on the fit "
      "records joined in order (the state runs on across each junction), ranked on the separate "
      "records predicted by validation_start ('rest', 'periodic', 'continue') and "
      "validation_align ('none', 'first-sample'); leave_one_out=True instead holds each fit "
      "record out in turn. Returns a CrossRecordComparison. options: {model name: {fit option: "
      "value}}. A model whose fit fails gets a row with the reason (ok False); the others still "
      "run. progress: called as progress(done, total, current) before each model's fit and once "
      "at the end (done == total, current ''); the package's hyst.compare also takes True (a "
      "tqdm bar when tqdm is installed, else lines on standard error).");
}

}  // namespace hyst::python
