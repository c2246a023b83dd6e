// Registry entry of the butterfly strain model with creep: its model-file form (the butterfly
// model's fields, then the creep part's), its inverse on monotone branches and its fit.

#include <cmath>

#include <fmt/format.h>

#include "butterfly_fields.hpp"
#include "creep_fields.hpp"
#include "hyst/identify/fit_butterfly_strain_creep.hpp"
#include "hyst/inverse/inverse_butterfly_strain_creep.hpp"
#include "hyst/models/butterfly_strain_creep.hpp"
#include "hyst/registry/butterfly_creep_fit.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

// {"saturation", "memory", "input"} of the switching part, "play", "creep" and ("leakage") of
// the creep part.
nlohmann::json butterfly_creep_state_to_json(const ButterflyStrainCreep::State& state) {
  auto json = preisach_state_to_json(state.switching);
  json["play"] = state.creep.play;
  json["creep"] = state.creep.creep;
  if (state.creep.leakage != 0.0) json["leakage"] = state.creep.leakage;
  return json;
}

struct ButterflyCreepCodec : CodecOf<ButterflyStrainCreep, "butterfly_strain_creep">,
                             ContinuousTimeCodec<ButterflyStrainCreep> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add_all(&P::butterfly, butterfly_strain_fields())
        .add("creep_thresholds", &P::creep_thresholds, "input units",
             "play half-widths 0 = r_0 < r_1 < ... of the creep part")
        .add("time_constants", &P::time_constants, "s", "creep lags tau_i > 0, increasing")
        .add("creep_weights", &P::creep_weights, "P units / input units",
             "c_ij >= 0, row-major: one row of one weight per creep threshold for each time "
             "constant")
        .add("sample_time", &P::sample_time, "s", "Ts > 0 of the input samples")
        .add("leakage_conductance", &P::leakage_conductance, "P units / (input units s)",
             "g: the leakage charge's rate per unit input (0: none); it strains nothing",
             Presence::optional)
        .add("leakage_current", &P::leakage_current, "P units / s",
             "i0: the leakage charge's rate at zero input (0: none)", Presence::optional);
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return butterfly_creep_state_to_json(state);
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    auto switching = preisach_state_from_json(model.butterfly().polarisation_model(), fields);
    auto play = fields.numbers("play");
    auto creep = fields.numbers("creep");
    const double leakage = fields.number_or("leakage", 0.0);
    auto creep_state = state_at(fields, [&] {
      return model.creep().make_state(std::move(play), std::move(creep), leakage);
    });
    return {std::move(switching), std::move(creep_state)};
  }
  static std::size_t parameter_count(const Model& model) {
    const auto& p = model.params();
    return p.butterfly.polarisation.everett.weights.size() + model.butterfly().degree() + 3 +
           p.creep_weights.size() + (model.creep().has_leakage() ? 2 : 0);
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    const auto& grid = p.butterfly.polarisation.everett;
    std::string text = fmt::format(
        "Butterfly strain model with creep: switching polarisation by a Preisach relay grid of {} "
        "levels on [{}, {}] ({} relays, total weight F0 = {}, P offset {}, initial state {}); "
        "creep by {} plays and {} lags, sample time {} s{};\n"
        "strain y = {} + {} v",
        grid.levels, grid.lower, grid.upper, grid.weights.size(),
        model.butterfly().polarisation_model().total_weight(), p.butterfly.polarisation.offset,
        to_string(p.butterfly.polarisation.initial_state), model.creep().size(),
        model.creep().lags(), p.sample_time,
        model.creep().has_leakage()
            ? fmt::format(", leakage charge g = {:.6g} per input unit s, i0 = {:.6g} per s",
                          p.leakage_conductance, p.leakage_current)
            : std::string(),
        p.butterfly.offset, p.butterfly.field_coefficient);
    for (std::size_t n = 0; n < model.butterfly().degree(); ++n)
      text += fmt::format(" + {} P^{}", p.butterfly.polarisation_coefficients[n], n + 1);
    return text + " (P = switching + creep, without the leakage charge)\n" +
           describe_plays_and_lags(model.creep());
  }
  static bool has_inverse(const Model&) { return true; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    // Unlimited: the polarisation's input range widened by its span on either side (the switching
    // stops beyond it, but the creep lags keep following the input).
    const auto& grid = model.params().butterfly.polarisation.everett;
    const double span = grid.upper - grid.lower;
    const double lo = std::isfinite(limits.input_min) ? limits.input_min : grid.lower - span;
    const double hi = std::isfinite(limits.input_max) ? limits.input_max : grid.upper + span;
    return std::make_unique<
        InverseAdapter<InverseButterflyStrainCreep, decltype(&butterfly_creep_state_to_json)>>(
        InverseButterflyStrainCreep(model, {lo, hi}), state, &butterfly_creep_state_to_json);
  }
};

