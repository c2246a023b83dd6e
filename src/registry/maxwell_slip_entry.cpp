// Registry entry of the Maxwell-slip model: its model-file form, its inverse (through the
// equivalent PI model, when there is a linear spring) and its NNLS fitter.

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "hyst/identify/fit_maxwell_slip.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/models/maxwell_slip.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

nlohmann::json inverse_state_to_json(const InversePrandtlIshlinskii::State& state) {
  return {{"play", state.play}};
}

struct MaxwellSlipCodec {
  using Model = MaxwellSlip;
  static constexpr std::string_view name = "maxwell_slip";

  static nlohmann::json params_to_json(const Model& model) {
    const auto& p = model.params();
    return {{"stiffness", p.stiffness},
            {"break_away", p.break_away},
            {"linear_stiffness", p.linear_stiffness},
            {"offset", p.offset},
            {"orientation", orientation_name(p.orientation)}};
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"deflection", state.deflection}, {"input", state.input}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    auto deflection = fields.numbers("deflection");
    const double input = fields.number("input");
    return state_at(fields, [&] { return model.make_state(std::move(deflection), input); });
  }
  static std::size_t parameter_count(const Model& model) { return 2 * model.size() + 2; }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    std::string text = fmt::format(
        "Maxwell-slip model: {} elasto-slide elements, linear stiffness {}, offset {}, {} loop, "
        "{}invertible\n   i    stiffness k_i   break-away f_i   slip f_i/k_i\n",
        model.size(), p.linear_stiffness, p.offset, orientation_name(p.orientation),
        model.is_invertible() ? "" : "not ");
    for (std::size_t i = 0; i < model.size(); ++i) {
      text += fmt::format("{:4}  {:14.8g}  {:14.8g}  {:14.8g}\n", i, p.stiffness[i],
                          p.break_away[i], model.slip_displacements()[i]);
    }
    return text;
  }
  static bool has_inverse(const Model& model) { return model.is_invertible(); }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    if (!model.is_invertible()) {
      throw Error(
          "the Maxwell-slip model has no inverse unless its slope just after a reversal is > 0: "
          "linear_stiffness > 0 (clockwise) or linear_stiffness > sum of stiffness "
          "(counter-clockwise)",
          "linear_stiffness");
    }
    InversePrandtlIshlinskii inverse(model.to_prandtl_ishlinskii(),
                                     {limits.input_min, limits.input_max});
    auto inverse_state = inverse.state_consistent_with(model.prandtl_ishlinskii_state(state));
    return std::make_unique<
        InverseAdapter<InversePrandtlIshlinskii, decltype(&inverse_state_to_json)>>(
        std::move(inverse), std::move(inverse_state), &inverse_state_to_json);
  }
};

MaxwellSlip::Params maxwell_slip_params_from_json(const nlohmann::json& params_json,
                                                  const std::string& path) {
  JsonFields fields(params_json, path);
  MaxwellSlip::Params params;
  params.stiffness = fields.numbers("stiffness");
  params.break_away = fields.numbers("break_away");
  params.linear_stiffness = fields.number_or("linear_stiffness", 0.0);
  params.offset = fields.number_or("offset", 0.0);
  if (fields.has("orientation")) {
    params.orientation =
        parse_orientation(fields.string("orientation"), fields.path_of("orientation"));
  }
  fields.finish();
  return params;
}

std::unique_ptr<DynamicModel> create_maxwell_slip(const nlohmann::json& params_json,
                                                  const nlohmann::json* state_json) {
  return make_dynamic_model<MaxwellSlipCodec>(maxwell_slip_params_from_json(params_json, "params"),
                                              state_json);
}

FitOutcome fit_maxwell_slip_request(const FitRequest& request) {
  JsonFields fields(request.options, "fit options");
  MaxwellSlipFitOptions options;
  options.elements = fields.count_or("elements", options.elements);
  if (fields.has("slip_displacements")) {
    options.slip_displacements = fields.numbers("slip_displacements");
  }
  options.fit_linear_stiffness =
      fields.boolean_or("fit_linear_stiffness", options.fit_linear_stiffness);
  options.fit_offset = fields.boolean_or("fit_offset", options.fit_offset);
  const auto orientation = fields.string_or("orientation", "auto");
  if (orientation != "auto") {
    options.orientation = parse_orientation(orientation, fields.path_of("orientation"));
  }
  fields.finish();
  options.validate_fraction = request.validate_fraction;
  auto result = fit_maxwell_slip(request.input, request.output, options);
  return {std::make_unique<ModelAdapter<MaxwellSlipCodec>>(std::move(result.model),
                                                           std::move(result.initial_state)),
          std::move(result.report)};
}

}  // namespace

ModelEntry maxwell_slip_entry() {
  ModelEntry entry;
  entry.name = std::string(MaxwellSlipCodec::name);
  entry.description =
      "Maxwell-slip: parallel elasto-slide elements (stop operators), clockwise or "
      "counter-clockwise loops; inverse via the PI form; stiffnesses by NNLS";
  entry.parameters = {
      {"stiffness", "array of numbers", "force / position units", "k_i > 0 of each element"},
      {"break_away", "array of numbers", "force units",
       "f_i > 0 of each element; f_i/k_i strictly increasing"},
      {"linear_stiffness", "number", "force / position units",
       "k_lin >= 0 of a parallel spring (default 0); > 0 makes the model invertible"},
      {"offset", "number", "force units", "F_off (default 0)"},
      {"orientation", "string", "",
       "\"clockwise\" (default: F = F_off + k_lin x + sum k_i delta_i) or \"counter-clockwise\" "
       "(F = F_off + k_lin x - sum k_i delta_i)"},
  };
  entry.fit_options = {
      {"elements", "whole number", "", "N elements when slip_displacements is not given (10)"},
      {"slip_displacements", "array of numbers", "position units",
       "fixed f_i/k_i, increasing (default: uniform up to half the range)"},
      {"fit_linear_stiffness", "boolean", "", "fit k_lin >= 0 (true)"},
      {"fit_offset", "boolean", "", "fit the force offset (true)"},
      {"orientation", "string", "",
       "loop orientation in the (x, F) plane: \"auto\" (default: the sign of the enclosed "
       "area, clockwise when the area is 0), \"clockwise\" or \"counter-clockwise\""},
  };
  entry.create = &create_maxwell_slip;
  entry.fit = &fit_maxwell_slip_request;
  entry.example_params = {{"stiffness", {3.0, 2.0, 1.0}},
                          {"break_away", {0.3, 0.4, 0.5}},
                          {"linear_stiffness", 0.5},
                          {"offset", 0.0}};
  entry.actuator_force = actuator_force_of<MaxwellSlipCodec>();
  return entry;
}

}  // namespace hyst::detail
