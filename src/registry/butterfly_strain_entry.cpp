// Registry entry of the butterfly strain model: its model-file form (the Preisach polarisation's
// fields, then the strain map), its inverse on monotone branches and its direct-form fit.

#include <cmath>

#include <fmt/format.h>

#include "butterfly_fields.hpp"
#include "hyst/identify/fit_butterfly_strain.hpp"
#include "hyst/inverse/inverse_butterfly_strain.hpp"
#include "hyst/models/butterfly_strain.hpp"
#include "hyst/registry/butterfly_fit.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"
#include "preisach_state_json.hpp"

namespace hyst::detail {
namespace {

struct ButterflyCodec : CodecOf<ButterflyStrain, "butterfly_strain"> {
  static FieldTable<P> parameters() { return butterfly_strain_fields(); }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return preisach_state_to_json(state);
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    return preisach_state_from_json(model.polarisation_model(), fields);
  }
  static std::size_t parameter_count(const Model& model) {
    return model.params().polarisation.everett.weights.size() + model.degree() + 3;
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    const auto& grid = p.polarisation.everett;
    std::string text = fmt::format(
        "Butterfly strain model: polarisation by a Preisach relay grid of {} levels on [{}, {}] "
        "({} relays, total weight F0 = {}, P offset {}, initial state {});\n"
        "strain y = {} + {} v",
        grid.levels, grid.lower, grid.upper, grid.weights.size(),
        model.polarisation_model().total_weight(), p.polarisation.offset,
        to_string(p.polarisation.initial_state), p.offset, p.field_coefficient);
    for (std::size_t n = 0; n < model.degree(); ++n)
      text += fmt::format(" + {} P^{}", p.polarisation_coefficients[n], n + 1);
    return text + '\n';
  }
  static bool has_inverse(const Model&) { return true; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    // Unlimited: the polarisation's input range, beyond which nothing changes but d v.
    const auto& grid = model.params().polarisation.everett;
    const double lo = std::isfinite(limits.input_min) ? limits.input_min : grid.lower;
    const double hi = std::isfinite(limits.input_max) ? limits.input_max : grid.upper;
    return std::make_unique<
        InverseAdapter<InverseButterflyStrain, decltype(&preisach_state_to_json)>>(
        InverseButterflyStrain(model, {lo, hi}), state, &preisach_state_to_json);
  }
};

// The two-stage fit's options: the direct form's and the leakage of the measured polarisation.
FieldTable<ButterflyFitOptions> butterfly_two_stage_option_table() {
  using O = ButterflyFitOptions;
  return butterfly_fit_option_table()
      .add("fit_leakage", &O::fit_leakage, "", "fit the polarisation's leakage conductance")
      .add("sample_time", &O::sample_time, "s", "Ts of the record (for the leakage charge)");
}

ButterflyFit fit_butterfly_record(std::span<const double> input, std::span<const double> output,
                                  const ButterflyFitOptions& options) {
  return fit_butterfly_strain(input, output, options);
}

std::unique_ptr<DynamicModel> butterfly_dynamic_model(ButterflyFit fit) {
  return std::make_unique<ModelAdapter<ButterflyCodec>>(std::move(fit.model),
                                                        std::move(fit.initial_state));
}

ButterflyFit fit_butterfly_records(std::span<const FitRecord> records,
                                   const ButterflyFitOptions& options) {
  return fit_butterfly_strain(records, options);
}

}  // namespace

ModelEntry butterfly_strain_entry() {
  auto entry = entry_of<ButterflyCodec>(
      "butterfly strain: Preisach polarisation P(v) and a static map y = y_off + d v + sum q_n "
      "P^n (electrostriction); latent-P fit by Levenberg-Marquardt; inverse on monotone branches");
  set_fitter<ButterflyCodec>(entry, butterfly_fit_option_table(), &fit_butterfly_record);
  set_records_fitter<ButterflyCodec>(entry, butterfly_fit_option_table(), &fit_butterfly_records);
  // P switches between -1 and +1 at +-2/3 (three levels); y = P + 0.3 P^2 has no vertex in
  // [-1, 1], so this example inverts over its whole range (q_2 > q_1 / 2 draws a butterfly).
  entry.example_params = {{"levels", 3},
                          {"lower", -1.0},
                          {"upper", 1.0},
                          {"weights", {0.1, 0.0, 0.1, 0.7, 0.0, 0.1}},
                          {"field_coefficient", 0.0},
                          {"polarisation_coefficients", {1.0, 0.3}},
                          {"offset", 0.0}};
  return entry;
}

}  // namespace hyst::detail

namespace hyst {

ButterflyFitOptions butterfly_fit_options(const nlohmann::json& options) {
  static const auto table = detail::butterfly_fit_option_table();
  return table.read(options, "fit options");
}

ButterflyModelFit fit_butterfly_strain_model(std::span<const FitRecord> records,
                                             const nlohmann::json& options) {
  auto fit = fit_butterfly_strain(records, butterfly_fit_options(options));
  auto report = std::move(fit.report);
  return {detail::butterfly_dynamic_model(std::move(fit)), std::move(report)};
}

ButterflyTwoStageModelFit fit_butterfly_strain_model_with_polarisation(
    std::span<const double> input, std::span<const double> polarisation,
    std::span<const double> output, const nlohmann::json& options) {
  static const auto table = detail::butterfly_two_stage_option_table();
  auto fit = fit_butterfly_strain_with_polarisation(input, polarisation, output,
                                                    table.read(options, "fit options"));
  auto report = std::move(fit.fit.report);
  return {detail::butterfly_dynamic_model(std::move(fit.fit)), std::move(report),
          std::move(fit.polarisation_report), std::move(fit.map_report), fit.leakage_conductance};
}

}  // namespace hyst
