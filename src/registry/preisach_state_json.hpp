#pragma once
// The model-file form of a Preisach model, shared by every Preisach entry (relay grid, tabulated
// Everett function): its parameters (the Everett function's fields, offset, initial state) and
// its state: the saturation the history starts from, the stored extrema, and the last input (null
// when no input was applied since saturation; JSON has no infinity).

#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "../detail/json_fields.hpp"
#include "field_table.hpp"
#include "hyst/core/error.hpp"
#include "hyst/models/preisach.hpp"

namespace hyst::detail {

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

}  // namespace hyst::detail
