// The model registry: any model by name, with parameters and state as Python dicts (JSON), model
// files, and fitting through the registry.

#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/core/error.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/export/export_c.hpp"
#include "hyst/export/export_fmu.hpp"
#include "hyst/identify/fitted_domain.hpp"
#include "hyst/registry/dynamic_model.hpp"
#include "hyst/registry/fitted_domain_file.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/registry/record_score.hpp"
#include "hyst/registry/timed_simulation.hpp"

namespace hyst::python {
namespace {

// The time axis of `sample_time=` or `time=` for a record of `samples` samples; none for neither.
std::optional<data::TimeAxis> record_time_axis(std::optional<double> sample_time,
                                               const std::optional<InputArray>& time,
                                               std::size_t samples) {
  if (sample_time && time) throw Error("give sample_time or time, not both");
  if (sample_time) {
    if (!(*sample_time > 0.0) || !std::isfinite(*sample_time))
      throw Error(fmt::format("sample_time = {} must be finite and > 0", *sample_time));
    return data::TimeAxis{*sample_time, {}};
  }
  if (!time) return std::nullopt;
  if (static_cast<std::size_t>(time->size()) != samples)
    throw Error(fmt::format("time has {} samples but input has {}", time->size(), samples));
  return data::time_axis(as_span(*time, "time"), "time");
}

const ModelRegistry& registry() {
  return ModelRegistry::builtin();
}

std::unique_ptr<DynamicModel> create_model(const std::string& name, const py::handle& params,
                                           const py::handle& state) {
  const auto& entry = registry().find(name);
  const auto params_json = python_to_json(params, "params");
  if (state.is_none()) return entry.create(params_json, nullptr);
  const auto state_json = python_to_json(state, "state");
  return entry.create(params_json, &state_json);
}

nlohmann::json info_json(const py::handle& info) {
  if (info.is_none()) return nlohmann::json::object();
  auto json = python_to_json(info, "info");
  if (!json.is_object()) throw Error("info must be a dict");
  return json;
}

// simulate() of a model into a new array, without the GIL.
py::array_t<double> simulate_into(DynamicModel& model, const InputArray& input) {
  const auto samples = as_span(input, "input");
  std::vector<double> output(samples.size());
  {
    py::gil_scoped_release release;
    model.simulate(samples, output);
  }
  return to_array(std::move(output));
}

// invert() of an inverse into a new array: (inputs, InverseReport).
InvertResult invert_into(DynamicInverse& inverse, const InputArray& targets) {
  const auto samples = as_span(targets, "targets");
  std::vector<double> inputs(samples.size());
  InverseReport report;
  {
    py::gil_scoped_release release;
    report = inverse.invert(samples, inputs);
  }
  return py::make_tuple(to_array(std::move(inputs)), report);
}

// The stateful objects of Model.runner() and Inverse.runner(): a copy that advances, and the
// copy it started as (for reset()).
struct ModelRunner {
  explicit ModelRunner(std::unique_ptr<DynamicModel> running)
      : model(std::move(running)), start(model->clone()) {}
  void reset() { model = start->clone(); }
  std::unique_ptr<DynamicModel> model;
  std::unique_ptr<DynamicModel> start;
};

struct InverseRunner {
  explicit InverseRunner(std::unique_ptr<DynamicInverse> running)
      : inverse(std::move(running)), start(inverse->clone()) {}
  void reset() { inverse = start->clone(); }
  std::unique_ptr<DynamicInverse> inverse;
  std::unique_ptr<DynamicInverse> start;
};

}  // namespace

void bind_registry(py::module_& module) {
  py::class_<ParameterInfo>(module, "ParameterInfo", "One entry of a model's parameter schema.")
      .def_readonly("name", &ParameterInfo::name)
      .def_readonly("type", &ParameterInfo::type)
      .def_readonly("unit", &ParameterInfo::unit)
      .def_readonly("description", &ParameterInfo::description)
      .def_readonly("default", &ParameterInfo::default_value,
                    "the value taken when the field is left out (text); empty when it must be "
                    "given or the description says what leaving it out means")
      .def("__repr__", [](const ParameterInfo& p) {
        return fmt::format("ParameterInfo(name='{}', type='{}', unit='{}')", p.name, p.type,
                           p.unit);
      });

  py::class_<ModelEntry>(module, "ModelEntry", "A registered model: see hyst.models().")
      .def_readonly("name", &ModelEntry::name)
      .def_readonly("description", &ModelEntry::description)
      .def_readonly("parameters", &ModelEntry::parameters)
      .def_readonly("fit_options", &ModelEntry::fit_options)
      .def_readonly("input_unit", &ModelEntry::input_unit,
                    "unit the parameters assume for the input ('A/m' for jiles_atherton); '' "
                    "for any")
      .def_readonly("output_unit", &ModelEntry::output_unit,
                    "unit the parameters assume for the output ('T' for jiles_atherton); '' for "
                    "any")
      .def_property_readonly("can_fit", &ModelEntry::can_fit, "True when hyst.fit() can fit it.")
      .def_property_readonly("can_fit_records", &ModelEntry::can_fit_records,
                             "True when hyst.fit_records() can fit several records together.")
      .def_property_readonly(
          "example_params",
          [](const ModelEntry& e) { return StrDict(py::dict(json_to_python(e.example_params))); },
          "A small valid parameter set, as a dict.")
      .def("__repr__", [](const ModelEntry& e) {
        return fmt::format("ModelEntry(name='{}', can_fit={}, description='{}')", e.name,
                           e.can_fit() ? "True" : "False", e.description);
      });

  module.def(
      "models",
      [] {
        std::vector<const ModelEntry*> entries;
        for (const auto& entry : registry().entries())
          entries.push_back(&entry);
        return entries;
      },
      py::return_value_policy::reference,
      "Every registered model (ModelEntry: name, description, parameters, can_fit, "
      "example_params).");
  module.def(
      "model_entry", [](std::string_view name) { return &registry().find(name); }, "name"_a,
      py::return_value_policy::reference, "The registry entry of a model; hyst.Error if unknown.");

  // Declared first, so that the signature lines of the runners' methods name it (hyst.Model).
  py::class_<DynamicModel> model(
      module, "Model",
      "Any registered model, chosen by name at run time, with its start state. Parameters and "
      "state are dicts in the model-file form, e.g. Model('pi', {'thresholds': [0, 0.3], "
      "'weights': [1, 0.5]}). A Model never changes when it runs: simulate() starts from the "
      "start state (or a state passed in) every time; runner() gives a stateful copy for "
      "step-by-step use.");
  py::class_<InverseRunner>(
      module, "InverseRunner",
      "An inverse with a running state, for step-by-step use (Inverse.runner()): every call "
      "continues where the previous one ended.")
      .def(
          "invert",
          [](InverseRunner& runner, const InputArray& targets) {
            return invert_into(*runner.inverse, targets);
          },
          "targets"_a,
          "Inputs that make the model produce `targets`, continuing from the running state "
          "(advanced): returns (inputs, InverseReport).")
      .def(
          "step",
          [](InverseRunner& runner, double target) {
            double input = 0.0;
            runner.inverse->invert(std::span<const double>(&target, 1),
                                   std::span<double>(&input, 1));
            return input;
          },
          "target"_a,
          "The input for one target, advancing the running state (an unreachable target gives "
          "the nearest reachable input; invert() reports it).")
      .def_property_readonly(
          "state",
          [](const InverseRunner& runner) {
            return StrDict(py::dict(json_to_python(runner.inverse->state())));
          },
          "The running state as a dict.")
      .def("reset", &InverseRunner::reset, "Back to the state the runner started from.");

  py::class_<DynamicInverse>(
      module, "Inverse",
      "The inverse of a hyst.Model (Model.inverse()). It never changes: invert() always starts "
      "from the inverse's start state, consistent with the model state it was made from. For a "
      "running state use runner().")
      .def(
          "invert",
          [](const DynamicInverse& inverse, const InputArray& targets) {
            return invert_into(*inverse.clone(), targets);
          },
          "targets"_a,
          "Inputs that make the model produce `targets`, from the inverse's start state (the "
          "inverse is unchanged): returns (inputs, InverseReport); saturation is reported, not "
          "raised.")
      .def(
          "runner", [](const DynamicInverse& inverse) { return InverseRunner(inverse.clone()); },
          "A stateful copy for step-by-step use, starting from the inverse's start state.")
      .def_property_readonly(
          "state",
          [](const DynamicInverse& inverse) {
            return StrDict(py::dict(json_to_python(inverse.state())));
          },
          "The start state as a dict.");

  py::class_<ModelRunner>(
      module, "ModelRunner",
      "A model with a running state, for step-by-step use (Model.runner()): every call "
      "continues where the previous one ended.")
      .def(
          "step",
          [](ModelRunner& runner, double input) {
            double output = 0.0;
            runner.model->simulate(std::span<const double>(&input, 1),
                                   std::span<double>(&output, 1));
            return output;
          },
          "input"_a, "The output for one input sample, advancing the running state.")
      .def(
          "simulate",
          [](ModelRunner& runner, const InputArray& input) {
            return simulate_into(*runner.model, input);
          },
          "input"_a, "The outputs for `input`, continuing from the running state (advanced).")
      .def_property(
          "state",
          [](const ModelRunner& runner) {
            return StrDict(py::dict(json_to_python(runner.model->state())));
          },
          [](ModelRunner& runner, const py::handle& state) {
            runner.model->set_state(python_to_json(state, "state"));
          },
          "The running state as a dict; assigning validates it.")
      .def("reset", &ModelRunner::reset, "Back to the state the runner started from.")
      .def(
          "inverse",
          [](const ModelRunner& runner, double input_min, double input_max) {
            return runner.model->inverse({input_min, input_max});
          },
          "input_min"_a = -kInfinity, "input_max"_a = kInfinity,
          "The inverse, started consistently with the running state (e.g. for feedforward "
          "after a run).")
      .def(
          "to_model", [](const ModelRunner& runner) { return runner.model->clone(); },
          "A hyst.Model whose start state is the running state.");

  model
      .def(py::init(&create_model), "name"_a, "params"_a, "state"_a = py::none(),
           "Builds a registered model; hyst.Error names a bad field (\"params.thresholds[1]: "
           "...\").")
      .def_property_readonly("name", [](const DynamicModel& m) { return std::string(m.name()); })
      .def_property_readonly(
          "params",
          [](const DynamicModel& m) { return StrDict(py::dict(json_to_python(m.params()))); },
          "The parameters as a dict (a copy).")
      .def_property(
          "state",
          [](const DynamicModel& m) { return StrDict(py::dict(json_to_python(m.state()))); },
          [](DynamicModel& m, const py::handle& state) {
            m.set_state(python_to_json(state, "state"));
          },
          "The start state as a dict: where simulate(), runner() and inverse() start, and what "
          "save_model() writes. Assigning validates it.")
      .def("reset", &DynamicModel::reset,
           "Sets the start state to the model's default initial state.")
      .def(
          "simulate",
          [](const DynamicModel& m, const InputArray& input, const py::handle& state,
             bool return_state, std::optional<double> sample_time,
             const std::optional<InputArray>& time)
              -> Typed<py::object,
                       "Union[numpy.ndarray[numpy.float64], Tuple[numpy.ndarray[numpy.float64], "
                       "Dict[str, Any]]]"> {
            const auto axis = record_time_axis(sample_time, time, input.size());
            // From the start state with nothing to return but the outputs: the model itself runs
            // on a copy of its state (a copy of the whole model costs more than the run for a
            // large Preisach grid).
            if (state.is_none() && !return_state && !axis) {
              const auto samples = as_span(input, "input");
              std::vector<double> y(samples.size());
              {
                py::gil_scoped_release release;
                m.simulate_from_state(samples, y);
              }
              return to_array(std::move(y));
            }
            auto run = m.clone();
            if (!state.is_none()) run->set_state(python_to_json(state, "state"));
            py::object output;
            if (axis) {
              const auto u = as_vector(input, "input");
              std::vector<double> y(u.size());
              {
                py::gil_scoped_release release;
                simulate_on_time_axis(run, *axis, u, y);
              }
              output = to_array(std::move(y));
            } else {
              output = simulate_into(*run, input);
            }
            if (!return_state) return output;
            return py::make_tuple(output, json_to_python(run->state()));
          },
          "input"_a, "state"_a = py::none(), "return_state"_a = false, py::kw_only(),
          "sample_time"_a = py::none(), "time"_a = py::none(),
          "The outputs for `input`, starting from `state` (a dict) or, when it is None, from the "
          "start state. The model is unchanged, so every call starts afresh; with "
          "return_state=True returns (outputs, final state dict), and passing that state to the "
          "next call continues the run. sample_time [s] or time (the samples' times [s], "
          "increasing) give the record's time axis: a model with time in it (time_dependence "
          "'continuous') is re-discretised at its step (run by run through a non-uniform time), a "
          "'discrete' one (NARX) refuses another sample time, a rate-independent one ignores "
          "time. Without either, the record is taken as sampled at the model's own sample time.")
      .def(
          "runner",
          [](const DynamicModel& m, const py::handle& state) {
            auto run = m.clone();
            if (!state.is_none()) run->set_state(python_to_json(state, "state"));
            return ModelRunner(std::move(run));
          },
          "state"_a = py::none(),
          "A stateful copy for step-by-step use (ModelRunner), starting from `state` or the start "
          "state.")
      .def_property_readonly(
          "time_dependence",
          [](const DynamicModel& m) { return std::string(to_string(m.time_dependence())); },
          "'none' (rate independent: time does not change the output), 'continuous' (lags or "
          "ODEs, re-discretised at any sample time) or 'discrete' (NARX: its own sample time "
          "only).")
      .def_property_readonly(
          "sample_time", [](const DynamicModel& m) { return m.sample_time(); },
          "The sample time [s] the model is discretised at, or None (rate independent, or a "
          "discrete model fitted without a time axis).")
      .def(
          "at_sample_time",
          [](const DynamicModel& m, double seconds) { return m.at_sample_time(seconds); },
          "seconds"_a,
          "The same model and start state at the sample time `seconds`: re-discretised "
          "(continuous), unchanged (rate independent), or hyst.Error naming both sample times "
          "(discrete, at another one).")
      .def("parameter_count", &DynamicModel::parameter_count)
      .def("describe", &DynamicModel::describe, "A few lines on the model and its parameters.")
      .def("has_inverse", &DynamicModel::has_inverse)
      .def(
          "inverse",
          [](const DynamicModel& m, double input_min, double input_max) {
            return m.inverse({input_min, input_max});
          },
          "input_min"_a = -kInfinity, "input_max"_a = kInfinity,
          "The inverse, started consistently with the model's start state (Model.state).")
      .def(
          "to_dict",
          [](const DynamicModel& m, const py::object& info) {
            return StrDict(py::dict(json_to_python(model_to_json(m, info_json(info)))));
          },
          "info"_a = py::none(), "The model-file document as a dict.")
      .def("__copy__", &DynamicModel::clone)
      .def(
          "__deepcopy__", [](const DynamicModel& m, py::dict) { return m.clone(); }, "memo"_a)
      .def("__repr__", [](const DynamicModel& m) {
        return fmt::format("hyst.Model('{}', params={}, state={})", m.name(), m.params().dump(),
                           m.state().dump());
      });

  module.def(
      "evaluate",
      [](const DynamicModel& m, const InputArray& input, const InputArray& output,
         std::string_view validation_start, std::string_view validation_align,
         std::optional<double> sample_time, const std::optional<InputArray>& time,
         const std::optional<FittedDomain>& domain) -> StrDict {
        const auto u = as_vector(input, "input");
        const auto y = as_vector(output, "output");
        const auto rule = saved_model_rule(validation_start, validation_align, "hyst.evaluate");
        const auto axis = record_time_axis(sample_time, time, u.size());
        if (axis && !axis->uniform() && m.time_dependence() != TimeDependence::none)
          throw Error(
              fmt::format("hyst.evaluate: time is not uniform (median step {:.6g} s) and "
                          "model '{}' depends on time: resample the record, or use "
                          "Model.simulate(time=...), which steps through it",
                          axis->sample_time, m.name()));
        const auto timed = axis ? at_record_sample_time(m.clone(), axis->sample_time) : m.clone();
        auto score = [&] {
          py::gil_scoped_release release;
          return score_on_record(*timed, u, y, rule);
        }();
        const auto figures = [](const PredictionScore& s) {
          py::dict d;
          d["rmse"] = s.metrics.rmse;
          d["nrmse_range_percent"] = s.metrics.nrmse_percent;
          d["nrmse_std_percent"] = s.nrmse_std_percent;
          d["max_error"] = s.metrics.max_error;
          return d;
        };
        py::dict out = figures(score.model);
        out["samples"] = score.model.metrics.samples;
        out["predicted"] = to_array(std::move(score.predicted));
        py::dict yardsticks;
        for (const auto& yardstick : score.yardsticks)
          yardsticks[py::str(yardstick.name)] = figures(yardstick.score);
        out["yardsticks_on_this_record"] = yardsticks;
        out["time_dependence"] = std::string(to_string(timed->time_dependence()));
        out["sample_time"] = timed->sample_time();
        if (domain) {
          const auto check = axis ? check_record_inputs(*domain, u, axis->sample_time, axis->steps)
                                  : check_record_inputs(*domain, u, std::nullopt);
          out["domain"] = domain_check_dict(check, u.size());
        } else {
          out["domain"] = py::none();
        }
        return out;
      },
      "model"_a, "input"_a, "output"_a, "validation_start"_a = "rest",
      "validation_align"_a = "none", py::kw_only(), "sample_time"_a = py::none(),
      "time"_a = py::none(), "domain"_a = py::none(),
      "A single-input Model scored on a measured record as `hyst evaluate --model m.json --data "
      "r.csv` and `hyst fit --validation-data` score it: predicted from validation_start "
      "('rest', 'periodic' or 'file': the model's start state), aligned by validation_align "
      "('none' or 'first-sample'); a dict with rmse, nrmse_range_percent, nrmse_std_percent, "
      "max_error, samples, the prediction and yardsticks_on_this_record (its mean and a static "
      "cubic y(v), fitted on this record), and the model's time_dependence and the sample_time "
      "it ran at. sample_time [s] or time (the samples' times [s]) give the record's time axis, "
      "as for Model.simulate (a model with time in it needs a uniform one here). domain (a "
      "FittedDomain: FitReport.domain, hyst.load_fitted_domain(path)) adds 'domain': {'inside', "
      "'message'} on the record's inputs, rates and holds (else None), as the CLI's warning.");
  module.def(
      "load_fitted_domain",
      [](const std::filesystem::path& path) { return load_fitted_domain(path); }, "path"_a,
      "The FittedDomain of a model file (its info.domain, written by hyst fit), or None.");
  module.def(
      "model_from_dict",
      [](const py::handle& document, std::string_view source) {
        return model_from_json(python_to_json(document, ""), source);
      },
      "document"_a, "source"_a = "<dict>",
      "A Model from a model-file document {'model': ..., 'version': 1, 'params': {...}, "
      "'state': {...}}.");
  module.def(
      "model_to_dict",
      [](const DynamicModel& m, const py::object& info) {
        return StrDict(py::dict(json_to_python(model_to_json(m, info_json(info)))));
      },
      "model"_a, "info"_a = py::none(), "The model-file document of a model in its current state.");
  module.def(
      "load_model", [](const std::filesystem::path& path) { return load_model(path); }, "path"_a,
      "Reads and validates a model file (JSON); hyst.Error names the file and the field.");
  module.def(
      "save_model",
      [](const std::filesystem::path& path, const DynamicModel& m, const py::object& info) {
        save_model(path, m, info_json(info));
      },
      "path"_a, "model"_a, "info"_a = py::none(),
      "Writes a model file atomically; `info` (a dict, e.g. the fit report) is stored as given.");

  module.def(
      "export_c",
      [](const DynamicModel& m, const std::filesystem::path& folder, const std::string& prefix,
         bool single, double input_min, double input_max, const std::string& source) -> StrDict {
        CExportOptions options;
        options.prefix = prefix;
        options.scalar = single ? CScalar::single_precision : CScalar::double_precision;
        options.limits = {input_min, input_max};
        options.source = source;
        const CCode code = export_c(m, folder, options);
        return py::dict("header"_a = folder / code.header_name,
                        "source"_a = folder / code.source_name, "has_inverse"_a = code.has_inverse);
      },
      "model"_a, "folder"_a, "prefix"_a = "", "float"_a = false,
      "input_min"_a = -std::numeric_limits<double>::infinity(),
      "input_max"_a = std::numeric_limits<double>::infinity(), "source"_a = "",
      "Writes the model (and its inverse, where there is one) as dependency-free C99 code: "
      "<prefix>.h and <prefix>.c in an existing folder (as `hyst export --lang c`). Returns "
      "{'header', 'source', 'has_inverse'}.");

  module.def(
      "export_fmu",
      [](const DynamicModel& m, const std::filesystem::path& folder, const std::string& prefix,
         bool single, bool inverse, const std::string& input_name, const std::string& output_name,
         const std::string& input_unit, const std::string& output_unit, double input_min,
         double input_max, const std::string& compiler, const std::string& source) -> StrDict {
        FmuExportOptions options;
        options.code.prefix = prefix;
        options.code.scalar = single ? CScalar::single_precision : CScalar::double_precision;
        options.code.limits = {input_min, input_max};
        options.code.source = source;
        options.inverse = inverse;
        options.input_name = input_name;
        options.output_name = output_name;
        options.input_unit = input_unit;
        options.output_unit = output_unit;
        options.compiler = compiler;
        FmuFiles files;
        {
          py::gil_scoped_release release;
          files = export_fmu(m, folder, options);
        }
        return py::dict("model"_a = files.model, "inverse"_a = files.inverse.empty()
                                                                   ? py::object(py::none())
                                                                   : py::cast(files.inverse));
      },
      "model"_a, "folder"_a, "prefix"_a = "", "float"_a = false, "inverse"_a = false,
      "input_name"_a = "u", "output_name"_a = "y", "input_unit"_a = "", "output_unit"_a = "",
      "input_min"_a = -std::numeric_limits<double>::infinity(),
      "input_max"_a = std::numeric_limits<double>::infinity(), "compiler"_a = "", "source"_a = "",
      "Writes the model as an FMI 2.0 co-simulation FMU, <prefix>.fmu in `folder` (created when "
      "missing), and with inverse=True its inverse compensator as <prefix>_inverse.fmu (as "
      "`hyst export --lang fmu`). The binary is built by `compiler` ($CC or cc by default). "
      "Returns {'model', 'inverse'} (paths; inverse None when not asked for).");

  module.def(
      "fit",
      [](const std::string& name, const InputArray& input, const InputArray& output,
         const std::optional<InputArray>& validation_input,
         const std::optional<InputArray>& validation_output, std::optional<std::string> cycles,
         bool detrend, std::string_view resample, double resample_step, double band,
         std::string_view validation_start, std::string_view validation_align,
         const std::optional<InputArray>& time, const py::object& progress,
         const py::kwargs& options) {
        const auto& entry = registry().find(name);
        if (!entry.can_fit()) {
          throw Error(fmt::format("model '{}' has no fitter", name));
        }
        if (validation_input.has_value() != validation_output.has_value()) {
          throw Error("validation_input and validation_output must be given together");
        }
        FitRequest request;
        request.input = as_span(input, "input");
        request.output = as_span(output, "output");
        if (validation_input) {
          request.validation_input = as_span(*validation_input, "validation_input");
          request.validation_output = as_span(*validation_output, "validation_output");
        }
        request.validation.start = validation_start_from_string(validation_start);
        request.validation.align = validation_alignment_from_string(validation_align);
        request.options = python_to_json(options, "");
        if (time) {
          if (request.options.contains("sample_time"))
            throw Error("time and sample_time both give the sample time: give one");
          if (!fits_sample_time(entry))
            throw Error(
                fmt::format("time: model '{}' has no sample time (its output depends on "
                            "the order of the samples only)",
                            name));
          if (time->size() != input.size())
            throw Error(
                fmt::format("time has {} samples but input has {}", time->size(), input.size()));
          request.options["sample_time"] =
              data::uniform_sample_time(as_span(*time, "time"), "time");
        }
        request.preprocessing.band = band;
        request.preprocessing.detrend = detrend;
        if (cycles) request.preprocessing.cycles = data::cycle_range_from_string(*cycles);
        request.preprocessing.resample = data::resample_method_from_string(resample);
        request.preprocessing.resample_step = resample_step;
        request.progress = progress_callback(progress);
        std::optional<FitOutcome> outcome;
        {
          py::gil_scoped_release release;
          outcome.emplace(fit_model(entry, request));
        }
        return py::make_tuple(std::move(outcome->model), std::move(outcome->report));
      },
      "name"_a, "input"_a, "output"_a, "validation_input"_a = py::none(),
      "validation_output"_a = py::none(), py::kw_only(), "cycles"_a = py::none(),
      "detrend"_a = false, "resample"_a = "none", "resample_step"_a = 0.0, "band"_a = 0.0,
      "validation_start"_a = "rest", "validation_align"_a = "none", "time"_a = py::none(),
      "progress"_a = py::none(),
      "Fits a registered model by name: returns (Model, FitReport). time (the samples' times "
      "[s], uniform) gives a model with time in it its sample time (as the fit option "
      "sample_time). A separate validation record "
      "is predicted from validation_start: \"rest\" (the model's initial state), \"periodic\" "
      "(the record's own periodic steady state) or \"continue\" (where the fit record ended), "
      "with validation_align=\"first-sample\" shifting the prediction to the measured first "
      "sample; report.validation_rule says which. Keyword options are the "
      "model's fit options (see ModelEntry.fit_options), e.g. operators=20, "
      "initial_state=\"periodic\". The record can be prepared first (hyst.data.preprocess): "
      "detrend=True removes drift between cycles, cycles=\"2-3\" keeps those cycles, "
      "resample=\"input-grid\" or \"arc-length\" (step resample_step, 0 = automatic) "
      "resamples each branch; band is the hysteresis band (0 = 2 % of the input range). "
      "detrend also removes the drift of validation_input/validation_output (drift is a "
      "measurement artefact); cycles and resampling are fit-only. FitReport.preprocessing "
      "lists the steps applied. progress: progress(done, total, current) as a fitter with "
      "several starts (GPI, Bouc-Wen, Duhem, Jiles-Atherton, NARX, ...) runs them; the package's "
      "hyst.fit also takes True (a tqdm bar, or lines on standard error).");
  module.def(
      "fit_records",
      [](const std::string& name, const py::sequence& records,
         const std::optional<std::vector<double>>& sample_times, const py::kwargs& options) {
        const auto& entry = registry().find(name);
        if (!entry.can_fit_records()) {
          std::string names;
          for (const auto& other : registry().entries()) {
            if (other.can_fit_records()) names += (names.empty() ? "" : ", ") + other.name;
          }
          throw Error(fmt::format("model '{}' has no fit of several records (models with one: {})",
                                  name, names));
        }
        require_fit_record_count(records.size());
        const auto options_json = python_to_json(options, "");
        const auto owned = curves_from_python(records, "records");
        const auto views = fit_records_of(owned);
        const std::vector<double> times = sample_times.value_or(std::vector<double>{});
        std::optional<FitOutcome> outcome;
        naming_failed_allocation(fmt::format("fitting '{}' to {} records", name, views.size()),
                                 [&] {
                                   py::gil_scoped_release release;
                                   outcome.emplace(entry.fit_records(views, times, options_json));
                                 });
        return py::make_tuple(std::move(outcome->model), std::move(outcome->report));
      },
      "name"_a, "records"_a, "sample_times"_a = py::none(),
      "Fits one registered model to several records together, a sequence of (input, output) "
      "pairs (e.g. one actuator driven at several rates): returns (Model, FitReport), the report "
      "over every record. sample_times: one per record [s] for the models with a sample time "
      "(each record is then discretised at its own; the model at the first's), or None for the "
      "option sample_time on every record. Keyword options are the model's fit options. Models "
      "with this fit: ModelEntry.can_fit_records.");
}

}  // namespace hyst::python
