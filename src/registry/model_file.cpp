#include "hyst/registry/model_file.hpp"

#include <algorithm>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "../detail/json_fields.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/json_text.hpp"

namespace hyst {

void require_model_file_version(const nlohmann::json* version) {
  if (!version)
    throw Error(
        fmt::format("version: missing field (this library writes version {})", kModelFileVersion));
  if (!version->is_number_integer() || version->get<long long>() != kModelFileVersion)
    throw Error(fmt::format("version: {} is not supported (this library reads version {})",
                            version->dump(), kModelFileVersion));
}

std::unique_ptr<DynamicModel> model_from_json(const nlohmann::json& document,
                                              std::string_view source,
                                              const ModelRegistry& registry) {
  try {
    if (!document.is_object()) {
      throw Error(fmt::format("expected a JSON object, got {}", detail::describe_json(document)));
    }
    detail::JsonFields fields(document, "");
    const auto name = fields.string("model");
    const auto& entry = registry.find(name);
    const auto* version = fields.raw("version");
    require_model_file_version(version);
    const auto* params = fields.raw("params");
    if (!params) throw Error("params: missing field");
    const auto* state = fields.raw("state");
    const auto* info = fields.raw("info");
    if (info && !info->is_object()) {
      throw Error(fmt::format("info: expected an object, got {}", detail::describe_json(*info)));
    }
    fields.finish();
    return entry.create(*params, state);
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", source, error.what()));
  }
}

nlohmann::json model_to_json(const DynamicModel& model, const nlohmann::json& info) {
  nlohmann::json document = {{"model", std::string(model.name())},
                             {"version", kModelFileVersion},
                             {"params", model.params()},
                             {"state", model.state()}};
  if (!info.empty()) document["info"] = info;
  return document;
}

std::unique_ptr<DynamicModel> load_model(const std::filesystem::path& path,
                                         const ModelRegistry& registry) {
  const nlohmann::json document = io::parse_json_text(io::read_file(path), path.string());
  return model_from_json(document, path.string(), registry);
}

void save_model(const std::filesystem::path& path, const DynamicModel& model,
                const nlohmann::json& info) {
  io::write_file_atomically(path, model_to_json(model, info).dump(2) + "\n");
}

}  // namespace hyst
