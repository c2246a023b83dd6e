// Fuzz target: every JSON entry point of hyst with the same input - the checked reader itself
// (io::parse_json_text, which --options and `hyst info` use, and io::check_json_text, which
// every --option value passes), model files (load_model) and actuator configurations
// (load_actuator_config).
//
// Beyond "no crash": the checked reader must agree with nlohmann's own SAX parser on every text
// that parser accepts - it accepts the text exactly when the nesting is at most
// limits::kMaxJsonDepth, no object repeats a key and no NUL byte follows (nlohmann's parser
// takes one for the end of the input).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "hyst/actuator/actuator_config.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/io/limits.hpp"
#include "hyst/registry/model_file.hpp"

namespace {

//! Depth and duplicate keys as nlohmann's SAX parser sees them (it does not recurse).
struct Shape : nlohmann::json_sax<nlohmann::json> {
  std::size_t depth = 0;
  std::size_t deepest = 0;
  bool duplicate = false;
  std::vector<std::set<std::string>> keys;  // one set per open object

  bool open(bool object) {
    deepest = std::max(deepest, ++depth);
    if (object) keys.emplace_back();
    // Stop early where the checked reader must refuse anyway (keeps the oracle bounded).
    return depth <= hyst::io::limits::kMaxJsonDepth + 1;
  }
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return open(true); }
  bool key(string_t& name) override {
    if (!keys.back().insert(name).second) duplicate = true;
    return true;
  }
  bool end_object() override {
    keys.pop_back();
    --depth;
    return true;
  }
  bool start_array(std::size_t) override { return open(false); }
  bool end_array() override {
    --depth;
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = hyst::fuzz::as_text(data, size);

  bool accepted = true;
  try {
    static_cast<void>(hyst::io::parse_json_text(text, "fuzz.json"));
  } catch (const hyst::Error&) {
    accepted = false;
  }
  Shape shape;
  const bool valid = nlohmann::json::sax_parse(text, &shape, nlohmann::json::input_format_t::json,
                                               /*strict=*/true);
  if (valid) {
    // nlohmann stops at a NUL byte (and ignores the rest); the checked reader refuses one.
    const bool allowed = shape.deepest <= hyst::io::limits::kMaxJsonDepth && !shape.duplicate &&
                         text.find('\0') == std::string_view::npos;
    if (accepted != allowed) std::abort();
  } else if (accepted) {
    std::abort();  // the checked reader accepted what nlohmann refuses
  }
  try {
    hyst::io::check_json_text(text, "--option 'x=...'");
  } catch (const hyst::Error&) {
  }

  const auto path = hyst::fuzz::scratch_file("fuzz.json", text);
  try {
    static_cast<void>(hyst::load_model(path));
  } catch (const hyst::Error&) {
  }
  try {
    static_cast<void>(hyst::load_actuator_config(path));
  } catch (const hyst::Error&) {
  }
  return 0;
}
