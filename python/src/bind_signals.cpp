// hyst.signals: the deterministic test signals, as in C++ - a TimeGrid, a parameter struct per
// signal (keyword arguments with the C++ defaults) and generate(grid, signal).

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/signals/generators.hpp"

namespace hyst::python {
namespace {

using namespace hyst::signals;

template <class Signal, class Class>
void def_generate(py::module_& s, Class&) {
  s.def(
      "generate",
      [](const TimeGrid& grid, const Signal& signal) { return to_array(generate(grid, signal)); },
      "grid"_a, "signal"_a);
}

}  // namespace

void bind_signals(py::module_& module) {
  auto s = module.def_submodule(
      "signals",
      "Deterministic test signals on a uniform grid t_k = k dt:\n\n"
      "    grid = hyst.signals.TimeGrid(2000, 1e-3)\n"
      "    v = hyst.signals.generate(grid, hyst.signals.DecayingSine(amplitude=2, frequency=2))\n\n"
      "Sine and Triangle trace one major loop; DecayingSine a spiral of nested inner loops; "
      "GrowingSine loops growing out to the major loop; Multisine and RandomWalk irregular nested "
      "loops; Chirp a frequency sweep. Frequencies are in Hz, phases in rad. Invalid parameters "
      "raise hyst.Error naming the field.");
  py::module_::import("sys").attr("modules")["hyst.signals"] = s;

  py::class_<TimeGrid>(s, "TimeGrid", "Uniform time grid t_k = k dt, k = 0 .. samples-1.")
      .def(py::init([](std::size_t samples, double dt) {
             return TimeGrid{samples, dt};
           }),
           "samples"_a, "dt"_a = 1.0)
      .def_readwrite("samples", &TimeGrid::samples)
      .def_readwrite("dt", &TimeGrid::dt, "[s]")
      .def("__repr__", [](const TimeGrid& g) {
        return fmt::format("TimeGrid(samples={}, dt={})", g.samples, g.dt);
      });
  s.def(
      "times", [](const TimeGrid& grid) { return to_array(times(grid)); }, "grid"_a,
      "The sample times t_k = k dt [s].");

  py::class_<Sine> sine(s, "Sine", "v(t) = A sin(2 pi f t + phase) + offset.");
  sine.def(py::init([](double amplitude, double frequency, double phase, double offset) {
             return Sine{amplitude, frequency, phase, offset};
           }),
           py::kw_only(), "amplitude"_a = Sine{}.amplitude, "frequency"_a = Sine{}.frequency,
           "phase"_a = Sine{}.phase, "offset"_a = Sine{}.offset)
      .def_readwrite("amplitude", &Sine::amplitude)
      .def_readwrite("frequency", &Sine::frequency)
      .def_readwrite("phase", &Sine::phase)
      .def_readwrite("offset", &Sine::offset)
      .def("__repr__", [](const Sine& v) {
        return fmt::format("Sine(amplitude={}, frequency={}, phase={}, offset={})", v.amplitude,
                           v.frequency, v.phase, v.offset);
      });
  def_generate<Sine>(s, sine);

  py::class_<Triangle> triangle(s, "Triangle",
                                "Symmetric triangle wave with peaks +-A, phase as for Sine.");
  triangle
      .def(py::init([](double amplitude, double frequency, double phase, double offset) {
             return Triangle{amplitude, frequency, phase, offset};
           }),
           py::kw_only(), "amplitude"_a = Triangle{}.amplitude,
           "frequency"_a = Triangle{}.frequency, "phase"_a = Triangle{}.phase,
           "offset"_a = Triangle{}.offset)
      .def_readwrite("amplitude", &Triangle::amplitude)
      .def_readwrite("frequency", &Triangle::frequency)
      .def_readwrite("phase", &Triangle::phase)
      .def_readwrite("offset", &Triangle::offset)
      .def("__repr__", [](const Triangle& v) {
        return fmt::format("Triangle(amplitude={}, frequency={}, phase={}, offset={})", v.amplitude,
                           v.frequency, v.phase, v.offset);
      });
  def_generate<Triangle>(s, triangle);

  py::class_<DecayingSine> decaying(
      s, "DecayingSine",
      "v(t) = A exp(-t/tau) sin(2 pi f t + phase) + offset: nested inner loops.");
  decaying
      .def(py::init([](double amplitude, double frequency, double time_constant, double phase,
                       double offset) {
             return DecayingSine{amplitude, frequency, time_constant, phase, offset};
           }),
           py::kw_only(), "amplitude"_a = DecayingSine{}.amplitude,
           "frequency"_a = DecayingSine{}.frequency,
           "time_constant"_a = DecayingSine{}.time_constant, "phase"_a = DecayingSine{}.phase,
           "offset"_a = DecayingSine{}.offset)
      .def_readwrite("amplitude", &DecayingSine::amplitude)
      .def_readwrite("frequency", &DecayingSine::frequency)
      .def_readwrite("time_constant", &DecayingSine::time_constant)
      .def_readwrite("phase", &DecayingSine::phase)
      .def_readwrite("offset", &DecayingSine::offset)
      .def("__repr__", [](const DecayingSine& v) {
        return fmt::format(
            "DecayingSine(amplitude={}, frequency={}, time_constant={}, phase={}, offset={})",
            v.amplitude, v.frequency, v.time_constant, v.phase, v.offset);
      });
  def_generate<DecayingSine>(s, decaying);

  py::class_<GrowingSine> growing(
      s, "GrowingSine",
      "v(t) = A (1 - exp(-t/tau)) sin(2 pi f t + phase) + offset: loops growing outwards.");
  growing
      .def(py::init([](double amplitude, double frequency, double time_constant, double phase,
                       double offset) {
             return GrowingSine{amplitude, frequency, time_constant, phase, offset};
           }),
           py::kw_only(), "amplitude"_a = GrowingSine{}.amplitude,
           "frequency"_a = GrowingSine{}.frequency, "time_constant"_a = GrowingSine{}.time_constant,
           "phase"_a = GrowingSine{}.phase, "offset"_a = GrowingSine{}.offset)
      .def_readwrite("amplitude", &GrowingSine::amplitude)
      .def_readwrite("frequency", &GrowingSine::frequency)
      .def_readwrite("time_constant", &GrowingSine::time_constant)
      .def_readwrite("phase", &GrowingSine::phase)
      .def_readwrite("offset", &GrowingSine::offset)
      .def("__repr__", [](const GrowingSine& v) {
        return fmt::format(
            "GrowingSine(amplitude={}, frequency={}, time_constant={}, phase={}, offset={})",
            v.amplitude, v.frequency, v.time_constant, v.phase, v.offset);
      });
  def_generate<GrowingSine>(s, growing);

  py::class_<Multisine> multisine(
      s, "Multisine",
      "v(t) = sum_k a_k sin(2 pi f_k t + phi_k) + offset; phases=None gives Schroeder phases.");
  multisine
      .def(py::init([](std::vector<double> frequencies, std::vector<double> amplitudes,
                       std::optional<std::vector<double>> phases, double offset) {
             return Multisine{std::move(frequencies), std::move(amplitudes),
                              phases.value_or(std::vector<double>{}), offset};
           }),
           py::kw_only(), "frequencies"_a, "amplitudes"_a, "phases"_a = py::none(),
           "offset"_a = 0.0)
      .def_readwrite("frequencies", &Multisine::frequencies)
      .def_readwrite("amplitudes", &Multisine::amplitudes)
      .def_readwrite("phases", &Multisine::phases)
      .def_readwrite("offset", &Multisine::offset)
      .def("__repr__", [](const Multisine& v) {
        return fmt::format("Multisine(frequencies={}, amplitudes={}, phases={}, offset={})",
                           format_list(v.frequencies), format_list(v.amplitudes),
                           v.phases.empty() ? std::string("None") : format_list(v.phases),
                           v.offset);
      });
  def_generate<Multisine>(s, multisine);

  py::class_<Chirp> chirp(s, "Chirp",
                          "Linear frequency sweep from start_frequency at t = 0 to end_frequency "
                          "at the last sample.");
  chirp
      .def(py::init([](double amplitude, double start_frequency, double end_frequency, double phase,
                       double offset) {
             return Chirp{amplitude, start_frequency, end_frequency, phase, offset};
           }),
           py::kw_only(), "amplitude"_a = Chirp{}.amplitude,
           "start_frequency"_a = Chirp{}.start_frequency, "end_frequency"_a = Chirp{}.end_frequency,
           "phase"_a = Chirp{}.phase, "offset"_a = Chirp{}.offset)
      .def_readwrite("amplitude", &Chirp::amplitude)
      .def_readwrite("start_frequency", &Chirp::start_frequency)
      .def_readwrite("end_frequency", &Chirp::end_frequency)
      .def_readwrite("phase", &Chirp::phase)
      .def_readwrite("offset", &Chirp::offset)
      .def("__repr__", [](const Chirp& v) {
        return fmt::format(
            "Chirp(amplitude={}, start_frequency={}, end_frequency={}, phase={}, offset={})",
            v.amplitude, v.start_frequency, v.end_frequency, v.phase, v.offset);
      });
  def_generate<Chirp>(s, chirp);

  py::class_<RandomWalk> walk(
      s, "RandomWalk",
      "Bounded random walk with uniform steps in [-max_step, max_step), reflected at the bounds; "
      "reproducible for a given seed on every platform.");
  walk.def(py::init(
               [](double max_step, double lower, double upper, double start, std::uint64_t seed) {
                 return RandomWalk{max_step, lower, upper, start, seed};
               }),
           py::kw_only(), "max_step"_a = RandomWalk{}.max_step, "lower"_a = RandomWalk{}.lower,
           "upper"_a = RandomWalk{}.upper, "start"_a = RandomWalk{}.start,
           "seed"_a = RandomWalk{}.seed)
      .def_readwrite("max_step", &RandomWalk::max_step)
      .def_readwrite("lower", &RandomWalk::lower)
      .def_readwrite("upper", &RandomWalk::upper)
      .def_readwrite("start", &RandomWalk::start)
      .def_readwrite("seed", &RandomWalk::seed)
      .def("__repr__", [](const RandomWalk& v) {
        return fmt::format("RandomWalk(max_step={}, lower={}, upper={}, start={}, seed={})",
                           v.max_step, v.lower, v.upper, v.start, v.seed);
      });
  def_generate<RandomWalk>(s, walk);
}

}  // namespace hyst::python
