// FieldTable (src/registry/field_table.hpp): one description of a struct's fields gives its JSON
// reading and writing and its schema; and every registered model's files and fit options follow
// their tables.

#include <cmath>
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "field_table.hpp"
#include "hyst/core/error.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

enum class Colour { red, green };
std::string_view to_string(Colour colour) {
  return colour == Colour::red ? "red" : "green";
}
Colour colour_from_string(std::string_view text) {
  if (text == "red") return Colour::red;
  if (text == "green") return Colour::green;
  throw Error(fmt::format("unknown colour '{}' (expected red or green)", text));
}

using detail::FieldTable;
using detail::Presence;

struct Point {
  double x = 0.0;
  double y = 0.0;
};

struct Inner {
  std::size_t levels = 3;
  std::vector<double> weights;
};

struct Settings {
  double gain = 2.5;
  std::size_t count = 7;
  bool enabled = true;
  std::string label = "none";
  std::vector<double> values;
  std::vector<std::size_t> sizes{8};
  std::optional<double> limit;
  Colour colour = Colour::red;
  std::optional<Colour> accent;
  std::vector<Point> starts;
  Inner inner;
};

const FieldTable<Point>& point_table() {
  static const auto table =
      FieldTable<Point>().add("x", &Point::x, "m", "abscissa").add("y", &Point::y, "m", "ordinate");
  return table;
}

const FieldTable<Settings>& settings_table() {
  static const auto table = [] {
    const auto inner = FieldTable<Inner>(Presence::optional)
                           .add("levels", &Inner::levels, "", "grid levels")
                           .add("weights", &Inner::weights, "", "grid weights");
    return FieldTable<Settings>(Presence::optional)
        .add("gain", &Settings::gain, "V/m", "amplifier gain", Presence::required)
        .add("count", &Settings::count, "", "how many")
        .add("enabled", &Settings::enabled, "", "switch")
        .add("label", &Settings::label, "", "a name")
        .add("values", &Settings::values, "m", "samples")
        .add("sizes", &Settings::sizes, "", "layer sizes")
        .add("limit", &Settings::limit, "m", "upper limit (default: none)")
        .add("colour", &Settings::colour, colour_from_string, "red or green")
        .add("accent", &Settings::accent, colour_from_string, "red or green (default: none)")
        .add("starts", &Settings::starts, point_table(), "starting points")
        .add_all(&Settings::inner, inner);
  }();
  return table;
}

