// hyst.fit_butterfly_strain_records, hyst.fit_butterfly_strain_with_polarisation and
// hyst.fit_butterfly_strain_creep_with_polarisation: the butterfly strain fits beyond the
// registry's hyst.fit (hyst/registry/butterfly_fit.hpp, butterfly_creep_fit.hpp).

#include <optional>
#include <utility>

#include "bindings.hpp"
#include "hyst/registry/butterfly_creep_fit.hpp"
#include "hyst/registry/butterfly_fit.hpp"

namespace hyst::python {

void bind_butterfly(py::module_& module) {
  module.def(
      "fit_butterfly_strain_records",
      [](const py::sequence& records, const py::kwargs& options) {
        const auto options_json = python_to_json(options, "");
        const auto owned = curves_from_python(records, "records");
        const auto views = fit_records_of(owned);
        std::optional<ButterflyModelFit> fit;
        {
          py::gil_scoped_release release;
          fit.emplace(fit_butterfly_strain_model(views, options_json));
        }
        return py::make_tuple(std::move(fit->model), std::move(fit->report));
      },
      "records"_a,
      "Fits one butterfly strain model (voltage -> latent polarisation -> strain) to several "
      "records together, a sequence of (input, output) pairs; returns (Model, FitReport). "
      "Keyword options as for hyst.fit('butterfly_strain', ...): levels (16), lower, upper, "
      "degree (2), fit_field_term (True), initial_state (\"periodic\"), max_iterations (300).");
  module.def(
      "fit_butterfly_strain_with_polarisation",
      [](const InputArray& input, const InputArray& polarisation, const InputArray& output,
         const py::kwargs& options) {
        const auto options_json = python_to_json(options, "");
        const auto v = as_span(input, "input");
        const auto p = as_span(polarisation, "polarisation");
        const auto y = as_span(output, "output");
        std::optional<ButterflyTwoStageModelFit> fit;
        {
          py::gil_scoped_release release;
          fit.emplace(fit_butterfly_strain_model_with_polarisation(v, p, y, options_json));
        }
        return py::make_tuple(std::move(fit->model), std::move(fit->report),
                              std::move(fit->polarisation_report), std::move(fit->map_report),
                              fit->leakage_conductance);
      },
      "input"_a, "polarisation"_a, "output"_a,
      "The two-stage butterfly strain fit with measured polarisation: P(v) by NNLS on a Preisach "
      "relay grid, then y = y_off + d v + sum q_n P^n on the model's P; returns (Model, "
      "FitReport of the strain, FitReport of P(v), FitReport of the map on the measured P, "
      "leakage conductance g). Keyword options as for fit_butterfly_strain_records, and "
      "fit_leakage (False) with sample_time (1.0 s): fit the leakage charge g * integral(v dt) "
      "of the measured polarisation too (g >= 0), which the maps then leave out.");
  module.def(
      "fit_butterfly_strain_creep_with_polarisation",
      [](const InputArray& input, const InputArray& polarisation, const InputArray& output,
         const py::kwargs& options) {
        const auto options_json = python_to_json(options, "");
        const auto v = as_span(input, "input");
        const auto p = as_span(polarisation, "polarisation");
        const auto y = as_span(output, "output");
        std::optional<ButterflyCreepTwoStageModelFit> fit;
        {
          py::gil_scoped_release release;
          fit.emplace(fit_butterfly_strain_creep_model_with_polarisation(v, p, y, options_json));
        }
        return py::make_tuple(std::move(fit->model), std::move(fit->report),
                              std::move(fit->polarisation_report));
      },
      "input"_a, "polarisation"_a, "output"_a,
      "The butterfly strain with creep fit with measured polarisation: the polarisation by one "
      "NNLS over relay, creep and (fit_leakage=True) leakage weights, then the strain map on the "
      "model's polarisation without the leakage charge; returns (Model, FitReport of the "
      "strain, FitReport of the measured polarisation). Keyword options as for "
      "hyst.fit('butterfly_strain_creep', ...), with sample_time [s] and fit_leakage (False).");
}

}  // namespace hyst::python
