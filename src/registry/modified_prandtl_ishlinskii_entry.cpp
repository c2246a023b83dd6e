// Registry entry of the modified Prandtl-Ishlinskii model: its model-file form, its analytic
// inverse and its constrained least-squares fitter.

#include <cmath>

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "c_code_capability.hpp"
#include "hyst/identify/fit_modified_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"
#include "play_state_json.hpp"

namespace hyst::detail {
namespace {

struct ModifiedPiCodec {
  using Model = ModifiedPrandtlIshlinskii;
  static constexpr std::string_view name = "modified_pi";

  static nlohmann::json params_to_json(const Model& model) {
    const auto& p = model.params();
    nlohmann::json json{{"thresholds", p.pi.thresholds},
                        {"weights", p.pi.weights},
                        {"pi_offset", p.pi.offset},
                        {"dead_zone_thresholds", p.dead_zone.thresholds},
                        {"dead_zone_weights", p.dead_zone.weights},
                        {"offset", p.offset}};
    // Infinite limits (no clamp) are left out: JSON has no infinity.
    if (std::isfinite(p.output_min)) json["output_min"] = p.output_min;
    if (std::isfinite(p.output_max)) json["output_max"] = p.output_max;
    return json;
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
    text += "   i   dead zone d_i      weight g_i\n";
    for (std::size_t i = 0; i < p.dead_zone.thresholds.size(); ++i) {
      text += fmt::format("{:4}  {:14.8g}  {:14.8g}\n", i, p.dead_zone.thresholds[i],
                          p.dead_zone.weights[i]);
    }
    return text;
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

ModifiedPrandtlIshlinskii::Params modified_prandtl_ishlinskii_params_from_json(
    const nlohmann::json& params_json, const std::string& path) {
  JsonFields fields(params_json, path);
  ModifiedPrandtlIshlinskii::Params params;
  params.pi.thresholds = fields.numbers("thresholds");
  params.pi.weights = fields.numbers("weights");
  params.pi.offset = fields.number_or("pi_offset", 0.0);
  params.dead_zone.thresholds = fields.numbers("dead_zone_thresholds");
  params.dead_zone.weights = fields.numbers("dead_zone_weights");
  params.offset = fields.number_or("offset", 0.0);
  params.output_min = fields.number_or("output_min", params.output_min);
  params.output_max = fields.number_or("output_max", params.output_max);
  fields.finish();
  return params;
}

std::string modified_prandtl_ishlinskii_file_field(const std::string& field) {
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"pi.offset", "pi_offset"},
                                 {"pi.", ""},
                                 {"dead_zone.", "dead_zone_"}}) {
    if (field.rfind(from, 0) == 0) return to + field.substr(from.size());
  }
  return field;
}

std::unique_ptr<DynamicModel> create_modified_prandtl_ishlinskii(const nlohmann::json& params_json,
                                                                 const nlohmann::json* state_json) {
  auto params = modified_prandtl_ishlinskii_params_from_json(params_json, "params");
  // The model's fields are "pi.thresholds" etc.; in the file they are flat.
  try {
    return make_dynamic_model<ModifiedPiCodec>(std::move(params), state_json);
  } catch (const Error& error) {
    const std::string message = error.what();
    if (message.rfind("params.", 0) != 0) throw;
    throw Error("params." + modified_prandtl_ishlinskii_file_field(message.substr(7)));
  }
}

const FieldTable<ModifiedPiFitOptions>& modified_prandtl_ishlinskii_fit_option_table() {
  using O = ModifiedPiFitOptions;
  static const auto table =
      FieldTable<O>(Presence::optional)
          .add("operators", &O::operators, "", "number of plays when thresholds are not given")
          .add("thresholds", &O::thresholds, "input units", "fixed thresholds (default: uniform)")
          .add("dead_zones", &O::dead_zones, "", "dead zones per side of the inverse map")
          .add("dead_zone_thresholds", &O::dead_zone_thresholds, "output units",
               "thresholds of the inverse dead-zone map around the offset, containing 0")
          .add("output_offset", &O::output_offset, "output units",
               "y_off (default: mid-range of the output)")
          .add("min_weight", &O::min_weight, "",
               "relative lower bound of p_0 and of the map's slopes")
          .add("initial_state", &O::initial_state, pi_initial_state_from_string,
               "virgin (plays at 0) or periodic (one period run first)")
          .add("clamp_output", &O::clamp_output, "",
               "limit the output to the fitted record's output range; false = no limits")
          .add("output_margin", &O::output_margin, "",
               "widen those limits by this fraction of the output range on each side");
  return table;
}

}  // namespace

ModelEntry modified_prandtl_ishlinskii_entry() {
  ModelEntry entry;
  entry.name = std::string(ModifiedPiCodec::name);
  entry.description =
      "modified PI (Kuhnen): PI followed by dead-zone superposition; analytic inverse; weights "
      "by constrained least squares";
  entry.parameters = {
      {"thresholds", "array of numbers", "input units", "play half-widths 0 = r_0 < r_1 < ...", {}},
      {"weights", "array of numbers", "output / input units", "p_j, one per threshold", {}},
      {"pi_offset", "number", "output units", "offset of the PI part (default 0)", {}},
      {"dead_zone_thresholds",
       "array of numbers",
       "output units",
       "d_i, increasing, one of them 0",
       {}},
      {"dead_zone_weights",
       "array of numbers",
       "",
       "g_i; invertible iff outward partial sums > 0",
       {}},
      {"offset", "number", "output units", "y_off added after the dead zones (default 0)", {}},
      {"output_min",
       "number",
       "output units",
       "lower limit the output is clamped to (default: none; a fit sets the record's minimum)",
       {}},
      {"output_max",
       "number",
       "output units",
       "upper limit the output is clamped to (default: none; a fit sets the record's maximum)",
       {}},
  };
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
