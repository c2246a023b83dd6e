#pragma once
// Reading model-file JSON with error messages that name the field path ("params.weights[2]").

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "hyst/core/error.hpp"

namespace hyst::detail {

// The fields of one JSON object. Every accessor records the key as known; finish() then rejects
// any field that was not asked for, so typos in model files do not pass silently.
class JsonFields {
 public:
  // Throws unless `value` is an object: "params: expected an object, got array".
  JsonFields(const nlohmann::json& value, std::string path);

  const std::string& path() const { return path_; }
  std::string path_of(std::string_view key) const;

  // True if the field is present; either way the key counts as known.
  bool has(std::string_view key);
  double number(std::string_view key);
  double number_or(std::string_view key, double fallback);
  std::vector<double> numbers(std::string_view key);
  std::size_t count(std::string_view key);
  std::vector<std::size_t> counts(std::string_view key);
  std::size_t count_or(std::string_view key, std::size_t fallback);
  bool boolean(std::string_view key);
  bool boolean_or(std::string_view key, bool fallback);
  std::string string(std::string_view key);
  std::string string_or(std::string_view key, std::string fallback);
  // A string field turned into a value by `parse` (e.g. an enumeration's from_string); a
  // hyst::Error from `parse` gets the field's path in front.
  template <class Parse>
  auto parsed(std::string_view key, Parse parse) {
    const auto text = string(key);
    try {
      return parse(text);
    } catch (const Error& error) {
      throw Error(path_of(key) + ": " + error.what());
    }
  }
  // The raw value of a field, or nullptr when absent.
  const nlohmann::json* raw(std::string_view key);

  // Throws for the first field that no accessor asked for: "params.wieghts: unknown field
  // (known: thresholds, weights, offset)".
  void finish() const;

 private:
  const nlohmann::json& require(std::string_view key);

  const nlohmann::json& object_;
  std::string path_;
  std::vector<std::string> known_;
};

// A description of a JSON value's type for messages: "string \"abc\"", "array", "null".
std::string describe_json(const nlohmann::json& value);

// Reads a JSON number; throws "<path>: expected a number, got string \"x\"" or
// "<path> = inf is not finite".
double json_number(const nlohmann::json& value, const std::string& path);

// Rethrows a hyst::Error from model validation with the JSON path of its field in front:
// "params.thresholds[3]: PI threshold r[3] = -0.2 must be > r[2] = 1".
[[noreturn]] void rethrow_at(const Error& error, std::string_view object_path);

}  // namespace hyst::detail
