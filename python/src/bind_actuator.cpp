// The hysteretic actuator: configurations (JSON files or dicts), closed-loop simulation under each
// control strategy, the strategy comparison with its table and plots, the linearised plant, and
// the PID controller.

#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/actuator/actuator_config.hpp"
#include "hyst/actuator/comparison.hpp"
#include "hyst/actuator/linearised_plant.hpp"
#include "hyst/control/pid.hpp"
#include "hyst/io/output_set.hpp"

namespace hyst::python {
namespace {

// A PID with its running state (the Python face of control::Pid).
class StatefulPid {
 public:
  StatefulPid(const control::Pid::Params& params, double period)
      : pid_(params, period), state_(pid_.initial_state()) {}
  double step(double reference, double measurement, double feedforward) {
    return pid_.step(state_, reference, measurement, feedforward);
  }
  void reset() { state_ = pid_.initial_state(); }
  double integral() const { return state_.integral; }
  const control::Pid& pid() const { return pid_; }

 private:
  control::Pid pid_;
  control::Pid::State state_;
};

StrDict trace_to_dict(LoopTrace&& trace) {
  py::dict result;
  result["reference"] = to_array(std::move(trace.reference));
  result["measured"] = to_array(std::move(trace.measured));
  result["position"] = to_array(std::move(trace.position));
  result["current_reference"] = to_array(std::move(trace.current_reference));
  result["current"] = to_array(std::move(trace.current));
  result["force"] = to_array(std::move(trace.force));
  result["voltage"] = to_array(std::move(trace.voltage));
  return result;
}

StrDict metrics_to_dict(const control::TrackingMetrics& m) {
  py::dict result;
  result["rms_error"] = m.rms_error;
  result["max_error"] = m.max_error;
  result["settling_time"] = m.settling_time;
  result["overshoot"] = m.overshoot;
  result["control_effort"] = m.control_effort;
  return result;
}

}  // namespace

void bind_actuator(py::module_& module) {
  py::class_<LinearisedPlant>(
      module, "LinearisedPlant",
      "G(s) = k_F exp(-sT) / ((L s + R)(m s^2 + b s + k)): the actuator with the compensated force "
      "F = k_F i.")
      .def(py::init([](double resistance, double inductance, double force_gain, double mass,
                       double damping, double stiffness, double delay) {
             return LinearisedPlant(
                 {resistance, inductance, force_gain, mass, damping, stiffness, delay});
           }),
           "resistance"_a, "inductance"_a, "force_gain"_a, "mass"_a, "damping"_a, "stiffness"_a,
           "delay"_a = 0.0)
      .def_property_readonly("dc_gain", &LinearisedPlant::dc_gain, "k_F / (R k) [m/V]")
      .def("poles", &LinearisedPlant::poles, "-R/L and the roots of m s^2 + b s + k [rad/s]")
      .def("frequency_response", &LinearisedPlant::frequency_response, "omega"_a)
      .def(
          "step_response",
          [](const LinearisedPlant& plant, const InputArray& times, double amplitude) {
            const auto t = as_span(times, "times");
            std::vector<double> x(t.size());
            for (std::size_t k = 0; k < t.size(); ++k)
              x[k] = plant.step_response(t[k], amplitude);
            return to_array(std::move(x));
          },
          "times"_a, "amplitude"_a = 1.0,
          "x(t) [m] for a voltage step of `amplitude` [V] at t = 0 (analytic).");

  py::class_<ActuatorConfig>(
      module, "ActuatorConfig",
      "An actuator (coil, hysteretic force, mechanics, delay, noise) with its controller and "
      "scenarios; see hyst.load_actuator_config().")
      .def(py::init([](const py::dict& document) {
             return actuator_config_from_json(python_to_json(document, ""), "<dict>");
           }),
           "document"_a, "A configuration from a dict of the JSON file's form.")
      .def_readonly("name", &ActuatorConfig::name)
      .def_readonly("description", &ActuatorConfig::description)
      .def_property_readonly("sample_time",
                             [](const ActuatorConfig& c) { return c.plant.sample_time; })
      .def_property_readonly(
          "hysteresis_model",
          [](const ActuatorConfig& c) { return std::string(hysteresis_name(c.hysteresis)); },
          "The force model's name: gpi, pi, preisach, modified_pi, kp, maxwell_slip, ikuta_sma or "
          "bouc_wen "
          "(rate_dependent_pi is rejected: its output depends on the input rate).")
      .def(
          "linearised_plant",
          [](const ActuatorConfig& c) { return LinearisedPlant::of(c.plant, c.loop.force_gain); },
          "The linearised plant with the configuration's k_F.")
      .def(
          "simulate",
          [](const ActuatorConfig& c, const InputArray& reference, const std::string& strategy) {
            const auto values = as_span(reference, "reference");
            return trace_to_dict(simulate_loop(c, control_strategy_from_string(strategy),
                                               {values.begin(), values.end()}));
          },
          "reference"_a, "strategy"_a = "pid_feedforward",
          "Runs one strategy (open_loop, feedforward, pid, pid_feedforward) from rest on a "
          "reference [m] sampled at sample_time; returns a dict of arrays: reference, measured, "
          "position, current_reference, current, force, voltage.")
      .def(
          "compare",
          [](const ActuatorConfig& c, const std::optional<std::filesystem::path>& plot_folder)
              -> Typed<py::tuple, "Tuple[List[Dict[str, Any]], str]"> {
            // The plots are published as one set (hyst/io/output_set.hpp).
            std::optional<io::OutputSet> set;
            if (plot_folder) set.emplace(*plot_folder, std::vector<std::string>{});
            const auto comparison = compare_strategies(c, scenario_references(c));
            if (set) {
              write_comparison_plots(comparison, set->staged(""));
              set->publish();
            }
            py::list rows;
            for (const auto& run : comparison.runs) {
              auto row = metrics_to_dict(run.metrics);
              row["reference"] = run.reference;
              row["strategy"] = std::string(to_string(run.strategy));
              rows.append(row);
            }
            return py::make_tuple(rows, comparison_markdown(comparison));
          },
          "plot_folder"_a = py::none(),
          "Every strategy on the configuration's scenarios: (rows, markdown table); rows are "
          "dicts with reference, strategy and the metrics in SI units. With plot_folder, also "
          "writes tracking_*.png and error_*.png there (needs gnuplot).");

  module.def(
      "load_actuator_config",
      [](const std::filesystem::path& path) { return load_actuator_config(path); }, "path"_a,
      "Reads an actuator configuration (JSON); hyst.Error names the file and field.");

  module.def(
      "tracking_metrics",
      [](const InputArray& reference, const InputArray& output, const InputArray& effort,
         double sample_time, std::optional<std::tuple<double, double, double>> step) {
        std::optional<control::StepEvent> event;
        if (step)
          event = control::StepEvent{std::get<0>(*step), std::get<1>(*step), std::get<2>(*step)};
        return metrics_to_dict(
            control::tracking_metrics(as_span(reference, "reference"), as_span(output, "output"),
                                      as_span(effort, "effort"), sample_time, event));
      },
      "reference"_a, "output"_a, "effort"_a, "sample_time"_a, "step"_a = py::none(),
      "RMS and max error, control effort (RMS), and for step=(time, from, to) the overshoot "
      "[%] and 2 % settling time [s].");

  py::class_<StatefulPid>(module, "Pid",
                          "Discrete PID with filtered derivative on the measurement, output "
                          "limits and anti-windup (none, clamping, back_calculation).")
      .def(py::init([](double kp, double ki, double kd, double derivative_filter, double output_min,
                       double output_max, const std::string& anti_windup,
                       std::optional<double> tracking_time, double period) {
             control::Pid::Params params{
                 kp,
                 ki,
                 kd,
                 derivative_filter,
                 output_min,
                 output_max,
                 control::anti_windup_from_string(anti_windup),
                 tracking_time.value_or(std::numeric_limits<double>::quiet_NaN())};
             return StatefulPid(params, period);
           }),
           "kp"_a = 0.0, "ki"_a = 0.0, "kd"_a = 0.0, "derivative_filter"_a = 0.0,
           "output_min"_a = -std::numeric_limits<double>::infinity(),
           "output_max"_a = std::numeric_limits<double>::infinity(),
           "anti_windup"_a = "back_calculation", "tracking_time"_a = py::none(), py::kw_only(),
           "period"_a)
      .def("step", &StatefulPid::step, "reference"_a, "measurement"_a, "feedforward"_a = 0.0,
           "One controller period; returns the (limited) output.")
      .def("reset", &StatefulPid::reset)
      .def_property_readonly("integral", &StatefulPid::integral)
      .def_property_readonly("tracking_time",
                             [](const StatefulPid& p) { return p.pid().tracking_time(); });
}

}  // namespace hyst::python