std::string error_of(const nlohmann::json& json) {
  try {
    settings_table().read(json, "options");
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

TEST(FieldTable, ReadsEveryKindOfField) {
  const auto settings =
      settings_table().read({{"gain", -1.5},
                             {"count", 4},
                             {"enabled", false},
                             {"label", "stage"},
                             {"values", {1.0, 2.0}},
                             {"sizes", {3, 2}},
                             {"limit", 0.25},
                             {"colour", "green"},
                             {"accent", "red"},
                             {"starts", {{{"x", 1.0}, {"y", 2.0}}, {{"x", -1.0}, {"y", 0.5}}}},
                             {"levels", 5},
                             {"weights", {0.5}}},
                            "options");
  EXPECT_EQ(settings.gain, -1.5);
  EXPECT_EQ(settings.count, 4u);
  EXPECT_FALSE(settings.enabled);
  EXPECT_EQ(settings.label, "stage");
  EXPECT_EQ(settings.values, (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(settings.sizes, (std::vector<std::size_t>{3, 2}));
  ASSERT_TRUE(settings.limit.has_value());
  EXPECT_EQ(*settings.limit, 0.25);
  EXPECT_EQ(settings.colour, Colour::green);
  ASSERT_TRUE(settings.accent.has_value());
  EXPECT_EQ(*settings.accent, Colour::red);
  ASSERT_EQ(settings.starts.size(), 2u);
  EXPECT_EQ(settings.starts[1].x, -1.0);
  EXPECT_EQ(settings.starts[1].y, 0.5);
  EXPECT_EQ(settings.inner.levels, 5u);
  EXPECT_EQ(settings.inner.weights, (std::vector<double>{0.5}));
}

TEST(FieldTable, FieldsLeftOutKeepTheDefaultsAndTheSchemaShowsThem) {
  const auto settings = settings_table().read({{"gain", 1.0}}, "options");
  const Settings defaults;
  EXPECT_EQ(settings.count, defaults.count);
  EXPECT_EQ(settings.sizes, defaults.sizes);
  EXPECT_FALSE(settings.limit.has_value());
  EXPECT_FALSE(settings.accent.has_value());
  EXPECT_EQ(settings.inner.levels, 3u);

  const auto& schema = settings_table().schema();
  ASSERT_EQ(schema.size(), 12u);  // the nested struct's fields are flat
  const auto find = [&](std::string_view name) {
    for (const auto& info : schema) {
      if (info.name == name) return info;
    }
    ADD_FAILURE() << name << " not in the schema";
    return ParameterInfo{};
  };
  EXPECT_EQ(find("gain").default_value, "");  // required
  EXPECT_EQ(find("gain").unit, "V/m");
  EXPECT_EQ(find("gain").type, "number");
  EXPECT_EQ(find("count").default_value, "7");
  EXPECT_EQ(find("count").type, "whole number");
  EXPECT_EQ(find("enabled").default_value, "true");
  EXPECT_EQ(find("label").default_value, "none");
  EXPECT_EQ(find("values").default_value, "");  // an empty list: the description says
  EXPECT_EQ(find("sizes").default_value, "[8]");
  EXPECT_EQ(find("sizes").type, "array of whole numbers");
  EXPECT_EQ(find("limit").default_value, "");
  EXPECT_EQ(find("colour").default_value, "red");
  EXPECT_EQ(find("colour").type, "string");
  EXPECT_EQ(find("starts").type, "array of objects");
  EXPECT_EQ(find("levels").default_value, "3");
}

TEST(FieldTable, OtherDefaultsThanTheStructs) {
  Settings defaults;
  defaults.count = 20;
  const auto table =
      FieldTable<Settings>(Presence::optional, defaults).add("count", &Settings::count, "", "n");
  EXPECT_EQ(table.read(nlohmann::json::object(), "options").count, 20u);
  EXPECT_EQ(table.schema().front().default_value, "20");
}

TEST(FieldTable, WritesWhatItReads) {
  Settings settings;
  settings.gain = 0.125;
  settings.values = {3.0};
  settings.limit = 9.0;
  settings.colour = Colour::green;
  settings.starts = {{0.5, 1.5}};
  settings.inner.weights = {1.0, 2.0};
  const auto json = settings_table().write(settings);
  EXPECT_EQ(json.at("colour"), "green");
  EXPECT_FALSE(json.contains("accent"));  // unset optionals are left out
  EXPECT_EQ(json.at("starts").at(0).at("y"), 1.5);
  EXPECT_EQ(json.at("levels"), 3);
  const auto again = settings_table().read(json, "options");
  EXPECT_EQ(settings_table().write(again), json);
}

TEST(FieldTable, ErrorsNameTheField) {
  EXPECT_EQ(error_of(nlohmann::json::object()), "options.gain: missing field");
  EXPECT_EQ(
      error_of({{"gain", 1.0}, {"cuont", 2}}).rfind("options.cuont: unknown field (known: ", 0),
      0u);
  EXPECT_EQ(error_of({{"gain", "1"}}), "options.gain: expected a number, got string \"1\"");
  EXPECT_EQ(error_of({{"gain", 1.0}, {"count", -2}}),
            "options.count: expected a non-negative whole number, got number -2");
  EXPECT_EQ(error_of({{"gain", 1.0}, {"enabled", 1}}),
            "options.enabled: expected true or false, got number 1");
  EXPECT_EQ(error_of({{"gain", 1.0}, {"sizes", {1, 0.5}}}),
            "options.sizes[1]: expected a non-negative whole number, got number 0.5");
  EXPECT_EQ(error_of({{"gain", 1.0}, {"colour", "blue"}}),
            "options.colour: unknown colour 'blue' (expected red or green)");
  EXPECT_EQ(error_of({{"gain", 1.0}, {"starts", {{{"x", 1.0}}}}}),
            "options.starts[0].y: missing field");
  EXPECT_EQ(error_of({{"gain", 1.0}, {"starts", 3}}),
            "options.starts: expected an array of objects, got number 3");
}

// Every field a model file of a registered model holds is in its entry's schema, and every field
// the schema requires is in the file: the file and the schema come from one description.
TEST(FieldTable, EveryModelFileFollowsItsSchema) {
  for (const auto& entry : ModelRegistry::builtin().entries()) {
    SCOPED_TRACE(entry.name);
    const auto file = model_to_json(*entry.create(entry.example_params, nullptr));
    std::set<std::string> documented;
    for (const auto& info : entry.parameters)
      documented.insert(info.name);
    for (const auto& [name, value] : file.at("params").items())
      EXPECT_TRUE(documented.count(name)) << name << " is written but not documented";
  }
}

// Every fit option an entry documents is read by its fitter: setting it to its documented default
// is never "unknown field". The fits are not run (an invalid record stops them first).
TEST(FieldTable, EveryDocumentedFitOptionIsAccepted) {
  const std::vector<double> one_sample{0.0};
  for (const auto& entry : ModelRegistry::builtin().entries()) {
    if (!entry.can_fit()) continue;
    for (const auto& option : entry.fit_options) {
      SCOPED_TRACE(entry.name + "." + option.name);
      if (option.default_value.empty()) continue;
      FitRequest request;
      request.input = one_sample;
      request.output = one_sample;
      const bool is_text = option.type == "string";
      request.options[option.name] = is_text ? nlohmann::json(option.default_value)
                                             : nlohmann::json::parse(option.default_value);
      try {
        entry.fit(request);
        ADD_FAILURE() << "a one-sample record was fitted";
      } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()).find("unknown field"), std::string::npos)
            << error.what();
        EXPECT_EQ(std::string(error.what()).find("fit options"), std::string::npos) << error.what();
      }
    }
  }
}

TEST(FieldTable, GpiBoundsAndStartsAreFitOptions) {
  const auto& gpi = ModelRegistry::builtin().find("gpi");
  const auto error_of_options = [&](const nlohmann::json& options) {
    std::vector<double> input, output;
    for (int k = 0; k < 200; ++k) {
      input.push_back(std::sin(0.1 * k));
      output.push_back(std::tanh(2.0 * input.back()));
    }
    FitRequest request;
    request.input = input;
    request.output = output;
    request.options = options;
    try {
      gpi.fit(request);
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(
      error_of_options({{"lower", {{"a9", 1.0}}}}).rfind("fit options.lower.a9: unknown field", 0),
      0u);
  EXPECT_EQ(error_of_options({{"starts", {{{"a0", 1.0}}}}}),
            "fit options.starts[0].a1: missing field");
  EXPECT_NE(error_of_options({{"lower", {{"a1", 2.0}}}, {"upper", {{"a1", 1.0}}}}).find("a1"),
            std::string::npos);
  // A start outside given bounds is refused: the start and the bounds reach the fitter.
  nlohmann::json start;
  for (const char* name : {"a0", "a1", "a2", "a3", "b0", "b1", "b2", "b3", "rho", "tau", "alpha"})
    start[name] = 0.5;
  EXPECT_EQ(error_of_options({{"starts", {start}}, {"upper", {{"tau", 0.25}}}})
                .rfind("GPI fit start 0: ", 0),
            0u);
}

// Fields that exist for one kind only: the GPI's density parameters.
TEST(FieldTable, FieldsOfOneKindOnly) {
  const auto& gpi = ModelRegistry::builtin().find("gpi");
  const auto error_of_params = [&](const nlohmann::json& params) {
    try {
      gpi.create(params, nullptr);
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  auto params = gpi.example_params;
  EXPECT_EQ(error_of_params(params), "no error");
  params["thresholds"] = {0.0, 0.5};
  EXPECT_EQ(error_of_params(params), "params.thresholds: not used with the exponential density");
  params.erase("thresholds");
  params.erase("rho");
  EXPECT_EQ(error_of_params(params), "params.rho: missing field");

  // The free density: rho & co. are neither needed nor written.
  auto free_params = gpi.example_params;
  for (const char* name : {"rho", "tau", "alpha", "m"})
    free_params.erase(name);
  free_params["density"] = "free";
  free_params["thresholds"] = {0.0, 0.3, 0.6};
  free_params["weights"] = {0.5, 0.3, 0.2};
  const auto file = model_to_json(*gpi.create(free_params, nullptr));
  EXPECT_FALSE(file.at("params").contains("rho"));
  EXPECT_EQ(file.at("params").at("weights").size(), 3u);
}

// Every fitter with a choice of start names it initial_state; "periodic" means the same in each.
TEST(FieldTable, OneInitialStateVocabulary) {
  for (const auto* name : {"pi", "modified_pi", "gpi", "jiles_atherton", "preisach"}) {
    SCOPED_TRACE(name);
    const auto& entry = ModelRegistry::builtin().find(name);
    bool found = false;
    for (const auto& option : entry.fit_options)
      found = found || option.name == "initial_state";
    EXPECT_TRUE(found);
  }
  const auto& ja = ModelRegistry::builtin().find("jiles_atherton");
  const std::vector<double> samples(20, 0.0);
  FitRequest request;
  request.input = samples;
  request.output = samples;
  request.options = {{"initial_state", "virgin"}};
  try {
    ja.fit(request);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "fit options.initial_state: unknown initial state 'virgin' (expected "
                 "demagnetised or periodic)");
  }
}

}  // namespace
}  // namespace hyst
