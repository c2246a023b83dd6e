// Registry entry of the Krasnosel'skii-Pokrovskii model: its model-file form and its NNLS
// fitter. No inverse.

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "hyst/identify/fit_krasnoselskii_pokrovskii.hpp"
#include "hyst/models/krasnoselskii_pokrovskii.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

struct KpCodec {
  using Model = KrasnoselskiiPokrovskii;
  static constexpr std::string_view name = "kp";

  static nlohmann::json params_to_json(const Model& model) {
    const auto& p = model.params();
    return {{"levels", p.levels},   {"lower", p.lower},           {"upper", p.upper},
            {"weights", p.weights}, {"ramp_cells", p.ramp_cells}, {"offset", p.offset}};
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"kernels", state.kernels}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    auto kernels = fields.numbers("kernels");
    return state_at(fields, [&] { return model.make_state(std::move(kernels)); });
  }
  static std::size_t parameter_count(const Model& model) { return model.kernel_count() + 1; }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "Krasnosel'skii-Pokrovskii model: {} cells on [{}, {}] ({} kernels, ramp {} cells), "
        "total weight {}, offset {}\n",
        p.levels, p.lower, p.upper, model.kernel_count(), p.ramp_cells, model.total_weight(),
        p.offset);
  }
  static bool has_inverse(const Model&) { return false; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model&, const Model::State&,
                                                      const InverseLimits&) {
    throw Error("the KP model has no inverse in hyst (use the Preisach model's numerical one)");
  }
};

KrasnoselskiiPokrovskii::Params krasnoselskii_pokrovskii_params_from_json(
    const nlohmann::json& params_json, const std::string& path) {
  JsonFields fields(params_json, path);
  KrasnoselskiiPokrovskii::Params params;
  params.levels = fields.count("levels");
  params.lower = fields.number("lower");
  params.upper = fields.number("upper");
  params.weights = fields.numbers("weights");
  params.ramp_cells = fields.number_or("ramp_cells", params.ramp_cells);
  params.offset = fields.number_or("offset", 0.0);
  fields.finish();
  return params;
}

std::unique_ptr<DynamicModel> create_krasnoselskii_pokrovskii(const nlohmann::json& params_json,
                                                              const nlohmann::json* state_json) {
  return make_dynamic_model<KpCodec>(
      krasnoselskii_pokrovskii_params_from_json(params_json, "params"), state_json);
}

FitOutcome fit_krasnoselskii_pokrovskii_request(const FitRequest& request) {
  JsonFields fields(request.options, "fit options");
  KpFitOptions options;
  options.levels = fields.count_or("levels", options.levels);
  if (fields.has("lower")) options.lower = fields.number("lower");
  if (fields.has("upper")) options.upper = fields.number("upper");
  options.ramp_cells = fields.number_or("ramp_cells", options.ramp_cells);
  options.fit_offset = fields.boolean_or("fit_offset", options.fit_offset);
  fields.finish();
  options.validate_fraction = request.validate_fraction;
  auto result = fit_krasnoselskii_pokrovskii(request.input, request.output, options);
  auto initial = result.model.initial_state();
  return {std::make_unique<ModelAdapter<KpCodec>>(std::move(result.model), std::move(initial)),
          std::move(result.report)};
}

}  // namespace

ModelEntry krasnoselskii_pokrovskii_entry() {
  ModelEntry entry;
  entry.name = std::string(KpCodec::name);
  entry.description =
      "Krasnosel'skii-Pokrovskii: ramped relays on a triangular grid, continuous output; weights "
      "by NNLS";
  entry.parameters = {
      {"levels", "whole number", "", "N cells: N(N+1)/2 kernels"},
      {"lower", "number", "input units", "lower end of the grid (all kernels -1 below)"},
      {"upper", "number", "input units", "upper end of the grid (all kernels +1 above)"},
      {"weights", "array of numbers", "output units",
       "mu >= 0 per kernel, kernel (i, j) at index i(i+1)/2 + j"},
      {"ramp_cells", "number", "", "ramp width of the kernels in cells (default 1)"},
      {"offset", "number", "output units", "y_off (default 0)"},
  };
  entry.fit_options = {
      {"levels", "whole number", "", "N cells (12)"},
      {"lower", "number", "input units", "grid range (default: the data's)"},
      {"upper", "number", "input units", "grid range (default: the data's)"},
      {"ramp_cells", "number", "", "ramp width in cells (1)"},
      {"fit_offset", "boolean", "", "fit the output offset (true)"},
  };
  entry.create = &create_krasnoselskii_pokrovskii;
  entry.fit = &fit_krasnoselskii_pokrovskii_request;
  entry.example_params = {{"levels", 6},       {"lower", -1.0},
                          {"upper", 1.0},      {"weights", std::vector<double>(21, 1.0 / 21.0)},
                          {"ramp_cells", 1.0}, {"offset", 0.0}};
  entry.actuator_force = actuator_force_of<KpCodec>();
  return entry;
}

}  // namespace hyst::detail
