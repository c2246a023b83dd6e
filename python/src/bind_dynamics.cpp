// Linear dynamics: the MIMO state-space model, the best linear approximation of periodic
// experiments, the state-space fit and the benchmark score. Signals are numpy arrays: a record is
// (samples, channels); periodic data are (N, channel, realisation, period) unless a layout says
// otherwise (hyst::io::arrange_periodic).

#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/eigen.h>

#include "bindings.hpp"
#include "hyst/core/error.hpp"
#include "hyst/dynamics/best_linear_approximation.hpp"
#include "hyst/dynamics/fit_hammerstein.hpp"
#include "hyst/dynamics/fit_hysteretic_lfr.hpp"
#include "hyst/dynamics/fit_state_space.hpp"
#include "hyst/dynamics/free_run_check.hpp"
#include "hyst/dynamics/initial_state_estimate.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/dynamics/state_space.hpp"
#include "hyst/io/numpy_file.hpp"
#include "hyst/registry/hysteretic_lfr_file.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/registry/state_space_file.hpp"

namespace hyst::python {
namespace {

constexpr const char* kDefaultLayout = "N,channel,realisation,period";

using AnyArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

//! A numpy array of any dimension as periodic signals, its axes named by `layout`; None and
//! arrays above the limit of files are refused by `name` before anything is copied.
PeriodicSignals periodic_signals(const py::object& value, const std::string& layout,
                                 const std::string& name) {
  const AnyArray array = as_bounded_array(value, name);
  if (array.ndim() == 0)
    throw Error(fmt::format("{} is a single number; expected an array of periodic signals", name));
  // The layout names as many axes as the array has: its first ones.
  std::string used;
  std::size_t axes = 0;
  for (std::size_t start = 0; start <= layout.size() && axes < std::size_t(array.ndim()); ++axes) {
    const std::size_t comma = std::min(layout.find(',', start), layout.size());
    if (!used.empty()) used += ',';
    used.append(layout, start, comma - start);
    start = comma + 1;
  }
  // Two copies of the values: the array's, then the arrangement's.
  return naming_failed_allocation(
      fmt::format("arranging {} ({} values) as periodic signals", name, array.size()), [&] {
        io::NumpyArray values;
        for (py::ssize_t d = 0; d < array.ndim(); ++d)
          values.shape.push_back(static_cast<std::size_t>(array.shape(d)));
        values.values.assign(array.data(), array.data() + array.size());
        return io::arrange_periodic(values, used, name);
      });
}

//! A record (samples, channels) as a matrix; None and arrays above the limit of files are refused
//! by `name` before the record is copied.
Eigen::MatrixXd bounded_record(const py::object& value, const std::string& name) {
  const AnyArray array = as_bounded_array(value, name);
  return naming_failed_allocation(fmt::format("copying {} ({} values)", name, array.size()),
                                  [&] { return array.cast<Eigen::MatrixXd>(); });
}

std::vector<PeriodicExperiment> experiments_of(const py::sequence& pairs,
                                               const std::string& layout) {
  require_fit_record_count(pairs.size());
  std::vector<PeriodicExperiment> experiments;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto pair = pairs[i].cast<py::sequence>();
    if (pair.size() != 2)
      throw Error(fmt::format("experiments[{}]: expected an (input, output) pair", i));
    experiments.push_back(
        {periodic_signals(pair[0], layout, fmt::format("experiments[{}] input", i)),
         periodic_signals(pair[1], layout, fmt::format("experiments[{}] output", i))});
  }
  return experiments;
}

//! Per-frequency matrices as one (F, rows, cols) array.
template <class Matrix>
py::array stack(const std::vector<Matrix>& matrices) {
  using Scalar = typename Matrix::Scalar;
  const auto rows = matrices.empty() ? 0 : matrices[0].rows();
  const auto cols = matrices.empty() ? 0 : matrices[0].cols();
  py::array_t<Scalar> out({py::ssize_t(matrices.size()), py::ssize_t(rows), py::ssize_t(cols)});
  auto view = out.template mutable_unchecked<3>();
  for (std::size_t f = 0; f < matrices.size(); ++f)
    for (Eigen::Index i = 0; i < rows; ++i)
      for (Eigen::Index j = 0; j < cols; ++j)
        view(py::ssize_t(f), i, j) = matrices[f](i, j);
  return out;
}

Typed<py::object, "Optional[numpy.ndarray[numpy.float64]]"> stack_or_none(
    const std::vector<Eigen::MatrixXd>& matrices) {
  return matrices.empty() ? py::object(py::none()) : py::object(stack(matrices));
}

StrDict score_dict(const SimulationScore& score) {
  std::vector<double> rmse, relative, deviation;
  for (const auto& c : score.channels) {
    rmse.push_back(c.rmse);
    relative.push_back(c.relative_error);
    deviation.push_back(c.output_std);
  }
  py::dict out;
  out["rmse"] = to_array(std::move(rmse));
  out["relative_error"] = to_array(std::move(relative));
  out["output_std"] = to_array(std::move(deviation));
  out["mean_rmse"] = score.mean_rmse;
  out["mean_relative_error"] = score.mean_relative_error;
  out["scored_samples"] = score.scored_samples;
  return out;
}

SimulationScore score_model(const StateSpace& model, const PeriodicSignals& u,
                            const PeriodicSignals& y, const ScoreOptions& options) {
  return score_state_space(model, u, y, options);
}
SimulationScore score_model(const AnyHystereticLfr& model, const PeriodicSignals& u,
                            const PeriodicSignals& y, const ScoreOptions& options) {
  return score_hysteretic_lfr(model, u, y, options);
}

// A RuntimeWarning when the linear block has a pole outside the unit circle: its free run
// grows without bound (free_run_check.hpp); the simulation itself goes on.
void warn_if_unstable(const StateSpace& linear) {
  if (!(linear.spectral_radius() > kUnstablePoleMagnitude)) return;
  const auto text = free_run_warnings(linear, RunawayCount{}).front();
  if (PyErr_WarnEx(PyExc_RuntimeWarning, text.c_str(), 1) != 0) throw py::error_already_set();
}

const StateSpace& linear_block(const StateSpace& model) {
  return model;
}
const StateSpace& linear_block(const AnyHystereticLfr& model) {
  return model.linear();
}

template <class Model>
StrDict evaluate_model(const Model& model, const py::object& input, const py::object& output,
                       const std::string& layout, bool periodic, std::size_t transient,
                       bool strict) {
  const auto u = periodic_signals(input, layout, "input");
  const auto y = periodic_signals(output, layout, "output");
  const auto score =
      naming_failed_allocation(fmt::format("scoring the model ({} states) on {} input values",
                                           model.order(), u.values.size()),
                               [&] {
                                 py::gil_scoped_release release;
                                 return score_model(model, u, y, {periodic, transient});
                               });
  const auto warnings = free_run_warnings(linear_block(model), score.runaway);
  if (strict && !warnings.empty()) throw Error(warnings.front() + " (strict=True)");
  auto out = score_dict(score);
  out["warnings"] = warnings;
  out["runaway_samples"] = score.runaway.samples;
  return out;
}

// A fit of a model with hysteresis from a linear model (fit_hysteretic_lfr, fit_hammerstein),
// run without the GIL; it returns (HystereticLfr, FitReport).
template <typename Options, typename Fit>
void def_hysteresis_fit(py::module_& module, const char* name, Fit fit, const char* doc) {
  const Options defaults;
  const auto run = [fit](const StateSpace& linear, const py::sequence& experiments,
                         const std::string& layout, const Options& options) {
    const auto data = experiments_of(experiments, layout);
    auto result = naming_failed_allocation(
        fmt::format("fitting a {}-state model with {} thresholds per channel to {} experiments",
                    linear.order(), options.threshold_fractions.size(), data.size()),
        [&] {
          py::gil_scoped_release release;
          return fit(linear, data, options);
        });
    return py::make_tuple(any_hysteretic_lfr(result.model), std::move(result.report));
  };
  const auto options = [](const std::vector<double>& threshold_fractions, bool fit_poles,
                          bool fit_io_matrices, double max_pole_radius, std::size_t max_iterations,
                          std::size_t threads, const py::object& progress) {
    return Options{.threshold_fractions = threshold_fractions,
                   .max_iterations = max_iterations,
                   .threads = threads,
                   .fit_poles = fit_poles,
                   .fit_io_matrices = fit_io_matrices,
                   .max_pole_radius = max_pole_radius,
                   .progress = progress_callback(progress)};
  };
  if constexpr (requires { defaults.general_iterations; }) {
    module.def(
        name,
        [run, options](
            const StateSpace& linear, const py::sequence& experiments, const std::string& layout,
            const std::vector<double>& threshold_fractions, bool fit_poles, bool fit_io_matrices,
            double max_pole_radius, std::size_t max_iterations, std::size_t general_iterations,
            std::size_t feedback_channels, std::size_t threads, const py::object& progress) {
          auto o = options(threshold_fractions, fit_poles, fit_io_matrices, max_pole_radius,
                           max_iterations, threads, progress);
          o.general_iterations = general_iterations;
          o.feedback_channels = feedback_channels;
          return run(linear, experiments, layout, o);
        },
        "linear"_a, "experiments"_a, "layout"_a = kDefaultLayout,
        "threshold_fractions"_a = defaults.threshold_fractions, "fit_poles"_a = defaults.fit_poles,
        "fit_io_matrices"_a = defaults.fit_io_matrices,
        "max_pole_radius"_a = defaults.max_pole_radius,
        "max_iterations"_a = defaults.max_iterations,
        "general_iterations"_a = defaults.general_iterations,
        "feedback_channels"_a = defaults.feedback_channels, "threads"_a = defaults.threads,
        "progress"_a = py::none(), doc);
  } else {
    module.def(
        name,
        [run, options](const StateSpace& linear, const py::sequence& experiments,
                       const std::string& layout, const std::vector<double>& threshold_fractions,
                       bool fit_poles, bool fit_io_matrices, double max_pole_radius,
                       std::size_t max_iterations, std::size_t threads,
                       const py::object& progress) {
          return run(linear, experiments, layout,
                     options(threshold_fractions, fit_poles, fit_io_matrices, max_pole_radius,
                             max_iterations, threads, progress));
        },
        "linear"_a, "experiments"_a, "layout"_a = kDefaultLayout,
        "threshold_fractions"_a = defaults.threshold_fractions, "fit_poles"_a = defaults.fit_poles,
        "fit_io_matrices"_a = defaults.fit_io_matrices,
        "max_pole_radius"_a = defaults.max_pole_radius,
        "max_iterations"_a = defaults.max_iterations, "threads"_a = defaults.threads,
        "progress"_a = py::none(), doc);
  }
}

}  // namespace

