#include "hyst/actuator/hysteretic_force.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include <fmt/format.h>

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

// Each force model's registry name and how its "params" object becomes the model.
template <class H>
struct ForceModel;

template <Envelope E>
struct ForceModel<GeneralizedPrandtlIshlinskii<E>> {
  static constexpr std::string_view name = "gpi";
  static AnyHysteresis parse(const nlohmann::json& params, const std::string& path) {
    auto gpi = detail::generalized_prandtl_ishlinskii_params_from_json(params, path);
    return visit_envelope(gpi.envelope, [&]<class F>(F) -> AnyHysteresis {
      return build<GeneralizedPrandtlIshlinskii<F>>(gpi, path);
    });
  }
};

template <>
struct ForceModel<PrandtlIshlinskii> {
  static constexpr std::string_view name = "pi";
  static AnyHysteresis parse(const nlohmann::json& params, const std::string& path) {
    return build<PrandtlIshlinskii>(detail::prandtl_ishlinskii_params_from_json(params, path),
                                    path);
  }
};

template <>
struct ForceModel<Preisach> {
  static constexpr std::string_view name = "preisach";
  static AnyHysteresis parse(const nlohmann::json& params, const std::string& path) {
    return build<Preisach>(detail::preisach_params_from_json(params, path), path);
  }
};

template <>
struct ForceModel<ModifiedPrandtlIshlinskii> {
  static constexpr std::string_view name = "modified_pi";
  static AnyHysteresis parse(const nlohmann::json& params, const std::string& path) {
    try {
      return ModifiedPrandtlIshlinskii(
          detail::modified_prandtl_ishlinskii_params_from_json(params, path));
    } catch (const Error& error) {  // the file's flat field names
      detail::rethrow_at(
          Error(error.what(), detail::modified_prandtl_ishlinskii_file_field(error.field())), path);
    }
  }
};

template <>
struct ForceModel<KrasnoselskiiPokrovskii> {
  static constexpr std::string_view name = "kp";
  static AnyHysteresis parse(const nlohmann::json& params, const std::string& path) {
    return build<KrasnoselskiiPokrovskii>(
        detail::krasnoselskii_pokrovskii_params_from_json(params, path), path);
  }
};

template <>
struct ForceModel<MaxwellSlip> {
  static constexpr std::string_view name = "maxwell_slip";
  static AnyHysteresis parse(const nlohmann::json& params, const std::string& path) {
    return build<MaxwellSlip>(detail::maxwell_slip_params_from_json(params, path), path);
  }
};

template <>
struct ForceModel<IkutaSma> {
  static constexpr std::string_view name = "ikuta_sma";
  static AnyHysteresis parse(const nlohmann::json& params, const std::string& path) {
    return build<IkutaSma>(detail::ikuta_sma_params_from_json(params, path), path);
  }
};

template <>
struct ForceModel<BoucWen> {
  static constexpr std::string_view name = "bouc_wen";
  static AnyHysteresis parse(const nlohmann::json& params, const std::string& path) {
    return build<BoucWen>(detail::bouc_wen_params_from_json(params, path), path);
  }
};

// A model whose inverse does not exist (is_invertible() false) cannot be compensated: building
// its inverse throws the message that says why (the limits do not matter for it).
template <class H>
void require_invertible(const H& model, const std::string& params_path) {
  if constexpr (requires { model.is_invertible(); }) {
    if (model.is_invertible()) return;
    try {
      InverseModel<H>::make(model, 0.0, 1.0);
    } catch (const Error& error) {
      detail::rethrow_at(error, params_path);
    }
    throw Error(params_path + ": the model is not invertible");
  }
}

// The first alternative of AnyHysteresis named `name` parses it; nullopt if none is.
template <std::size_t... I>
std::optional<AnyHysteresis> parse_named(std::string_view name, const nlohmann::json& params,
                                         const std::string& path, std::index_sequence<I...>) {
  std::optional<AnyHysteresis> model;
  ((!model && ForceModel<std::variant_alternative_t<I, AnyHysteresis>>::name == name
        ? (void)model.emplace(
              ForceModel<std::variant_alternative_t<I, AnyHysteresis>>::parse(params, path))
        : (void)0),
   ...);
  return model;
}

template <std::size_t... I>
std::string names(std::index_sequence<I...>) {
  const std::string_view all[] = {
      ForceModel<std::variant_alternative_t<I, AnyHysteresis>>::name...};
  std::string list;
  for (std::size_t k = 0; k < std::size(all); ++k) {
    if (std::find(all, all + k, all[k]) != all + k) continue;  // the GPI envelopes share "gpi"
    list += (list.empty() ? "" : ", ") + std::string(all[k]);
  }
  return list;
}

constexpr auto kAlternatives = std::make_index_sequence<std::variant_size_v<AnyHysteresis>>{};

}  // namespace

std::string_view hysteresis_name(const AnyHysteresis& model) {
  return std::visit(
      [](const auto& held) -> std::string_view {
        return ForceModel<std::decay_t<decltype(held)>>::name;
      },
      model);
}

std::string hysteresis_names() {
  return names(kAlternatives);
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
  auto model = parse_named(entry.name, *params, params_path, kAlternatives);
  if (!model) {
    throw Error(fields.path_of("model") + ": model '" + name +
                    "' cannot be an actuator force (use one of " + hysteresis_names() + ")",
                "model");
  }
  std::visit([&](const auto& held) { require_invertible(held, params_path); }, *model);
  return std::move(*model);
}

}  // namespace hyst
