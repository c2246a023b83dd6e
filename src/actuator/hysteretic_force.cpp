#include "hyst/actuator/hysteretic_force.hpp"

#include <type_traits>
#include <variant>

#include "../detail/json_fields.hpp"
#include "../registry/model_entries.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

// Builds the model, giving a validation error the JSON path of its field.
template <class Model, class Params>
Model build(Params params, const std::string& params_path) {
  try {
    return Model(std::move(params));
  } catch (const Error& error) {
    detail::rethrow_at(error, params_path);
  }
}

}  // namespace

std::string_view hysteresis_name(const AnyHysteresis& model) {
  return std::visit(
      [](const auto& held) -> std::string_view {
        using H = std::decay_t<decltype(held)>;
        if constexpr (std::is_same_v<H, PrandtlIshlinskii>) {
          return "pi";
        } else if constexpr (std::is_same_v<H, Preisach>) {
          return "preisach";
        } else {
          return "gpi";
        }
      },
      model);
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
  if (entry.name == "pi") {
    return build<PrandtlIshlinskii>(
        detail::prandtl_ishlinskii_params_from_json(*params, params_path), params_path);
  }
  if (entry.name == "preisach") {
    return build<Preisach>(detail::preisach_params_from_json(*params, params_path), params_path);
  }
  if (entry.name == "gpi") {
    auto gpi = detail::generalized_prandtl_ishlinskii_params_from_json(*params, params_path);
    return visit_envelope(gpi.envelope, [&]<class E>(E) -> AnyHysteresis {
      return build<GeneralizedPrandtlIshlinskii<E>>(gpi, params_path);
    });
  }
  throw Error(fields.path_of("model") + ": model '" + name +
                  "' cannot be an actuator force (use gpi, pi or preisach)",
              "model");
}

}  // namespace hyst
