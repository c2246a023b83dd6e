// Registry entry of the modified PI model with creep: its model-file form (the fields of the PI
// with creep and of the modified PI's dead zones), its exact inverse and its NNLS fit.

#include <fmt/format.h>

#include "c_code_capability.hpp"
#include "creep_fields.hpp"
#include "hyst/identify/fit_modified_prandtl_ishlinskii_creep.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/modified_prandtl_ishlinskii_creep.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"
#include "modified_pi_fields.hpp"

namespace hyst::detail {
namespace {

struct ModifiedPiCreepCodec : CodecOf<ModifiedPrandtlIshlinskiiCreep, "modified_pi_creep">,
                              ContinuousTimeCodec<ModifiedPrandtlIshlinskiiCreep> {
  // The file's fields are flat: those of the PI with creep (its offset "pi_offset"), the dead
  // zones', the output offset and limits.
  static FieldTable<P> parameters() {
    auto table = FieldTable<P>().add_all(
        &P::pi_creep, pi_creep_fields("pi_offset", "offset q of the PI with creep"));
    add_output_shaping_fields(table);
    return table;
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return creep_state_to_json(state);
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    return creep_state_from_json(model, fields);
  }
  static std::size_t parameter_count(const Model& model) {
    const auto& core = model.hysteresis_creep();
    return core.size() * (1 + core.lags()) + model.dead_zone().size() + 2;
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
               "Modified Prandtl-Ishlinskii model with creep: {} play operators, {} creep lags, "
               "sample time {} s, PI offset {}, {} dead zones, output offset {}, {}invertible\n",
               model.hysteresis_creep().size(), model.hysteresis_creep().lags(),
               p.pi_creep.sample_time, p.pi_creep.offset, model.dead_zone().size(), p.offset,
               model.is_invertible() ? "" : "not ") +
           describe_plays_and_lags(model.hysteresis_creep()) + describe_dead_zones(p.dead_zone);
  }
  static bool has_inverse(const Model& model) { return model.is_invertible(); }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    InverseModifiedPrandtlIshlinskiiCreep inverse(model, {limits.input_min, limits.input_max});
    auto inverse_state = inverse.state_consistent_with(state);
    return std::make_unique<InverseAdapter<InverseModifiedPrandtlIshlinskiiCreep,
                                           decltype(&creep_inverse_state_to_json)>>(
        std::move(inverse), std::move(inverse_state), &creep_inverse_state_to_json);
  }
};

std::unique_ptr<DynamicModel> create_modified_prandtl_ishlinskii_creep(
    const nlohmann::json& params_json, const nlohmann::json* state_json) {
  auto params = params_of_json<ModifiedPiCreepCodec>(params_json, "params");
  try {
    return make_dynamic_model<ModifiedPiCreepCodec>(std::move(params), state_json);
  } catch (const Error& error) {
    throw with_file_field_names(
        error, {{"pi_creep.offset", "pi_offset"}, {"pi_creep.", ""}, {"dead_zone.", "dead_zone_"}});
  }
}

FieldTable<ModifiedPiCreepFitOptions> modified_prandtl_ishlinskii_creep_fit_option_table() {
  using O = ModifiedPiCreepFitOptions;
  return add_creep_fit_options(
             add_dead_zone_fit_options(add_play_weight_options(FieldTable<O>(Presence::optional))))
      .add("output_error_iterations", &O::output_error_iterations, "",
           "iterations of the output-error stage after the NNLS (0: the NNLS alone)");
}

ModifiedPiCreepFit fit_modified_pi_creep_record(std::span<const double> input,
                                                std::span<const double> output,
                                                const ModifiedPiCreepFitOptions& options) {
  return fit_modified_prandtl_ishlinskii_creep(input, output, options);
}

ModifiedPiCreepFit fit_modified_pi_creep_records(std::span<const FitRecord> records,
                                                 const ModifiedPiCreepFitOptions& options) {
  return fit_modified_prandtl_ishlinskii_creep(records, options);
}

}  // namespace

ModelEntry modified_prandtl_ishlinskii_creep_entry() {
  ModelEntry entry;
  entry.name = std::string(ModifiedPiCreepCodec::name);
  entry.description =
      "modified PI with Kuhnen creep: PI and creep lags, then dead-zone superposition; every "
      "weight by one NNLS (equation error); exact inverse";
  entry.parameters = parameter_table<ModifiedPiCreepCodec>().schema();
  entry.create = &create_modified_prandtl_ishlinskii_creep;
  set_fitter<ModifiedPiCreepCodec>(entry, modified_prandtl_ishlinskii_creep_fit_option_table(),
                                   &fit_modified_pi_creep_record);
  set_records_fitter<ModifiedPiCreepCodec>(
      entry, modified_prandtl_ishlinskii_creep_fit_option_table(), &fit_modified_pi_creep_records);
  entry.c_code = c_code_of<ModifiedPiCreepCodec>();
  entry.example_params = {{"thresholds", {0.0, 0.3, 0.7}},
                          {"weights", {0.8, 0.5, 0.3}},
                          {"time_constants", {0.01, 0.1}},
                          {"creep_weights", {0.1, 0.05, 0.02, 0.05, 0.02, 0.01}},
                          {"sample_time", 1e-3},
                          {"pi_offset", 0.0},
                          {"dead_zone_thresholds", {-1.5, -0.8, 0.0, 0.9, 1.6}},
                          {"dead_zone_weights", {0.1, 0.2, 1.0, -0.2, -0.1}},
                          {"offset", 0.0}};
  return entry;
}

}  // namespace hyst::detail
