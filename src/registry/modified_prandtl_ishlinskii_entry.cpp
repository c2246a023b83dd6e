// Registry entry of the modified Prandtl-Ishlinskii model: its model-file form, its analytic
// inverse and its constrained least-squares fitter.

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "c_code_capability.hpp"
#include "hyst/identify/fit_modified_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"
#include "modified_pi_fields.hpp"
#include "play_state_json.hpp"

namespace hyst::detail {
namespace {

struct ModifiedPiCodec : CodecOf<ModifiedPrandtlIshlinskii, "modified_pi"> {
  static FieldTable<P> parameters() {
    using Pi = PrandtlIshlinskii::Params;
    // The file's fields are flat: the PI part's offset is "pi_offset", the dead zone's fields
    // have "dead_zone_" in front.
    const auto pi =
        FieldTable<Pi>()
            .add("thresholds", &Pi::thresholds, "input units",
                 "play half-widths 0 = r_0 < r_1 < ...")
            .add("weights", &Pi::weights, "output / input units", "p_j, one per threshold")
            .add("pi_offset", &Pi::offset, "output units", "offset of the PI part",
                 Presence::optional);
    auto table = FieldTable<P>().add_all(&P::pi, pi);
    add_output_shaping_fields(table);
    return table;
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return play_state_to_json(state);
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    return play_state_from_json(model, fields);
  }
  static std::size_t parameter_count(const Model& model) {
    return model.params().pi.weights.size() + model.params().dead_zone.weights.size() + 2;
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    std::string text = fmt::format(
        "Modified Prandtl-Ishlinskii model: {} play operators (offset {}), {} dead zones, output "
        "offset {}, {}invertible\n   j   threshold r_j      weight p_j\n",
        p.pi.thresholds.size(), p.pi.offset, p.dead_zone.thresholds.size(), p.offset,
        model.is_invertible() ? "" : "not ");
    for (std::size_t j = 0; j < p.pi.thresholds.size(); ++j)
      text += fmt::format("{:4}  {:14.8g}  {:14.8g}\n", j, p.pi.thresholds[j], p.pi.weights[j]);
    return text + describe_dead_zones(p.dead_zone);
  }
  static bool has_inverse(const Model& model) { return model.is_invertible(); }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    InverseModifiedPrandtlIshlinskii inverse(model, {limits.input_min, limits.input_max});
    auto inverse_state = inverse.state_consistent_with(state);
    return std::make_unique<
        InverseAdapter<InverseModifiedPrandtlIshlinskii, decltype(&play_state_to_json)>>(
        std::move(inverse), std::move(inverse_state), &play_state_to_json);
  }
};

std::unique_ptr<DynamicModel> create_modified_prandtl_ishlinskii(const nlohmann::json& params_json,
                                                                 const nlohmann::json* state_json) {
  auto params = params_of_json<ModifiedPiCodec>(params_json, "params");
  // The model's fields are "pi.thresholds" etc.; in the file they are flat.
  try {
    return make_dynamic_model<ModifiedPiCodec>(std::move(params), state_json);
  } catch (const Error& error) {
    throw with_file_field_names(
        error, {{"pi.offset", "pi_offset"}, {"pi.", ""}, {"dead_zone.", "dead_zone_"}});
  }
}

FieldTable<ModifiedPiFitOptions> modified_prandtl_ishlinskii_fit_option_table() {
  using O = ModifiedPiFitOptions;
  return add_dead_zone_fit_options(add_play_weight_options(FieldTable<O>(Presence::optional)))
      .add("initial_state", &O::initial_state, pi_initial_state_from_string,
           "virgin (plays at 0) or periodic (one period run first)");
}

}  // namespace

ModelEntry modified_prandtl_ishlinskii_entry() {
  ModelEntry entry;
  entry.name = std::string(ModifiedPiCodec::name);
  entry.description =
      "modified PI (Kuhnen): PI followed by dead-zone superposition; analytic inverse; weights "
      "by constrained least squares";
  entry.parameters = parameter_table<ModifiedPiCodec>().schema();
  entry.create = &create_modified_prandtl_ishlinskii;
  set_fitter<ModifiedPiCodec>(entry, modified_prandtl_ishlinskii_fit_option_table(),
                              &fit_modified_prandtl_ishlinskii);
  entry.example_params = {{"thresholds", {0.0, 0.3, 0.7, 1.0}},
                          {"weights", {0.8, 0.5, 0.3, 0.2}},
                          {"pi_offset", 0.0},
                          {"dead_zone_thresholds", {-1.5, -0.8, -0.3, 0.0, 0.4, 0.9, 1.6}},
                          {"dead_zone_weights", {0.05, 0.1, 0.2, 1.0, -0.15, -0.2, -0.1}},
                          {"offset", 0.0}};
  entry.c_code = c_code_of<ModifiedPiCodec>();
  entry.actuator_force = actuator_force_of<ModifiedPiCodec>();
  return entry;
}

}  // namespace hyst::detail
