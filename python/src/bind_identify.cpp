// Identification: the fit report, error metrics, contiguous data splits and the PI fitter.

#include <optional>
#include <utility>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/core/error.hpp"
#include "hyst/identify/data_split.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/identify/fitted_domain.hpp"

namespace hyst::python {
namespace {

std::string metrics_repr(const ErrorMetrics& m) {
  return fmt::format(
      "ErrorMetrics(samples={}, rmse={:.6g}, nrmse_percent={:.6g}, max_error={:.6g})", m.samples,
      m.rmse, m.nrmse_percent, m.max_error);
}

std::string report_repr(const FitReport& r) {
  std::string text = fmt::format("<FitReport {} by {}: {} after {} iterations; fit NRMSE {:.4g} %",
                                 r.model, r.method, r.status(), r.iterations, r.fit.nrmse_percent);
  if (r.validation) text += fmt::format("; validation NRMSE {:.4g} %", r.validation->nrmse_percent);
  return text + ">";
}

}  // namespace

py::dict domain_check_dict(const DomainCheck& check, std::size_t samples) {
  return py::dict(py::arg("inside") = check.inside(), py::arg("message") = check.message(samples));
}

void bind_identify(py::module_& module) {
  py::enum_<Termination>(module, "Termination", "Why an iterative fit stopped.")
      .value("converged", Termination::converged)
      .value("max_iterations", Termination::max_iterations)
      .value("no_progress", Termination::no_progress)
      .value("failed", Termination::failed);

  py::class_<ErrorMetrics>(module, "ErrorMetrics",
                           "How well a prediction matches a measurement: e = measured - "
                           "predicted; RMSE, NRMSE = RMSE / range(measured), max |e|.")
      .def_readonly("samples", &ErrorMetrics::samples)
      .def_readonly("rmse", &ErrorMetrics::rmse, "[output units]")
      .def_readonly("nrmse_percent", &ErrorMetrics::nrmse_percent,
                    "100 * RMSE / range of the measured output [%]")
      .def_readonly("max_error", &ErrorMetrics::max_error, "[output units]")
      .def("__repr__", &metrics_repr);
  module.def(
      "error_metrics",
      [](const InputArray& measured, const InputArray& predicted) {
        return error_metrics(as_span(measured, "measured"), as_span(predicted, "predicted"));
      },
      "measured"_a, "predicted"_a, "ErrorMetrics of `predicted` against `measured`.");

  py::class_<ReferenceScore>(module, "ReferenceScore",
                             "A reference predictor scored on held-out samples.")
      .def_readonly("name", &ReferenceScore::name)
      .def_readonly("validation", &ReferenceScore::validation, "ErrorMetrics, or None")
      .def_readonly("error", &ReferenceScore::error, "Why it could not be made")
      .def("__repr__", [](const ReferenceScore& r) {
        return r.validation ? fmt::format("ReferenceScore('{}', nrmse_percent={:.4g})", r.name,
                                          r.validation->nrmse_percent)
                            : fmt::format("ReferenceScore('{}', not made)", r.name);
      });

  py::class_<FittedDomain>(module, "FittedDomain",
                           "The domain a model was fitted on (its fit part): input and output "
                           "ranges, samples, the largest input step, the longest run without a "
                           "reversal, the sample time when known. check_inputs / check_targets "
                           "give (inside, message) for another record.")
      .def_readonly("input_min", &FittedDomain::input_min)
      .def_readonly("input_max", &FittedDomain::input_max)
      .def_readonly("output_min", &FittedDomain::output_min)
      .def_readonly("output_max", &FittedDomain::output_max)
      .def_readonly("samples", &FittedDomain::samples)
      .def_readonly("largest_input_step", &FittedDomain::largest_input_step,
                    "max |v[k] - v[k-1]| [input units per sample]")
      .def_readonly("longest_hold_samples", &FittedDomain::longest_hold_samples,
                    "the most consecutive samples without a reversal of the input")
      .def_readonly("sample_time", &FittedDomain::sample_time, "[s], or None")
      .def_readonly("largest_time_constant", &FittedDomain::largest_time_constant,
                    "[s] of a model with lags (creep), or None")
      .def_property_readonly("duration", &FittedDomain::duration, "[s], or None")
      .def_property_readonly("largest_input_rate", &FittedDomain::largest_input_rate,
                             "[input units / s], or None")
      .def_property_readonly("longest_hold", &FittedDomain::longest_hold,
                             "[s] without a reversal of the input, or None")
      .def(
          "check_timing",
          [](const FittedDomain& d, const InputArray& input, std::optional<double> sample_time) {
            const auto values = as_span(input, "input");
            const auto check = check_timing(d, values, sample_time);
            return std::make_pair(check.inside(), check.message(values.size()));
          },
          "input"_a, "sample_time"_a = py::none(),
          "(inside, message) of the input's rates and holds at `sample_time` [s] (None: the "
          "model's own): rates above the fitted largest by more than 5 %, holds longer than the "
          "largest time constant.")
      .def(
          "check_inputs",
          [](const FittedDomain& d, const InputArray& input) {
            const auto values = as_span(input, "input");
            const auto check = check_inputs(d, values);
            return std::make_pair(check.inside(), check.message(values.size()));
          },
          "input"_a,
          "(inside, message): whether every input lies within the fitted input range widened "
          "by 5 % of its width, and else how many samples do not and where the first is.")
      .def(
          "check_targets",
          [](const FittedDomain& d, const InputArray& targets) {
            const auto values = as_span(targets, "targets");
            const auto check = check_targets(d, values);
            return std::make_pair(check.inside(), check.message(values.size()));
          },
          "targets"_a, "(inside, message) of inverse targets against the fitted output range.");

  py::class_<FitReport>(module, "FitReport",
                        "Outcome of a fit. str() gives brief(), full() a table of every field.")
      .def_readonly("model", &FitReport::model)
      .def_readonly("method", &FitReport::method)
      .def_readonly("termination", &FitReport::termination)
      .def_readonly("message", &FitReport::message)
      .def_readonly("iterations", &FitReport::iterations)
      .def_readonly("initial_cost", &FitReport::initial_cost, "0.5 sum e^2 before fitting")
      .def_readonly("final_cost", &FitReport::final_cost, "0.5 sum e^2 of the fitted model")
      .def_readonly("parameters", &FitReport::parameters, "number of fitted parameters")
      .def_readonly("fit", &FitReport::fit, "ErrorMetrics on the samples used for fitting")
      .def_readonly("validation", &FitReport::validation,
                    "ErrorMetrics on held-out samples, or None")
      .def_readonly("seconds", &FitReport::seconds, "wall time of the fit [s]")
      .def_property_readonly(
          "status", [](const FitReport& r) { return std::string(r.status()); },
          "converged, iteration limit, no progress, degenerate, unstable or failed")
      .def_readonly("quality_note", &FitReport::quality_note,
                    "Why the simulation is degenerate or unstable ('' otherwise)")
      .def_readonly("references", &FitReport::references,
                    "Reference predictors scored on the held-out part (the yardstick)")
      .def_property_readonly(
          "beats_yardstick", [](const FitReport& r) { return r.beats_yardstick(); },
          "True/False against the best reference predictor, None without one")
      .def_readonly("preprocessing", &FitReport::preprocessing,
                    "how the record was prepared before fitting, one line per step")
      .def_readonly("validation_rule", &FitReport::validation_rule,
                    "how the validation was predicted, in words (empty: no validation)")
      .def_readonly("domain", &FitReport::domain,
                    "FittedDomain of the fit part, or None (a fitter outside hyst.fit)")
      .def("brief", &FitReport::brief, "One paragraph.")
      .def("full", &FitReport::full, "A multi-line table of every field.")
      .def("__str__", &FitReport::brief)
      .def("__repr__", &report_repr);

  py::class_<DataSplit>(module, "DataSplit",
                        "Index ranges [begin, end) of the fit part and the validation part after "
                        "it (samples are never shuffled: hysteresis has memory).")
      .def_readonly("fit_begin", &DataSplit::fit_begin)
      .def_readonly("fit_end", &DataSplit::fit_end)
      .def_readonly("validation_begin", &DataSplit::validation_begin)
      .def_readonly("validation_end", &DataSplit::validation_end)
      .def("fit_size", &DataSplit::fit_size)
      .def("validation_size", &DataSplit::validation_size)
      .def("has_validation", &DataSplit::has_validation)
      .def("__repr__", [](const DataSplit& s) {
        return fmt::format("DataSplit(fit=[{}, {}), validation=[{}, {}))", s.fit_begin, s.fit_end,
                           s.validation_begin, s.validation_end);
      });
  module.def("split_by_fraction", &split_by_fraction, "samples"_a, "validate_fraction"_a,
             "The last `validate_fraction` of the samples for validation, the rest for fitting.");

  module.def(
      "pi_default_thresholds",
      [](const InputArray& input, std::size_t operators) {
        return to_array(pi_default_thresholds(as_span(input, "input"), operators));
      },
      "input"_a, "operators"_a,
      "Uniform thresholds j (v_max - v_min) / (2 operators) over the range of `input`.");
  module.def(
      "pi_periodic_state",
      [](const PrandtlIshlinskii& model, const InputArray& input) {
        return pi_periodic_state(model, as_span(input, "input"));
      },
      "model"_a, "input"_a,
      "The periodic steady state for a record that is one period of its input.");

  const PiFitOptions defaults;
  module.def(
      "fit_prandtl_ishlinskii",
      [](const InputArray& input, const InputArray& output,
         const std::optional<InputArray>& validation_input,
         const std::optional<InputArray>& validation_output, std::size_t operators,
         const std::optional<InputArray>& thresholds, bool fit_offset, double min_linear_weight,
         std::string_view initial_state, double validate_fraction) {
        if (validation_input.has_value() != validation_output.has_value()) {
          throw Error("validation_input and validation_output must be given together");
        }
        PiFitOptions options;
        options.operators = operators;
        if (thresholds) options.thresholds = as_vector(*thresholds, "thresholds");
        options.fit_offset = fit_offset;
        options.min_linear_weight = min_linear_weight;
        options.initial_state = pi_initial_state_from_string(initial_state);
        options.validate_fraction = validate_fraction;
        const auto in = as_span(input, "input");
        const auto out = as_span(output, "output");
        std::optional<PiFit> fit;
        if (validation_input) {
          const auto vin = as_span(*validation_input, "validation_input");
          const auto vout = as_span(*validation_output, "validation_output");
          py::gil_scoped_release release;
          fit.emplace(fit_prandtl_ishlinskii(in, out, vin, vout, options));
        } else {
          py::gil_scoped_release release;
          fit.emplace(fit_prandtl_ishlinskii(in, out, options));
        }
        return py::make_tuple(std::move(fit->model), std::move(fit->initial_state),
                              std::move(fit->report));
      },
      "input"_a, "output"_a, "validation_input"_a = py::none(), "validation_output"_a = py::none(),
      py::kw_only(), "operators"_a = defaults.operators, "thresholds"_a = py::none(),
      "fit_offset"_a = defaults.fit_offset, "min_linear_weight"_a = defaults.min_linear_weight,
      "initial_state"_a = std::string(to_string(defaults.initial_state)),
      "validate_fraction"_a = defaults.validate_fraction,
      "Fits PI weights (and offset) by NNLS. Returns (model, initial_state, report): the model, "
      "the play state at the first sample of the record (all 0 for initial_state=\"virgin\", the "
      "steady state for \"periodic\") and a FitReport. Validation on a separate record "
      "(validation_input/validation_output) or on the last validate_fraction of this one.");
}

}  // namespace hyst::python
