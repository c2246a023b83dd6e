// Registry entry of the discrete Preisach model (relay grid, fast Everett form): its model-file
// form, its numerical inverse and its NNLS fitter.

#include <cmath>

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "c_code_capability.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_preisach.hpp"
#include "hyst/inverse/inverse_preisach.hpp"
#include "hyst/models/preisach.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"
#include "preisach_state_json.hpp"

namespace hyst::detail {
namespace {

Preisach::Params preisach_params_from_json(const nlohmann::json& params_json,
                                           const std::string& path) {
  JsonFields fields(params_json, path);
  Preisach::Params params;
  params.everett.levels = fields.count("levels");
  params.everett.lower = fields.number("lower");
  params.everett.upper = fields.number("upper");
  params.everett.weights = fields.numbers("weights");
  if (fields.has("layout")) {
    params.everett.layout = fields.parsed("layout", preisach_grid_layout_from_string);
  }
  params.offset = fields.number_or("offset", 0.0);
  if (fields.has("initial_state")) {
    params.initial_state = fields.parsed("initial_state", preisach_initial_state_from_string);
  }
  fields.finish();
  return params;
}

struct PreisachCodec {
  using Model = Preisach;
  static constexpr std::string_view name = "preisach";

  static nlohmann::json params_to_json(const Model& model) {
    const auto& p = model.params();
    return {{"levels", p.everett.levels},
            {"lower", p.everett.lower},
            {"upper", p.everett.upper},
            {"weights", p.everett.weights},
            {"layout", std::string(to_string(p.everett.layout))},
            {"offset", p.offset},
            {"initial_state", std::string(to_string(p.initial_state))}};
  }
  static nlohmann::json state_to_json(const Model&, const PreisachState& state) {
    return preisach_state_to_json(state);
  }
  static PreisachState state_from_json(const Model& model, JsonFields& fields) {
    return preisach_state_from_json(model, fields);
  }
  static std::size_t parameter_count(const Model& model) {
    return model.params().everett.weights.size() + 1;
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "Preisach model: {} levels on [{}, {}] ({} relays, {} layout), total weight F0 = {}, "
        "offset {}, output range [{}, {}], initial state {}\n",
        p.everett.levels, p.everett.lower, p.everett.upper, p.everett.weights.size(),
        to_string(p.everett.layout), model.total_weight(), p.offset, model.output_min(),
        model.output_max(), to_string(p.initial_state));
  }
  static bool has_inverse(const Model&) { return true; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model,
                                                      const PreisachState& state,
                                                      const InverseLimits& limits) {
    InversePreisachOptions options;
    if (std::isfinite(limits.input_min)) options.input_min = limits.input_min;
    if (std::isfinite(limits.input_max)) options.input_max = limits.input_max;
    return std::make_unique<InverseAdapter<InversePreisach, decltype(&preisach_state_to_json)>>(
        InversePreisach(model, options), state, &preisach_state_to_json);
  }
};

using PreisachAdapter = ModelAdapter<PreisachCodec>;

std::unique_ptr<DynamicModel> create_preisach(const nlohmann::json& params_json,
                                              const nlohmann::json* state_json) {
  return make_dynamic_model<PreisachCodec>(preisach_params_from_json(params_json, "params"),
                                           state_json);
}

FitOutcome fit_preisach_request(const FitRequest& request) {
  JsonFields fields(request.options, "fit options");
  PreisachWeightFitOptions options;
  options.levels = fields.count_or("levels", options.levels);
  if (fields.has("lower")) options.lower = fields.number("lower");
  if (fields.has("upper")) options.upper = fields.number("upper");
  if (fields.has("layout")) {
    options.layout = fields.parsed("layout", preisach_grid_layout_from_string);
  }
  if (fields.has("initial_state")) {
    options.initial_state = fields.parsed("initial_state", preisach_initial_state_from_string);
  }
  options.smoothness = fields.number_or("smoothness", options.smoothness);
  options.fit_offset = fields.boolean_or("fit_offset", options.fit_offset);
  fields.finish();
  options.validate_fraction = request.validate_fraction;

  auto result = fit_preisach_weights(request.input, request.output, options);
  auto initial = result.model.initial_state();
  return {std::make_unique<PreisachAdapter>(std::move(result.model), std::move(initial)),
          std::move(result.report)};
}

}  // namespace

ModelEntry preisach_entry() {
  ModelEntry entry;
  entry.name = std::string(PreisachCodec::name);
  entry.description =
      "Preisach: weighted relays on a triangular grid, fast Everett form (cost independent of "
      "the grid); numerical inverse; weights by NNLS";
  entry.parameters = {
      {"levels", "whole number", "", "N threshold levels: N(N+1)/2 relays alpha >= beta"},
      {"lower", "number", "input units", "lower end of the input range (negative saturation)"},
      {"upper", "number", "input units", "upper end of the input range (positive saturation)"},
      {"weights", "array of numbers", "output units",
       "mu >= 0 per relay, relay (i, j) at index i(i+1)/2 + j"},
      {"layout", "string", "", "cell_centred (default) or endpoints"},
      {"offset", "number", "output units", "y_off (default 0)"},
      {"initial_state", "string", "",
       "negative_saturation (default), positive_saturation or demagnetised"},
  };
  entry.fit_options = {
      {"levels", "whole number", "", "N threshold levels (21)"},
      {"lower", "number", "input units", "grid range (default: the data's)"},
      {"upper", "number", "input units", "grid range (default: the data's)"},
      {"layout", "string", "", "cell_centred or endpoints"},
      {"initial_state", "string", "", "state the record starts from (negative_saturation)"},
      {"smoothness", "number", "", "Tikhonov weight on neighbouring relay weights (0)"},
      {"fit_offset", "boolean", "", "fit the output offset (true)"},
  };
  entry.create = &create_preisach;
  entry.fit = &fit_preisach_request;
  // The unweighted 231-relay model of the seed paper (mu = 1 for every relay).
  entry.example_params = {{"levels", 21},
                          {"lower", -1.0},
                          {"upper", 1.0},
                          {"weights", std::vector<double>(231, 1.0)},
                          {"layout", "cell_centred"},
                          {"offset", 0.0},
                          {"initial_state", "negative_saturation"}};
  entry.c_code = c_code_of<PreisachCodec>();
  entry.actuator_force = actuator_force_of<PreisachCodec>();
  return entry;
}

}  // namespace hyst::detail