void bind_dynamics(py::module_& module) {
  py::class_<StateSpace>(module, "StateSpace",
                         "Discrete-time MIMO linear state-space model x[k+1] = A x[k] + B u[k], "
                         "y[k] = C x[k] + D u[k] at sample time Ts. Records are (samples, "
                         "channels) arrays.")
      .def(py::init([](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::MatrixXd& c,
                       const Eigen::MatrixXd& d, double sample_time) {
             return StateSpace(StateSpace::Params{a, b, c, d, sample_time});
           }),
           "a"_a, "b"_a, "c"_a, "d"_a, "sample_time"_a = 1.0)
      .def_static("from_continuous", &StateSpace::from_continuous, "a"_a, "b"_a, "c"_a, "d"_a,
                  "sample_time"_a,
                  "Exact zero-order-hold discretisation of dx/dt = a x + b u, y = c x + d u.")
      .def_property_readonly("a", [](const StateSpace& m) { return m.params().a; })
      .def_property_readonly("b", [](const StateSpace& m) { return m.params().b; })
      .def_property_readonly("c", [](const StateSpace& m) { return m.params().c; })
      .def_property_readonly("d", [](const StateSpace& m) { return m.params().d; })
      .def_property_readonly("sample_time", &StateSpace::sample_time, "Ts [s]")
      .def_property_readonly("order", &StateSpace::order, "Number of states n")
      .def_property_readonly("inputs", &StateSpace::inputs, "Number of inputs m")
      .def_property_readonly("outputs", &StateSpace::outputs, "Number of outputs p")
      .def(
          "simulate",
          [](const StateSpace& m, const py::object& input,
             const std::optional<Eigen::VectorXd>& initial_state) {
            const auto u = bounded_record(input, "input");
            auto state = initial_state ? m.make_state(*initial_state) : m.initial_state();
            warn_if_unstable(m);
            py::gil_scoped_release release;
            return m.simulate(u, state);
          },
          "input"_a, "initial_state"_a = py::none(),
          "Outputs (samples, p) for inputs (samples, m), from rest or from `initial_state`; a "
          "RuntimeWarning when a pole lies outside the unit circle (the free run grows).")
      .def(
          "estimate_initial_state",
          [](const StateSpace& m, const py::object& input, const py::object& output,
             std::size_t samples) {
            const auto u = bounded_record(input, "input");
            const auto y = bounded_record(output, "output");
            py::gil_scoped_release release;
            const auto estimate = estimate_initial_state(m, u, y, samples);
            return std::make_tuple(estimate.state, estimate.rms_residual);
          },
          "input"_a, "output"_a, "samples"_a,
          "(state, rms_residual): the state x0 that the first `samples` rows of input (N, m) and "
          "output (N, p) show, by least squares (the benchmarks' n_init rule); simulate(input, "
          "initial_state=state) then continues the record.")
      .def("periodic_state", &StateSpace::periodic_state, "one_period"_a,
           "The state one period of the periodic input (N, m) returns to.")
      .def("simulate_periodic", &StateSpace::simulate_periodic, "one_period"_a,
           "Outputs (N, p) over one period in periodic steady state.")
      .def(
          "frequency_response",
          [](const StateSpace& m, const InputArray& frequencies) {
            return stack(m.frequency_response(as_span(frequencies, "frequencies")));
          },
          "frequencies"_a, "G(exp(j 2 pi f Ts)) as a complex (F, p, m) array; f in Hz.")
      .def("poles", &StateSpace::poles, "Eigenvalues of A (complex).")
      .def("spectral_radius", &StateSpace::spectral_radius, "Largest pole magnitude.")
      .def("is_stable", &StateSpace::is_stable, "Every pole strictly inside the unit circle.")
      .def(
          "save",
          [](const StateSpace& m, const std::filesystem::path& path, const py::object& info) {
            save_state_space(
                path, m, std::nullopt,
                info.is_none() ? nlohmann::json::object() : python_to_json(info, "info"));
          },
          "path"_a, "info"_a = py::none(), "Writes the model file (JSON) atomically.")
      .def("__repr__", [](const StateSpace& m) {
        return fmt::format("<StateSpace: {} states, {} inputs, {} outputs, Ts = {:g} s>", m.order(),
                           m.inputs(), m.outputs(), m.sample_time());
      });
  module.def(
      "load_state_space",
      [](const std::filesystem::path& path) { return load_state_space(path).model; }, "path"_a,
      "A state-space model from its model file.");

  py::class_<BestLinearApproximation>(
      module, "BestLinearApproximation",
      "Frequency response of the best linear approximation at the excited lines, with its noise "
      "and total (noise and nonlinear distortion) variances.")
      .def_readonly("sample_time", &BestLinearApproximation::sample_time, "Ts [s]")
      .def_readonly("samples", &BestLinearApproximation::samples, "N per period")
      .def_readonly("lines", &BestLinearApproximation::lines, "Excited DFT lines")
      .def_readonly("blocks", &BestLinearApproximation::blocks, "Blocks of m realisations")
      .def_readonly("periods", &BestLinearApproximation::periods, "Periods per block")
      .def_property_readonly(
          "frequencies", [](const BestLinearApproximation& b) { return to_array(b.frequencies()); },
          "Frequencies of the lines [Hz]")
      .def_property_readonly(
          "response", [](const BestLinearApproximation& b) { return stack(b.response); },
          "Complex (F, p, m) array")
      .def_property_readonly(
          "noise_variance",
          [](const BestLinearApproximation& b) { return stack_or_none(b.noise_variance); },
          "(F, p, m) variances from the noise, or None with one period")
      .def_property_readonly(
          "total_variance",
          [](const BestLinearApproximation& b) { return stack_or_none(b.total_variance); },
          "(F, p, m) variances from noise and distortions, or None with one block")
      .def("__repr__", [](const BestLinearApproximation& b) {
        return fmt::format("<BestLinearApproximation: {} lines, {} outputs x {} inputs, {} blocks>",
                           b.lines.size(), b.outputs(), b.inputs(), b.blocks);
      });
  module.def(
      "estimate_bla",
      [](const py::sequence& experiments, double sample_time, const std::string& layout,
         double excitation_threshold, std::size_t transient_periods) {
        const auto data = experiments_of(experiments, layout);
        py::gil_scoped_release release;
        return estimate_bla(data, sample_time, {excitation_threshold, transient_periods});
      },
      "experiments"_a, "sample_time"_a, "layout"_a = kDefaultLayout,
      "excitation_threshold"_a = BlaOptions{}.excitation_threshold, "transient_periods"_a = 0,
      "The best linear approximation of periodic experiments, a sequence of (input, output) "
      "arrays whose axes `layout` names (axes beyond the array's are left out).");

  module.def(
      "fit_state_space",
      [](const BestLinearApproximation& bla, std::size_t order, const std::string& weighting,
         std::size_t max_iterations, std::size_t subspace_block_rows, double max_pole_radius,
         const py::object& progress) {
        StateSpaceFitOptions options;
        options.order = order;
        options.weighting = bla_weighting_from_string(weighting);
        options.max_iterations = max_iterations;
        options.subspace_block_rows = subspace_block_rows;
        options.max_pole_radius = max_pole_radius;
        options.progress = progress_callback(progress);
        auto fit = naming_failed_allocation(
            fmt::format("fitting a state-space model of order {} to {} lines", order,
                        bla.lines.size()),
            [&] {
              py::gil_scoped_release release;
              return fit_state_space(bla, options);
            });
        return py::make_tuple(std::move(fit.model), std::move(fit.report));
      },
      "bla"_a, "order"_a, "weighting"_a = "none", "max_iterations"_a = 200,
      "subspace_block_rows"_a = 0, "max_pole_radius"_a = StateSpaceFitOptions{}.max_pole_radius,
      "progress"_a = py::none(),
      "A state-space model of `order` states fitted to a BLA (frequency-domain subspace, then "
      "Levenberg-Marquardt); returns (StateSpace, FitReport). weighting: none, total_variance or "
      "noise_variance.");

  py::class_<AnyHystereticLfr>(
      module, "HystereticLfr",
      "Linear block with hysteresis in its feedback (an LFR): the StateSpace `linear` has the "
      "inputs (u, w) and the outputs (y, z); each hysteresis model maps z_i to w_i (all of one "
      "kind among the actuator force models, e.g. 'pi'). HystereticLfr.hammerstein() builds the "
      "Hammerstein system (a block per input, then the linear block). Records are (samples, "
      "channels) arrays.")
      .def(py::init([](const StateSpace& linear, std::size_t inputs,
                       const std::vector<const DynamicModel*>& feedback) {
             return AnyHystereticLfr(linear, inputs, feedback);
           }),
           "linear"_a, "inputs"_a, "feedback"_a)
      .def_static(
          "hammerstein",
          [](const StateSpace& linear, const std::vector<const DynamicModel*>& blocks) {
            return AnyHystereticLfr::hammerstein(linear, blocks);
          },
          "linear"_a, "blocks"_a, "blocks[i] on input i, then the linear block.")
      .def_property_readonly("linear", &AnyHystereticLfr::linear,
                             "The linear block (inputs u then w, outputs y then z).")
      .def_property_readonly("inputs", &AnyHystereticLfr::inputs)
      .def_property_readonly("outputs", &AnyHystereticLfr::outputs)
      .def_property_readonly("order", &AnyHystereticLfr::order)
      .def_property_readonly("sample_time", &AnyHystereticLfr::sample_time)
      .def_property_readonly("feedback_model", &AnyHystereticLfr::feedback_model)
      .def_property_readonly("feedback_channels", &AnyHystereticLfr::feedback_channels)
      .def_property_readonly("parameter_count", &AnyHystereticLfr::parameter_count)
      .def(
          "simulate",
          [](const AnyHystereticLfr& model, const py::object& input) {
            const auto u = bounded_record(input, "input");
            warn_if_unstable(model.linear());
            py::gil_scoped_release release;
            return model.simulate(u);
          },
          "input"_a,
          "Outputs (N, p) for inputs (N, m) from rest; a RuntimeWarning when a pole of the "
          "linear block lies outside the unit circle.")
      .def(
          "simulate_from_state",
          [](const AnyHystereticLfr& model, const py::object& input, const Eigen::VectorXd& state) {
            const auto u = bounded_record(input, "input");
            if (state.size() != Eigen::Index(model.order()))
              throw Error(fmt::format("state: {} values for a linear block of {} states",
                                      state.size(), model.order()));
            py::gil_scoped_release release;
            return model.simulate_from_state(u, state);
          },
          "input"_a, "state"_a,
          "Outputs (N, p) for inputs (N, m) from the linear block's state `state` (n,), the "
          "hysteresis channels at rest.")
      .def(
          "estimate_initial_state",
          [](const AnyHystereticLfr& model, const py::object& input, const py::object& output,
             std::size_t samples) {
            const auto u = bounded_record(input, "input");
            const auto y = bounded_record(output, "output");
            py::gil_scoped_release release;
            const auto estimate = model.estimate_initial_state(u, y, samples);
            return std::make_tuple(estimate.state, estimate.rms_residual, estimate.iterations);
          },
          "input"_a, "output"_a, "samples"_a,
          "(state, rms_residual, iterations): the linear block's state that the first `samples` "
          "rows of input and output show (least squares with the feedback open, then "
          "Gauss-Newton on the whole model; the hysteresis channels from rest); "
          "simulate_from_state(input, state) then continues the record.")
      .def(
          "simulate_periodic",
          [](const AnyHystereticLfr& model, const py::object& one_period) {
            const auto u = bounded_record(one_period, "one_period");
            py::gil_scoped_release release;
            return model.simulate_from_periodic_state(u, u);
          },
          "one_period"_a, "Outputs over one period (N, p) in periodic steady state.")
      .def(
          "save",
          [](const AnyHystereticLfr& model, const std::filesystem::path& path,
             const py::object& info) {
            save_hysteretic_lfr(
                path, model,
                info.is_none() ? nlohmann::json::object() : python_to_json(info, "info"));
          },
          "path"_a, "info"_a = py::none(), "Writes the model file (atomically).")
      .def("__repr__", [](const AnyHystereticLfr& m) {
        return fmt::format(
            "<HystereticLfr: {} states, {} inputs, {} outputs, {} '{}' feedback "
            "channels, {} parameters>",
            m.order(), m.inputs(), m.outputs(), m.feedback_channels(), m.feedback_model(),
            m.parameter_count());
      });
  module.def(
      "load_hysteretic_lfr",
      [](const std::filesystem::path& path) { return load_hysteretic_lfr(path).model; }, "path"_a,
      "Reads a hysteretic LFR model file.");

  def_hysteresis_fit<HystereticLfrFitOptions>(
      module, "fit_hysteretic_lfr",
      [](const StateSpace& l, const std::vector<PeriodicExperiment>& x,
         const HystereticLfrFitOptions& o) { return fit_hysteretic_lfr(l, x, o); },
      "A hysteretic LFR fitted from a linear model on the simulation error of periodic "
      "experiments (a sequence of (input, output) arrays whose axes `layout` names): a PI model "
      "per output (or feedback_channels of them) in the feedback, jointly with the linear block's "
      "poles (fit_poles) and B, C, D "
      "(fit_io_matrices), then general_iterations with every matrix of the LFR free (both count "
      "accepted Levenberg-Marquardt steps); returns (HystereticLfr, FitReport).");
  def_hysteresis_fit<HammersteinFitOptions>(
      module, "fit_hammerstein",
      [](const StateSpace& l, const std::vector<PeriodicExperiment>& x,
         const HammersteinFitOptions& o) { return fit_hammerstein(l, x, o); },
      "A Hammerstein system (a PI model per input ahead of the linear block) fitted from a linear "
      "model on the simulation error of periodic experiments, jointly with the linear block's "
      "poles (fit_poles) and B, C, D (fit_io_matrices); returns (HystereticLfr, FitReport): the "
      "system as an LFR whose hysteresis inputs are the inputs.");

  module.def("evaluate", &evaluate_model<StateSpace>, "model"_a, "input"_a, "output"_a,
             "layout"_a = kDefaultLayout, "periodic"_a = false, "transient"_a = 0,
             "strict"_a = false,
             "The benchmark score of a model on periodic test data: per output channel the RMSE "
             "of the free-run simulation averaged over realisations and periods, relative to the "
             "channel's standard deviation, and their means (a dict of numpy arrays and numbers). "
             "'warnings' lists why the free run cannot be trusted (a pole outside the unit circle, "
             "'runaway_samples' more than 10 times their channel's measured range beyond it); "
             "strict=True raises hyst.Error instead.");
  module.def("evaluate", &evaluate_model<AnyHystereticLfr>, "model"_a, "input"_a, "output"_a,
             "layout"_a = kDefaultLayout, "periodic"_a = false, "transient"_a = 0,
             "strict"_a = false);
}

}  // namespace hyst::python
