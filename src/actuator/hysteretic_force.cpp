#include "hyst/actuator/hysteretic_force.hpp"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "../detail/json_fields.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

// The registry entries that can be a force, in the order of their first alternative in
// AnyHysteresis.
std::vector<const ModelEntry*> force_entries() {
  std::vector<const ModelEntry*> entries;
  for (const auto& entry : ModelRegistry::builtin().entries()) {
    if (entry.actuator_force) entries.push_back(&entry);
  }
  const auto first = [](const ModelEntry* entry) {
    const auto& alternatives = entry->actuator_force->alternatives;
    return *std::min_element(alternatives.begin(), alternatives.end());
  };
  // Every alternative belongs to one entry, so no two entries tie and a plain sort is stable.
  std::sort(entries.begin(), entries.end(),
            [&](const ModelEntry* a, const ModelEntry* b) { return first(a) < first(b); });
  return entries;
}

// The entry's model of `params` without state; the entry's messages name "params", the
// configuration's messages name `params_path` ("hysteresis.params.rho: ...").
std::unique_ptr<DynamicModel> create_at(const ModelEntry& entry, const nlohmann::json& params,
                                        const std::string& params_path) {
  try {
    return entry.create(params, nullptr);
  } catch (const Error& error) {
    const std::string_view message = error.what();
    constexpr std::string_view kParams = "params";
    const bool at_params = message.starts_with(kParams) && message.size() > kParams.size() &&
                           (message[kParams.size()] == '.' || message[kParams.size()] == ':');
    if (!at_params) throw;
    throw Error(params_path + std::string(message.substr(kParams.size())), error.field());
  }
}

// A model whose inverse does not exist (is_invertible() false) cannot be compensated: building
// its inverse throws the message that says why (the limits do not matter for it).
template <class H>
void require_invertible(const H& model, const std::string& params_path) {
  if constexpr (requires { model.is_invertible(); }) {
    if (model.is_invertible()) return;
    try {
      ForceInverse<H>::make(model, 0.0, 1.0);
    } catch (const Error& error) {
      detail::rethrow_at(error, params_path);
    }
    throw Error(params_path + ": the model is not invertible");
  }
}

}  // namespace

std::string_view hysteresis_name(const AnyHysteresis& model) {
  for (const auto* entry : force_entries()) {
    const auto& alternatives = entry->actuator_force->alternatives;
    if (std::find(alternatives.begin(), alternatives.end(), model.index()) != alternatives.end())
      return entry->name;
  }
  throw Error(
      fmt::format("no registry entry provides the force model of alternative {}", model.index()));
}

std::string hysteresis_names() {
  std::string list;
  for (const auto* entry : force_entries())
    list += (list.empty() ? "" : ", ") + entry->name;
  return list;
}

AnyHysteresis hysteresis_from_json(const nlohmann::json& document, const std::string& path) {
  detail::JsonFields fields(document, path);
  const auto name = fields.string("model");
  const auto* params = fields.raw("params");
  fields.finish();
  const std::string params_path = fields.path_of("params");
  if (params == nullptr) throw Error(params_path + ": missing");
  // Unknown names get the registry's message listing the known models.
  const auto& entry = ModelRegistry::builtin().find(name);
  if (entry.name == "rate_dependent_pi") {
    throw Error(fields.path_of("model") +
                    ": model 'rate_dependent_pi' cannot be an actuator force: its output depends "
                    "on the input rate (through the model's own sample time) and hyst has no "
                    "inverse for it to compensate the force (use one of " +
                    hysteresis_names() + ")",
                "model");
  }
  if (!entry.actuator_force) {
    throw Error(fields.path_of("model") + ": model '" + name +
                    "' cannot be an actuator force (use one of " + hysteresis_names() + ")",
                "model");
  }
  AnyHysteresis model = entry.actuator_force->hysteresis(*create_at(entry, *params, params_path));
  std::visit([&](const auto& held) { require_invertible(held, params_path); }, model);
  return model;
}

}  // namespace hyst
