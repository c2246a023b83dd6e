#pragma once
// The actuator-force capability of an entry (ModelEntry::actuator_force): its concrete model as
// the alternative of AnyHysteresis.

#include <memory>

#include "hyst/registry/actuator_force.hpp"
#include "model_adapter.hpp"

namespace hyst::detail {

template <class... Codecs>
std::shared_ptr<const ActuatorForce> actuator_force_of() {
  return std::make_shared<const ActuatorForce>(ActuatorForce{
      [](const DynamicModel& model) {
        return with_concrete<Codecs...>(
            model, [](const auto& concrete, const auto&) { return AnyHysteresis(concrete); });
      },
      {hysteresis_index<typename Codecs::Model>...}});
}

}  // namespace hyst::detail
