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

// "clockwise" or "counter-clockwise"; an error names the field as the model's own check does.
MaxwellSlip::Orientation orientation_field(JsonFields& fields) {
  return parse_orientation(fields.string("orientation"), fields.path_of("orientation"));
}

struct MaxwellSlipCodec : CodecOf<MaxwellSlip, "maxwell_slip"> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("stiffness", &P::stiffness, "force / position units", "k_i > 0 of each element")
        .add("break_away", &P::break_away, "force units",
             "f_i > 0 of each element; f_i/k_i strictly increasing")
        .add("linear_stiffness", &P::linear_stiffness, "force / position units",
             "k_lin >= 0 of a parallel spring; > 0 makes the model invertible", Presence::optional)
        .add("offset", &P::offset, "force units", "F_off", Presence::optional)
        .add_custom(
            {"orientation", "string", "",
             "\"clockwise\" (F = F_off + k_lin x + sum k_i delta_i) or \"counter-clockwise\" "
             "(F = F_off + k_lin x - sum k_i delta_i)",
             "clockwise"},
            Presence::optional,
            [](JsonFields& fields, P& p) { p.orientation = orientation_field(fields); },
            [](const P& p, nlohmann::json& json) {
              json["orientation"] = orientation_name(p.orientation);
            });
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

FieldTable<MaxwellSlipFitOptions> maxwell_slip_fit_option_table() {
  using O = MaxwellSlipFitOptions;
  return FieldTable<O>(Presence::optional)
      .add("elements", &O::elements, "", "N elements when slip_displacements is not given")
      .add("slip_displacements", &O::slip_displacements, "position units",
           "fixed f_i/k_i, increasing (default: uniform up to half the range)")
      .add("fit_linear_stiffness", &O::fit_linear_stiffness, "", "fit k_lin >= 0")
      .add("fit_offset", &O::fit_offset, "", "fit the force offset")
      .add_custom(
          {"orientation", "string", "",
           "loop orientation in the (x, F) plane: \"auto\" (the sign of the "
           "enclosed area, clockwise when the area is 0), \"clockwise\" or "
           "\"counter-clockwise\"",
           "auto"},
          Presence::optional,
          [](JsonFields& fields, O& options) {
            if (fields.string("orientation") == "auto") {
              options.orientation.reset();
            } else {
              options.orientation = orientation_field(fields);
            }
          },
          [](const O& options, nlohmann::json& json) {
            json["orientation"] = options.orientation ? orientation_name(*options.orientation)
                                                      : std::string_view("auto");
          });
}

}  // namespace

ModelEntry maxwell_slip_entry() {
  auto entry = entry_of<MaxwellSlipCodec>(
      "Maxwell-slip: parallel elasto-slide elements (stop operators), clockwise or "
      "counter-clockwise loops; inverse via the PI form; stiffnesses by NNLS");
  set_fitter<MaxwellSlipCodec>(entry, maxwell_slip_fit_option_table(), &fit_maxwell_slip);
  entry.example_params = {{"stiffness", {3.0, 2.0, 1.0}},
                          {"break_away", {0.3, 0.4, 0.5}},
                          {"linear_stiffness", 0.5},
                          {"offset", 0.0}};
  entry.actuator_force = actuator_force_of<MaxwellSlipCodec>();
  return entry;
}

}  // namespace hyst::detail
