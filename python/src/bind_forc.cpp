// hyst.fit_preisach_forcs: the Preisach model identified from first-order reversal curves, from a
// MicroMag FORC file (hyst.io.read_micromag_forc) or from curves given as arrays
// (hyst/registry/forc_fit.hpp).

#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/limits.hpp"
#include "hyst/registry/forc_fit.hpp"

namespace hyst::python {

std::vector<PythonCurve> curves_from_python(const py::sequence& sequence, std::string_view what) {
  std::vector<PythonCurve> curves;
  std::size_t values = 0;  // of every curve, bounded like one array
  for (std::size_t n = 0; n < sequence.size(); ++n) {
    const py::object item = sequence[n];
    const auto name = fmt::format("{}[{}]", what, n);
    py::sequence pair;
    try {
      pair = item.cast<py::sequence>();
    } catch (const py::cast_error&) {
      throw Error(fmt::format("{} must be a pair (input, output) of arrays", name));
    }
    if (pair.size() != 2) {
      throw Error(fmt::format("{} must be a pair (input, output) of arrays, got {} items", name,
                              pair.size()));
    }
    const auto input_array = pair[0].cast<InputArray>();
    const auto output_array = pair[1].cast<InputArray>();
    const auto input = as_span(input_array, name + "[0] (input)");
    const auto output = as_span(output_array, name + "[1] (output)");
    values += input.size() + output.size();
    if (values > io::limits::kMaxNumpyValues) {
      throw Error(
          fmt::format("{}: with {} the curves hold more than {} values together (the "
                      "limit of one array)",
                      what, name, io::limits::kMaxNumpyValues));
    }
    curves.push_back({{input.begin(), input.end()}, {output.begin(), output.end()}});
  }
  return curves;
}

void bind_forc(py::module_& module) {
  module.def(
      "fit_preisach_forcs",
      [](const py::object& curves, std::string_view drift, std::size_t hold_out_every,
         const std::optional<std::vector<std::size_t>>& held_out, const py::kwargs& options) {
        const auto options_json = python_to_json(options, "");
        std::optional<ForcModelFit> fit;
        if (py::isinstance<io::MicromagForcFile>(curves)) {
          if (held_out) {
            throw Error("held_out: with a FORC file, hold out curves with hold_out_every=N");
          }
          ForcFitRequest request;
          request.drift = io::forc_drift_correction_from_string(drift);
          request.hold_out_every = hold_out_every;
          request.options = options_json;
          const auto& file = curves.cast<const io::MicromagForcFile&>();
          py::gil_scoped_release release;
          fit.emplace(fit_forc_file(file, request));
        } else {
          if (drift != "none") {
            throw Error(
                "drift: the calibration points of a FORC file correct drift; pass the file "
                "(hyst.io.read_micromag_forc), or correct the curves first");
          }
          if (held_out && hold_out_every != 0) {
            throw Error("held_out and hold_out_every: give one of them");
          }
          if (!py::isinstance<py::sequence>(curves) || py::isinstance<py::str>(curves)) {
            throw Error(
                "curves must be a hyst.io.MicromagForcFile or a sequence of (input, output) "
                "pairs");
          }
          const auto owned = curves_from_python(curves.cast<py::sequence>(), "curves");
          const auto reversal = fit_records_of(owned);
          auto fit_options = forc_fit_options_from_json(options_json);
          fit_options.held_out =
              held_out ? *held_out : every_nth_curve(reversal.size(), hold_out_every);
          py::gil_scoped_release release;
          fit.emplace(fit_forc_curves(reversal, fit_options));
        }
        return py::make_tuple(std::move(fit->model), std::move(fit->report));
      },
      "curves"_a, py::kw_only(), "drift"_a = "none", "hold_out_every"_a = 0,
      "held_out"_a = py::none(),
      "Identifies the Preisach model (a tabulated Everett function, model 'tabulated_preisach') "
      "from first-order reversal curves; returns (Model, FitReport). `curves` is a "
      "hyst.io.MicromagForcFile (drift=\"multiplicative\" or \"additive\" corrects the moments "
      "with its calibration points; the table spans the fields of its curves) or a sequence of "
      "(input, output) pairs, each starting at its reversal input after saturation. "
      "hold_out_every=N holds out curves N, 2N, ... (held_out=[indices] for arrays) and "
      "report.validation measures them. Keyword options: intervals (24), lower, upper, "
      "saturation (\"positive_saturation\"), smoothness (0), fit_offset (True).");
}

}  // namespace hyst::python
