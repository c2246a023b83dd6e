// Registry entry of the PI model with creep: its model-file form, its exact inverse and its
// joint NNLS fit of hysteresis and creep weights.

#include <fmt/format.h>

#include "c_code_capability.hpp"
#include "creep_fields.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii_creep.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

struct PiCreepCodec : CodecOf<PrandtlIshlinskiiCreep, "pi_creep">,
                      ContinuousTimeCodec<PrandtlIshlinskiiCreep> {
  static FieldTable<P> parameters() {
    return pi_creep_fields("offset", "y_off")
        .add("leakage_conductance", &P::leakage_conductance, "output / (input units s)",
             "g: the leakage drift's rate per unit input (0: none)", Presence::optional)
        .add("leakage_current", &P::leakage_current, "output units / s",
             "i0: the leakage drift's rate at zero input (0: none)", Presence::optional);
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    auto json = creep_state_to_json(state);
    if (state.leakage != 0.0) json["leakage"] = state.leakage;
    return json;
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    auto play = fields.numbers("play");
    auto creep = fields.numbers("creep");
    const double leakage = fields.number_or("leakage", 0.0);
    return state_at(fields,
                    [&] { return model.make_state(std::move(play), std::move(creep), leakage); });
  }
  static std::size_t parameter_count(const Model& model) {
    return model.size() * (1 + model.lags()) + 1 + (model.has_leakage() ? 2 : 0);
  }
  static std::string describe(const Model& model) {
    return fmt::format(
               "Prandtl-Ishlinskii model with creep: {} play operators, {} creep lags, sample "
               "time {} s, offset {}{}\n",
               model.size(), model.lags(), model.params().sample_time, model.params().offset,
               model.has_leakage()
                   ? fmt::format(", leakage g = {:.6g} per input unit s, i0 = {:.6g} per s",
                                 model.params().leakage_conductance, model.params().leakage_current)
                   : std::string()) +
           describe_plays_and_lags(model);
  }
  static bool has_inverse(const Model& model) {
    return PrandtlIshlinskii({model.params().thresholds, model.instantaneous_weights(), 0.0})
        .is_invertible();
  }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    InversePrandtlIshlinskiiCreep inverse(model, {limits.input_min, limits.input_max});
    auto inverse_state = inverse.state_consistent_with(state);
    return std::make_unique<
        InverseAdapter<InversePrandtlIshlinskiiCreep, decltype(&creep_inverse_state_to_json)>>(
        std::move(inverse), std::move(inverse_state), &creep_inverse_state_to_json);
  }
};

FieldTable<PiCreepFitOptions> prandtl_ishlinskii_creep_fit_option_table() {
  using O = PiCreepFitOptions;
  return add_creep_fit_options(add_play_weight_options(FieldTable<O>(Presence::optional)))
      .add("creep_law", &O::creep_law, creep_law_from_string,
           "free (every creep weight free, lags within the record) or logarithmic (lags from 10 Ts "
           "to longest_time_constant, weights smooth in log tau: a hold longer than the record's "
           "keeps creeping by the same amount per decade)")
      .add("law_smoothing", &O::law_smoothing, "",
           "logarithmic: weight of the smoothness penalty on the creep weights across lags")
      .add("lags_per_decade", &O::lags_per_decade, "",
           "logarithmic: time constants per decade (without time_constants)")
      .add("longest_time_constant", &O::longest_time_constant, "s",
           "logarithmic: the slowest lag (without time_constants)")
      .add("fit_leakage", &O::fit_leakage, "",
           "fit the leakage conductance and current (a drift g v + i0 integrated over time)");
}

PiCreepFit fit_pi_creep_record(std::span<const double> input, std::span<const double> output,
                               const PiCreepFitOptions& options) {
  return fit_prandtl_ishlinskii_creep(input, output, options);
}

PiCreepFit fit_pi_creep_records(std::span<const FitRecord> records,
                                const PiCreepFitOptions& options) {
  return fit_prandtl_ishlinskii_creep(records, options);
}

}  // namespace

ModelEntry prandtl_ishlinskii_creep_entry() {
  auto entry = entry_of<PiCreepCodec>(
      "PI with Kuhnen creep: plays driving first-order lags (exactly discretised), hysteresis and "
      "creep weights by one NNLS; exact inverse");
  set_fitter<PiCreepCodec>(entry, prandtl_ishlinskii_creep_fit_option_table(),
                           &fit_pi_creep_record);
  set_records_fitter<PiCreepCodec>(entry, prandtl_ishlinskii_creep_fit_option_table(),
                                   &fit_pi_creep_records);
  entry.c_code = c_code_of<PiCreepCodec>();
  entry.example_params = {{"thresholds", {0.0, 0.25, 0.5}},
                          {"weights", {1.0, 0.5, 0.25}},
                          {"time_constants", {0.01, 0.1}},
                          {"creep_weights", {0.1, 0.05, 0.02, 0.05, 0.02, 0.01}},
                          {"sample_time", 1e-3},
                          {"offset", 0.0}};
  return entry;
}

}  // namespace hyst::detail
