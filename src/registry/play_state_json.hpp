#pragma once
// The state of the play operators of a PI model in model files: {"play": [...]}, shared by the
// PI and the modified PI entries.

#include <nlohmann/json.hpp>

#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst::detail {

inline nlohmann::json play_state_to_json(const PrandtlIshlinskii::State& state) {
  return {{"play", state.play}};
}

}  // namespace hyst::detail
