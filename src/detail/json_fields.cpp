#include "json_fields.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "hyst/io/limits.hpp"

namespace hyst::detail {

std::string describe_json(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::boolean:
      return fmt::format("boolean {}", value.get<bool>());
    case nlohmann::json::value_t::string: {
      auto text = value.get<std::string>();
      if (text.size() > 40) text = text.substr(0, 40) + "...";
      return fmt::format("string \"{}\"", text);
    }
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::binary:
      return "binary data";
    case nlohmann::json::value_t::discarded:
      return "an invalid value";
    default:
      return fmt::format("number {}", value.dump());
  }
}

double json_number(const nlohmann::json& value, const std::string& path) {
  if (!value.is_number()) {
    throw Error(fmt::format("{}: expected a number, got {}", path, describe_json(value)));
  }
  const double number = value.get<double>();
  if (!std::isfinite(number)) throw Error(fmt::format("{} = {} is not finite", path, number));
  return number;
}

void rethrow_at(const Error& error, std::string_view object_path) {
  if (error.field().empty()) throw Error(fmt::format("{}: {}", object_path, error.what()));
  throw Error(fmt::format("{}.{}: {}", object_path, error.field(), error.what()));
}

JsonFields::JsonFields(const nlohmann::json& value, std::string path)
    : object_(value), path_(std::move(path)) {
  if (!value.is_object()) {
    throw Error(fmt::format("{}: expected an object, got {}", path_, describe_json(value)));
  }
}

std::string JsonFields::path_of(std::string_view key) const {
  return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

bool JsonFields::has(std::string_view key) {
  // Asking for a field makes it a known one, present or not (for the unknown-field message).
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
  return object_.contains(key);
}

const nlohmann::json& JsonFields::require(std::string_view key) {
  has(key);
  const auto found = object_.find(key);
  if (found == object_.end()) throw Error(fmt::format("{}: missing field", path_of(key)));
  return *found;
}

const nlohmann::json* JsonFields::raw(std::string_view key) {
  has(key);
  const auto found = object_.find(key);
  return found == object_.end() ? nullptr : &*found;
}

double JsonFields::number(std::string_view key) {
  return json_number(require(key), path_of(key));
}

double JsonFields::number_or(std::string_view key, double fallback) {
  const auto* value = raw(key);
  return value ? json_number(*value, path_of(key)) : fallback;
}

namespace {

void require_array_length(const nlohmann::json& array, const std::string& path) {
  if (array.size() > io::limits::kMaxModelArrayValues) {
    throw Error(fmt::format("{}: {} values, more than the limit of {} values of one array", path,
                            array.size(), io::limits::kMaxModelArrayValues));
  }
}

}  // namespace

std::vector<double> JsonFields::numbers(std::string_view key) {
  const auto& value = require(key);
  if (!value.is_array()) {
    throw Error(fmt::format("{}: expected an array of numbers, got {}", path_of(key),
                            describe_json(value)));
  }
  require_array_length(value, path_of(key));
  std::vector<double> numbers;
  numbers.reserve(value.size());
  for (std::size_t j = 0; j < value.size(); ++j) {
    numbers.push_back(json_number(value[j], fmt::format("{}[{}]", path_of(key), j)));
  }
  return numbers;
}

namespace {

std::size_t json_count(const nlohmann::json& value, const std::string& path) {
  if (!value.is_number_integer() || value.get<long long>() < 0) {
    throw Error(fmt::format("{}: expected a non-negative whole number, got {}", path,
                            describe_json(value)));
  }
  return value.get<std::size_t>();
}

}  // namespace

std::size_t JsonFields::count(std::string_view key) {
  return json_count(require(key), path_of(key));
}

std::vector<std::size_t> JsonFields::counts(std::string_view key) {
  const auto& value = require(key);
  if (!value.is_array()) {
    throw Error(fmt::format("{}: expected an array of whole numbers, got {}", path_of(key),
                            describe_json(value)));
  }
  require_array_length(value, path_of(key));
  std::vector<std::size_t> counts;
  counts.reserve(value.size());
  for (std::size_t j = 0; j < value.size(); ++j) {
    counts.push_back(json_count(value[j], fmt::format("{}[{}]", path_of(key), j)));
  }
  return counts;
}

std::size_t JsonFields::count_or(std::string_view key, std::size_t fallback) {
  return has(key) ? count(key) : fallback;
}

bool JsonFields::boolean(std::string_view key) {
  const auto& value = require(key);
  if (!value.is_boolean()) {
    throw Error(
        fmt::format("{}: expected true or false, got {}", path_of(key), describe_json(value)));
  }
  return value.get<bool>();
}

bool JsonFields::boolean_or(std::string_view key, bool fallback) {
  return has(key) ? boolean(key) : fallback;
}

std::string JsonFields::string(std::string_view key) {
  const auto& value = require(key);
  if (!value.is_string()) {
    throw Error(fmt::format("{}: expected a string, got {}", path_of(key), describe_json(value)));
  }
  return value.get<std::string>();
}

std::string JsonFields::string_or(std::string_view key, std::string fallback) {
  return has(key) ? string(key) : std::move(fallback);
}

void JsonFields::finish() const {
  for (const auto& [key, value] : object_.items()) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) {
      std::string known;
      for (const auto& name : known_)
        known += (known.empty() ? "" : ", ") + name;
      throw Error(fmt::format("{}: unknown field (known: {})", path_of(key), known));
    }
  }
}

}  // namespace hyst::detail
