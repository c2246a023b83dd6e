// Registry entry of Ikuta's SMA model (local memory): its model-file form. No inverse, no fitter.

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "hyst/models/ikuta_sma.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

struct IkutaSmaCodec : CodecOf<IkutaSma, "ikuta_sma"> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("martensite_finish", &P::martensite_finish, "input units",
             "M_f: cooling transformation ends (< M_s)")
        .add("martensite_start", &P::martensite_start, "input units",
             "M_s: cooling transformation starts")
        .add("austenite_start", &P::austenite_start, "input units",
             "A_s: heating transformation starts (>= M_f)")
        .add("austenite_finish", &P::austenite_finish, "input units",
             "A_f: heating transformation ends (>= M_s)")
        .add("output_austenite", &P::output_austenite, "output units",
             "y_A: output at martensite fraction 0")
        .add("output_martensite", &P::output_martensite, "output units",
             "y_M: output at martensite fraction 1")
        .add("initial_fraction", &P::initial_fraction, "", "martensite fraction at rest, in [0, 1]",
             Presence::optional)
        .add("initial_input", &P::initial_input, "input units", "input of the initial rest state",
             Presence::optional);
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"fraction", state.fraction},
            {"input", state.input},
            {"branch", std::string(to_string(state.branch))},
            {"scale", state.scale}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    const double fraction = fields.number("fraction");
    const double input = fields.number("input");
    const auto branch = fields.has("branch") ? fields.parsed("branch", ikuta_branch_from_string)
                                             : IkutaSma::Branch::rest;
    const double scale = fields.number_or("scale", -1.0);
    return state_at(fields, [&] { return model.make_state(fraction, input, branch, scale); });
  }
  static std::size_t parameter_count(const Model&) { return 6; }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "Ikuta SMA model (local memory, no internal loops): cooling window M_f = {} .. M_s = {}, "
        "heating window A_s = {} .. A_f = {}, output {} (austenite) .. {} (martensite); initial "
        "fraction {} at input {}\n",
        p.martensite_finish, p.martensite_start, p.austenite_start, p.austenite_finish,
        p.output_austenite, p.output_martensite, p.initial_fraction, p.initial_input);
  }
  static bool has_inverse(const Model&) { return false; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model&, const Model::State&,
                                                      const InverseLimits&) {
    throw Error(
        "the Ikuta SMA model is not invertible: its output is constant outside the "
        "transformation windows");
  }
};

}  // namespace

ModelEntry ikuta_sma_entry() {
  auto entry = entry_of<IkutaSmaCodec>(
      "Ikuta SMA model: cosine phase-fraction branches, local memory (no internal loops)");
  entry.example_params = {{"martensite_finish", -0.8}, {"martensite_start", 0.2},
                          {"austenite_start", -0.2},   {"austenite_finish", 0.8},
                          {"output_austenite", 1.0},   {"output_martensite", -1.0},
                          {"initial_fraction", 1.0},   {"initial_input", -1.0}};
  entry.actuator_force = actuator_force_of<IkutaSmaCodec>();
  return entry;
}

}  // namespace hyst::detail
