#pragma once
// The model-file form of a Preisach model, shared by every Preisach entry (relay grid, tabulated
// Everett function): its parameters (the Everett function's fields, offset, initial state) and
// its state: the saturation the history starts from, the stored extrema, and the last input (null
// when no input was applied since saturation; JSON has no infinity).

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "../detail/json_fields.hpp"
#include "field_table.hpp"
#include "hyst/core/error.hpp"
#include "hyst/inverse/inverse_preisach.hpp"
#include "hyst/models/preisach.hpp"
#include "model_adapter.hpp"

namespace hyst::detail {

// The relay grid's fields: levels, input range, weights (in `weight_unit`), layout.
inline FieldTable<RelayGridEverett::Params> relay_grid_everett_table(
    std::string weight_unit = "output units") {
  using E = RelayGridEverett::Params;
  return FieldTable<E>()
      .add("levels", &E::levels, "", "N threshold levels: N(N+1)/2 relays alpha >= beta")
      .add("lower", &E::lower, "input units", "lower end of the input range (negative saturation)")
      .add("upper", &E::upper, "input units", "upper end of the input range (positive saturation)")
      .add("weights", &E::weights, std::move(weight_unit),
           "mu >= 0 per relay, relay (i, j) at index i(i+1)/2 + j")
      .add("layout", &E::layout, preisach_grid_layout_from_string, "cell_centred or endpoints",
           Presence::optional);
}

template <class Params, class EverettParams>
FieldTable<Params> preisach_parameter_table(const FieldTable<EverettParams>& everett) {
  return FieldTable<Params>()
      .add_all(&Params::everett, everett)
      .add("offset", &Params::offset, "output units", "y_off", Presence::optional)
      .add("initial_state", &Params::initial_state, preisach_initial_state_from_string,
           "negative_saturation, positive_saturation or demagnetised", Presence::optional);
}

inline nlohmann::json preisach_state_to_json(const PreisachState& state) {
  const auto memory = state.memory();
  return {{"saturation",
           state.from_positive_saturation() ? "positive_saturation" : "negative_saturation"},
          {"memory", std::vector<double>(memory.begin(), memory.end())},
          {"input", std::isfinite(state.input) ? nlohmann::json(state.input) : nlohmann::json()}};
}

//! The state of `model` from a file's state object; errors name the field ("state.memory: ...").
template <class Model>
PreisachState preisach_state_from_json(const Model& model, JsonFields& fields) {
  const auto saturation_text = fields.string("saturation");
  const auto memory = fields.numbers("memory");
  const auto* input = fields.raw("input");
  try {
    const auto saturation = preisach_initial_state_from_string(saturation_text);
    if (saturation == PreisachInitialState::demagnetised) {
      throw Error("saturation must be negative_saturation or positive_saturation");
    }
    double last = saturation == PreisachInitialState::positive_saturation
                      ? std::numeric_limits<double>::infinity()
                      : -std::numeric_limits<double>::infinity();
    if (input && !input->is_null()) last = json_number(*input, fields.path_of("input"));
    return model.make_state(saturation, memory, last);
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", fields.path(), error.what()));
  }
}

// What the codecs of both Preisach entries share: the state's JSON form and the numerical
// inverse (InversePreisach or InverseTabulatedPreisach), within the given input limits.
template <class M, class Inverse, CodecName Name>
struct PreisachCodecCommon : CodecOf<M, Name> {
  template <class Model>
  static nlohmann::json state_to_json(const Model&, const PreisachState& state) {
    return preisach_state_to_json(state);
  }
  template <class Model>
  static PreisachState state_from_json(const Model& model, JsonFields& fields) {
    return preisach_state_from_json(model, fields);
  }
  template <class Model>
  static bool has_inverse(const Model&) {
    return true;
  }
  template <class Model>
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model,
                                                      const PreisachState& state,
                                                      const InverseLimits& limits) {
    InversePreisachOptions options;
    if (std::isfinite(limits.input_min)) options.input_min = limits.input_min;
    if (std::isfinite(limits.input_max)) options.input_max = limits.input_max;
    return std::make_unique<InverseAdapter<Inverse, decltype(&preisach_state_to_json)>>(
        Inverse(model, options), state, &preisach_state_to_json);
  }
};

}  // namespace hyst::detail
