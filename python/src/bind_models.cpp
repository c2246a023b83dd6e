// Operators (relay, play, backlash, stop, dead zone), the Prandtl-Ishlinskii model and its
// analytic inverse. States are separate Python objects: a model never changes, a state does.

#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/operators/backlash.hpp"
#include "hyst/operators/dead_zone.hpp"
#include "hyst/operators/play.hpp"
#include "hyst/operators/relay.hpp"
#include "hyst/operators/stop.hpp"

namespace hyst::python {
namespace {

// A state handed in from Python may belong to another model; the C++ step trusts its size.
void check_state(const auto&, const auto&) {}
void check_state(const PrandtlIshlinskii& model, const PrandtlIshlinskii::State& state) {
  if (state.play.size() != model.size()) {
    throw Error(
        fmt::format("state has {} play outputs but the model has {} operators; use a "
                    "state made by this model",
                    state.play.size(), model.size()));
  }
}

// step(state, input) and simulate(input, state=None) for any model with a State.
template <class Model, class Class>
void def_run(Class& cls) {
  using State = typename Model::State;
  cls.def(
      "step",
      [](const Model& model, State& state, double input) {
        require_finite(input, "input");
        check_state(model, state);
        return model.step(state, input);
      },
      "state"_a, "input"_a, "Advances `state` by one input sample and returns the output.");
  cls.def(
      "simulate",
      [](const Model& model, const InputArray& input, State* state) {
        const auto samples = as_span(input, "input");
        State local;
        if (!state) {
          local = model.initial_state();
          state = &local;
        }
        check_state(model, *state);
        std::vector<double> output(samples.size());
        {
          py::gil_scoped_release release;
          hyst::simulate(model, *state, samples, std::span<double>(output));
        }
        return to_array(std::move(output));
      },
      "input"_a, "state"_a = py::none(),
      "Runs the model over `input` and returns the outputs (a new float64 array). Starts from "
      "`state`, which is advanced, or from initial_state() when it is None. Raises hyst.Error "
      "naming the index of a NaN or infinite sample.");
}

// __copy__ / __deepcopy__ / __eq__ for plain value types.
template <class T, class Class>
void def_value(Class& cls) {
  cls.def("__copy__", [](const T& value) { return T(value); });
  cls.def(
      "__deepcopy__", [](const T& value, py::dict) { return T(value); }, "memo"_a);
}

void bind_relay(py::module_& m) {
  py::class_<Relay> relay(m, "Relay",
                          "Relay (Preisach hysteron): +1 once v >= alpha, -1 once v <= beta, "
                          "else unchanged. Initial output -1.");
  py::class_<Relay::State> state(relay, "State", "Relay output s (-1 or +1).");
  state.def_property_readonly("output", [](const Relay::State& s) { return s.output; })
      .def("__repr__",
           [](const Relay::State& s) { return fmt::format("Relay.State(output={})", s.output); });
  def_value<Relay::State>(state);
  relay.def(py::init<double, double>(), "alpha"_a, "beta"_a)
      .def_property_readonly("alpha", &Relay::alpha)
      .def_property_readonly("beta", &Relay::beta)
      .def("initial_state", &Relay::initial_state)
      .def("make_state", &Relay::make_state, "output"_a, "A state with output -1 or +1.")
      .def("__repr__", [](const Relay& r) {
        return fmt::format("Relay(alpha={}, beta={})", r.alpha(), r.beta());
      });
  def_run<Relay>(relay);
}

void bind_play(py::module_& m) {
  py::class_<Play> play(m, "Play",
                        "Play (backlash) operator F_r: w = max(v - r, min(v + r, w_prev)).");
  py::class_<Play::State> state(play, "State", "Play output w [input units].");
  state.def_property_readonly("output", [](const Play::State& s) { return s.output; })
      .def("__repr__",
           [](const Play::State& s) { return fmt::format("Play.State(output={})", s.output); });
  def_value<Play::State>(state);
  play.def(py::init<double>(), "half_width"_a)
      .def_property_readonly("half_width", &Play::half_width)
      .def("initial_state", &Play::initial_state)
      .def("make_state", &Play::make_state, "output"_a)
      .def("__repr__",
           [](const Play& p) { return fmt::format("Play(half_width={})", p.half_width()); });
  def_run<Play>(play);
}

void bind_backlash(py::module_& m) {
  py::class_<Backlash> backlash(
      m, "Backlash",
      "Backlash with gain K and half-width h, optionally saturated to [y_min, y_max].");
  py::class_<Backlash::State> state(backlash, "State", "Backlash output y(k-1).");
  state.def_property_readonly("output", [](const Backlash::State& s) { return s.output; })
      .def("__repr__", [](const Backlash::State& s) {
        return fmt::format("Backlash.State(output={})", s.output);
      });
  def_value<Backlash::State>(state);
  backlash
      .def(py::init([](double gain, double half_width, double output_min, double output_max) {
             return Backlash({gain, half_width, output_min, output_max});
           }),
           py::kw_only(), "gain"_a = 1.0, "half_width"_a = 0.0, "output_min"_a = -kInfinity,
           "output_max"_a = kInfinity)
      .def_property_readonly("gain", [](const Backlash& b) { return b.params().gain; })
      .def_property_readonly("half_width", [](const Backlash& b) { return b.params().half_width; })
      .def_property_readonly("output_min", [](const Backlash& b) { return b.params().output_min; })
      .def_property_readonly("output_max", [](const Backlash& b) { return b.params().output_max; })
      .def("initial_state", &Backlash::initial_state)
      .def("make_state", &Backlash::make_state, "output"_a)
      .def("__repr__", [](const Backlash& b) {
        const auto& p = b.params();
        return fmt::format("Backlash(gain={}, half_width={}, output_min={}, output_max={})", p.gain,
                           p.half_width, p.output_min, p.output_max);
      });
  def_run<Backlash>(backlash);
}

void bind_stop(py::module_& m) {
  py::class_<Stop> stop(
      m, "Stop", "Stop operator E_r: e = min(r, max(-r, e_prev + v - v_prev)) = v - F_r[v].");
  py::class_<Stop::State> state(stop, "State", "Stop output e(k-1) and input v(k-1).");
  state.def_property_readonly("output", [](const Stop::State& s) { return s.output; })
      .def_property_readonly("last_input", [](const Stop::State& s) { return s.last_input; })
      .def("__repr__", [](const Stop::State& s) {
        return fmt::format("Stop.State(output={}, last_input={})", s.output, s.last_input);
      });
  def_value<Stop::State>(state);
  stop.def(py::init<double>(), "half_width"_a)
      .def_property_readonly("half_width", &Stop::half_width)
      .def("initial_state", &Stop::initial_state)
      .def("state_from_play", &Stop::state_from_play, "play_output"_a, "input"_a,
           "The state equivalent to a play with output `play_output` at input `input`.")
      .def("__repr__",
           [](const Stop& s) { return fmt::format("Stop(half_width={})", s.half_width()); });
  def_run<Stop>(stop);
}

void bind_dead_zone(py::module_& m) {
  py::class_<DeadZone>(m, "DeadZone",
                       "Dead-zone S_d (memory-free): max(y - d, 0) for d > 0, y for d = 0, "
                       "min(y - d, 0) for d < 0.")
      .def(py::init<double>(), "threshold"_a)
      .def_property_readonly("threshold", &DeadZone::threshold)
      .def(
          "__call__", [](const DeadZone& d, double y) { return d(y); }, "input"_a)
      .def(
          "apply",
          [](const DeadZone& d, const InputArray& input) {
            const auto samples = as_span(input, "input");
            std::vector<double> output(samples.size());
            for (std::size_t k = 0; k < samples.size(); ++k)
              output[k] = d(samples[k]);
            return to_array(std::move(output));
          },
          "input"_a, "The dead zone applied to every sample.")
      .def("__repr__",
           [](const DeadZone& d) { return fmt::format("DeadZone(threshold={})", d.threshold()); });
}

std::string pi_repr(const PrandtlIshlinskii& model) {
  const auto& p = model.params();
  return fmt::format("PrandtlIshlinskii(thresholds={}, weights={}, offset={})",
                     format_list(p.thresholds), format_list(p.weights), p.offset);
}

void bind_prandtl_ishlinskii(py::module_& m) {
  using PI = PrandtlIshlinskii;
  py::class_<PI> pi(
      m, "PrandtlIshlinskii",
      "Prandtl-Ishlinskii model y = offset + sum_j p_j F_{r_j}[v].\n\n"
      "thresholds r_j: 0 = r_0 < r_1 < ...; weights p_j: one per threshold; the "
      "model is invertible iff p_0 > 0 and every partial sum is > 0. The model is "
      "immutable; its state (the play outputs) is a separate PrandtlIshlinskii.State.");
  py::class_<PI::State> state(pi, "State",
                              "Play outputs w_j of a PI model (or of its inverse); copyable.");
  state
      .def_property_readonly(
          "play", [](const PI::State& s) { return readonly_copy(s.play); },
          "The play outputs w_j as a read-only float64 array (a snapshot).")
      .def("__len__", [](const PI::State& s) { return s.play.size(); })
      .def("__eq__", [](const PI::State& a, const PI::State& b) { return a.play == b.play; })
      .def("__repr__", [](const PI::State& s) {
        return fmt::format("PrandtlIshlinskii.State(play={})", format_list(s.play));
      });
  def_value<PI::State>(state);

  pi.def(py::init([](const InputArray& thresholds, const InputArray& weights, double offset) {
           return PI({as_vector(thresholds, "thresholds"), as_vector(weights, "weights"), offset});
         }),
         "thresholds"_a, "weights"_a, "offset"_a = 0.0,
         "Validates the parameters; raises hyst.Error naming the first one that breaks a rule.")
      .def_property_readonly(
          "thresholds",
          [](py::object self) {
            return readonly_view(self.cast<const PI&>().params().thresholds, self);
          },
          "r_j as a read-only float64 array (a view of the model's memory).")
      .def_property_readonly(
          "weights",
          [](py::object self) {
            return readonly_view(self.cast<const PI&>().params().weights, self);
          },
          "p_j as a read-only float64 array (a view of the model's memory).")
      .def_property_readonly("offset", [](const PI& model) { return model.params().offset; })
      .def("size", &PI::size, "Number of play operators.")
      .def("__len__", &PI::size)
      .def("initial_state", &PI::initial_state, "All w_j = 0: the virgin state at v = 0.")
      .def("state_at_rest", &PI::state_at_rest, "input"_a, "All w_j = v0: at rest at input v0.")
      .def(
          "make_state",
          [](const PI& model, const InputArray& play) {
            return model.make_state(as_vector(play, "play"));
          },
          "play"_a, "A given state; raises hyst.Error unless some input history reaches it.")
      .def(
          "output", [](const PI& model, const PI::State& s) { return model.output(s); }, "state"_a,
          "The output in `state`, without advancing it.")
      .def("is_invertible", &PI::is_invertible, "True iff p_0 > 0 and every partial sum S_j > 0.")
      .def("__copy__", [](const PI& model) { return PI(model); })
      .def(
          "__deepcopy__", [](const PI& model, py::dict) { return PI(model); }, "memo"_a)
      .def("__repr__", &pi_repr);
  def_run<PI>(pi);

  m.def(
      "uniform_thresholds",
      [](std::size_t count, double spacing) {
        return to_array(uniform_thresholds(count, spacing));
      },
      "count"_a, "spacing"_a, "Thresholds r_j = spacing * j, j = 0 .. count-1.");
}

void bind_inverse(py::module_& m) {
  using PI = PrandtlIshlinskii;
  using Inverse = InversePrandtlIshlinskii;

  py::enum_<InverseStatus>(m, "InverseStatus", "Outcome of one inverse sample.")
      .value("ok", InverseStatus::ok)
      .value("below_range", InverseStatus::below_range)
      .value("above_range", InverseStatus::above_range)
      .value("not_invertible", InverseStatus::not_invertible);

  py::class_<InverseReport>(m, "InverseReport", "Summary of a batch inversion.")
      .def_readonly("saturated_samples", &InverseReport::saturated_samples)
      .def_readonly("first_saturated", &InverseReport::first_saturated,
                    "Index of the first saturated sample (meaningful when saturated_samples > 0).")
      .def_readonly("not_invertible_samples", &InverseReport::not_invertible_samples,
                    "Samples with status not_invertible (counted in saturated_samples too).")
      .def_readonly("first_not_invertible", &InverseReport::first_not_invertible)
      .def_readonly("limited_samples", &InverseReport::limited_samples,
                    "Samples with status below_range or above_range (counted in saturated_samples "
                    "too).")
      .def_readonly("first_limited", &InverseReport::first_limited,
                    "Index of the first sample limited to the input range (below_range or "
                    "above_range; meaningful when limited_samples > 0).")
      .def_property_readonly("ok", &InverseReport::ok, "True when no sample was saturated.")
      .def("__repr__", [](const InverseReport& r) {
        return r.ok() ? std::string("InverseReport(ok)")
                      : fmt::format("InverseReport(saturated_samples={}, first_saturated={})",
                                    r.saturated_samples, r.first_saturated);
      });

  const auto check = [](const Inverse& inverse, const PI::State& state) {
    if (state.play.size() != inverse.inverse_operator().size()) {
      throw Error(
          fmt::format("state has {} play outputs but the inverse has {} operators; use a "
                      "state made by this inverse",
                      state.play.size(), inverse.inverse_operator().size()));
    }
  };

  py::class_<Inverse> inverse(
      m, "InversePrandtlIshlinskii",
      "Analytic inverse of a PI model, itself a PI operator on y - offset. Start it from the state "
      "consistent with the forward model's (state_consistent_with); targets that need an input "
      "outside [input_min, input_max] are answered with the limit and a status.");
  inverse.attr("State") = m.attr("PrandtlIshlinskii").attr("State");
  inverse
      .def(py::init([](const PI& model, double input_min, double input_max) {
             return Inverse(model, {input_min, input_max});
           }),
           "model"_a, "input_min"_a = -kInfinity, "input_max"_a = kInfinity,
           "Raises hyst.Error when p_0 <= 0 or a partial sum S_j <= 0, or input_min > input_max.")
      .def("inverse_operator", &Inverse::inverse_operator,
           "The inverse as a PI model on y - offset: thresholds rh_j, weights ph_j.")
      .def("forward", &Inverse::forward, "The forward model.")
      .def_property_readonly("input_min", [](const Inverse& i) { return i.options().input_min; })
      .def_property_readonly("input_max", [](const Inverse& i) { return i.options().input_max; })
      .def("initial_state", &Inverse::initial_state,
           "Consistent with the forward model's initial_state(): all zero.")
      .def(
          "state_consistent_with",
          [](const Inverse& i, const PI::State& forward_state) {
            return i.state_consistent_with(forward_state);
          },
          "forward_state"_a, "The inverse state matching a forward state.")
      .def(
          "forward_state_consistent_with",
          [check](const Inverse& i, const PI::State& inverse_state) {
            check(i, inverse_state);
            return i.forward_state_consistent_with(inverse_state);
          },
          "inverse_state"_a, "The forward state matching an inverse state.")
      .def(
          "solve",
          [check](const Inverse& i, PI::State& state, double target) {
            require_finite(target, "target");
            check(i, state);
            const InverseSample sample = i.solve(state, target);
            return std::make_pair(sample.input, sample.status);
          },
          "state"_a, "target"_a, "One sample: returns (input, InverseStatus) and advances `state`.")
      .def(
          "step",
          [check](const Inverse& i, PI::State& state, double target) {
            require_finite(target, "target");
            check(i, state);
            return i.step(state, target);
          },
          "state"_a, "target"_a, "solve() without the status.")
      .def(
          "invert",
          [check](const Inverse& i, const InputArray& targets, PI::State* state) -> InvertResult {
            const auto samples = as_span(targets, "targets");
            PI::State local;
            if (!state) {
              local = i.initial_state();
              state = &local;
            }
            check(i, *state);
            std::vector<double> inputs(samples.size());
            InverseReport report;
            {
              py::gil_scoped_release release;
              report = hyst::invert(i, *state, samples, inputs);
            }
            return py::make_tuple(to_array(std::move(inputs)), report);
          },
          "targets"_a, "state"_a = py::none(),
          "Inputs that make the model produce `targets`: returns (inputs, InverseReport). Starts "
          "from `state` (advanced) or initial_state() when None.")
      .def("__copy__", [](const Inverse& i) { return Inverse(i); })
      .def(
          "__deepcopy__", [](const Inverse& i, py::dict) { return Inverse(i); }, "memo"_a)
      .def("__repr__", [](const Inverse& i) {
        return fmt::format("InversePrandtlIshlinskii(model={}, input_min={}, input_max={})",
                           pi_repr(i.forward()), i.options().input_min, i.options().input_max);
      });
}

}  // namespace

void bind_operators(py::module_& module) {
  bind_relay(module);
  bind_play(module);
  bind_backlash(module);
  bind_stop(module);
  bind_dead_zone(module);
}

void bind_models(py::module_& module) {
  bind_prandtl_ishlinskii(module);
  bind_inverse(module);
}

}  // namespace hyst::python