FieldTable<ButterflyCreepFitOptions> butterfly_creep_fit_option_table() {
  using O = ButterflyCreepFitOptions;
  return FieldTable<O>(Presence::optional)
      .add_all(&O::switching, butterfly_fit_option_table())
      .add("creep_operators", &O::creep_operators, "",
           "plays of the creep part when creep_thresholds are not given")
      .add("creep_thresholds", &O::creep_thresholds, "input units",
           "fixed play half-widths of the creep part (default: uniform over the input)")
      .add("creep_law", &O::creep_law, creep_law_from_string,
           "logarithmic (default: lags from 10 Ts to longest_time_constant, weights smooth in log "
           "tau) or free (every creep weight free, lags within the record)")
      .add("law_smoothing", &O::law_smoothing, "",
           "logarithmic: weight of the smoothness penalty across lags (default: chosen by forward "
           "validation)")
      .add("lags", &O::lags, "", "free: number of creep lags when time_constants are not given")
      .add("time_constants", &O::time_constants, "s", "fixed creep time constants")
      .add("lags_per_decade", &O::lags_per_decade, "",
           "logarithmic: time constants per decade (without time_constants)")
      .add("longest_time_constant", &O::longest_time_constant, "s",
           "logarithmic: the slowest lag (without time_constants)")
      .add("sample_time", &O::sample_time, "s", "Ts of the record")
      .add("rounds", &O::rounds, "", "Gauss-Newton rounds of the creep weights and the map")
      .add("fit_leakage", &O::fit_leakage, "",
           "with measured polarisation only (Python): fit the leakage charge g sum Ts v + i0 t");
}

std::unique_ptr<DynamicModel> butterfly_creep_dynamic_model(ButterflyCreepFit fit) {
  return std::make_unique<ModelAdapter<ButterflyCreepCodec>>(std::move(fit.model),
                                                             std::move(fit.initial_state));
}

ButterflyCreepFit fit_butterfly_creep_record(std::span<const double> input,
                                             std::span<const double> output,
                                             const ButterflyCreepFitOptions& options) {
  return fit_butterfly_strain_creep(input, output, options);
}

ButterflyCreepFit fit_butterfly_creep_records(std::span<const FitRecord> records,
                                              const ButterflyCreepFitOptions& options) {
  return fit_butterfly_strain_creep(records, options);
}

}  // namespace

ModelEntry butterfly_strain_creep_entry() {
  auto entry = entry_of<ButterflyCreepCodec>(
      "butterfly strain with creep: Preisach switching plus Kuhnen creep lags drive the strain "
      "map y = y_off + d v + sum q_n P^n; a leakage charge strains nothing; fit by the butterfly "
      "fit and Gauss-Newton NNLS on the creep weights (logarithmic law); inverse on monotone "
      "branches");
  set_fitter<ButterflyCreepCodec>(entry, butterfly_creep_fit_option_table(),
                                  &fit_butterfly_creep_record);
  set_records_fitter<ButterflyCreepCodec>(entry, butterfly_creep_fit_option_table(),
                                          &fit_butterfly_creep_records);
  // The butterfly example's switching and map (invertible over its whole range) with two lags
  // on two plays: after a step the strain keeps growing by a tenth.
  entry.example_params = {{"levels", 3},
                          {"lower", -1.0},
                          {"upper", 1.0},
                          {"weights", {0.1, 0.0, 0.1, 0.7, 0.0, 0.1}},
                          {"field_coefficient", 0.0},
                          {"polarisation_coefficients", {1.0, 0.3}},
                          {"offset", 0.0},
                          {"creep_thresholds", {0.0, 0.5}},
                          {"time_constants", {0.01, 0.1}},
                          {"creep_weights", {0.05, 0.02, 0.05, 0.02}},
                          {"sample_time", 1e-3}};
  return entry;
}

}  // namespace hyst::detail

namespace hyst {

ButterflyCreepTwoStageModelFit fit_butterfly_strain_creep_model_with_polarisation(
    std::span<const double> input, std::span<const double> polarisation,
    std::span<const double> output, const nlohmann::json& options) {
  static const auto table = detail::butterfly_creep_fit_option_table();
  // The held-out fraction, which the registry's fits take beside their options.
  auto rest = options;
  double validate_fraction = 0.0;
  if (rest.is_object() && rest.contains("validate_fraction")) {
    const auto& value = rest["validate_fraction"];
    if (!value.is_number()) throw Error("fit options.validate_fraction: expected a number");
    validate_fraction = value.get<double>();
    rest.erase("validate_fraction");
  }
  auto fit_options = table.read(rest, "fit options");
  fit_options.validate_fraction = validate_fraction;
  auto fit = fit_butterfly_strain_creep_with_polarisation(input, polarisation, output, fit_options);
  auto report = std::move(fit.fit.report);
  return {detail::butterfly_creep_dynamic_model(std::move(fit.fit)), std::move(report),
          std::move(fit.polarisation_report)};
}

}  // namespace hyst
