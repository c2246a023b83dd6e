#include "hyst/registry/model_file.hpp"

#include <algorithm>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "../detail/json_fields.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"

namespace hyst {

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
    if (!version) throw Error("version: missing field (this library writes version 1)");
    if (!version->is_number_integer() || version->get<long long>() != kModelFileVersion) {
      throw Error(fmt::format("version: {} is not supported (this library reads version {})",
                              version->dump(), kModelFileVersion));
    }
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

namespace {

//! " at line L, column C" for nlohmann's "number overflow parsing '1e400'", which has no position:
//! the first occurrence of the number in the text. Empty for other messages.
std::string overflow_position(const std::string& message, std::string_view text) {
  const std::string_view marker = "overflow parsing '";
  const auto start = message.find(marker);
  if (start == std::string::npos) return {};
  const auto end = message.find('\'', start + marker.size());
  if (end == std::string::npos) return {};
  const auto number =
      std::string_view(message).substr(start + marker.size(), end - start - marker.size());
  const auto at = text.find(number);
  if (number.empty() || at == std::string_view::npos) return {};
  const auto before = text.substr(0, at);
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const auto line_start = before.rfind('\n');
  const auto column = line_start == std::string_view::npos ? at + 1 : at - line_start;
  return fmt::format(" at line {}, column {}", line, column);
}

}  // namespace

std::unique_ptr<DynamicModel> load_model(const std::filesystem::path& path,
                                         const ModelRegistry& registry) {
  const std::string text = io::read_file(path);
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& error) {
    // Syntax errors (parse_error) and numbers beyond double (out_of_range 406, "number overflow
    // parsing '1e400'"). The library's message reads "[json.exception.parse_error.101] parse
    // error at line 3, column 5: ..."; keep the part after the tag.
    std::string message = error.what();
    if (const auto tag_end = message.find("] "); tag_end != std::string::npos) {
      message = message.substr(tag_end + 2);
    }
    throw Error(fmt::format("{}: not valid JSON: {}{}", path.string(), message,
                            overflow_position(message, text)));
  }
  return model_from_json(document, path.string(), registry);
}

void save_model(const std::filesystem::path& path, const DynamicModel& model,
                const nlohmann::json& info) {
  io::write_file_atomically(path, model_to_json(model, info).dump(2) + "\n");
}

}  // namespace hyst
