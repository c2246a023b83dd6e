// hyst models [NAME] [--json]: the registered models and the dynamic multi-input models (state
// space, hysteretic LFR: files of their own form), or one model's schema and example file.

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "hyst/core/error.hpp"
#include "hyst/registry/hysteretic_lfr_file.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/registry/state_space_file.hpp"

namespace hyst::cli {
namespace {

struct ModelsOptions {
  std::string name;
  bool json = false;
};

//! A model a file can hold that is not a registry entry: a dynamic multi-input model with a file
//! format of its own (hyst/registry/state_space_file.hpp, hysteretic_lfr_file.hpp), fitted by
//! `hyst fit-system` and scored by `hyst evaluate`.
struct DynamicModelInfo {
  std::string name;
  std::string description;
  std::vector<ParameterInfo> parameters;  //!< the "params" object
  std::vector<ParameterInfo> state;       //!< the "state" object ({} when it has none)
  std::string fit;                        //!< how to fit one
  nlohmann::json example;                 //!< a small complete model file
};

//! The names of the models a hysteretic LFR's feedback can hold (those with an actuator force).
std::string feedback_model_names() {
  std::string names;
  for (const auto& entry : ModelRegistry::builtin().entries())
    if (entry.actuator_force) names += (names.empty() ? "" : ", ") + entry.name;
  return names;
}

//! The dynamic models; each example is read by its own file reader and written again, so that it
//! is a valid file in the form the writer gives.
const std::vector<DynamicModelInfo>& dynamic_models() {
  static const std::vector<DynamicModelInfo> models = [] {
    const auto state_space_example = nlohmann::json::parse(R"({"model": "state_space",
        "version": 1, "params": {"sample_time": 0.01, "a": [[0.8]], "b": [[1.0]], "c": [[1.0]],
        "d": [[0.0]]}, "state": {"x": [0.0]}})");
    const auto state_space = state_space_from_json(state_space_example, "example");
    const auto lfr_example = nlohmann::json::parse(R"({"model": "hysteretic_lfr", "version": 1,
        "params": {"inputs": 1,
                   "linear": {"sample_time": 0.01, "a": [[0.9]], "b": [[0.5, -0.3]],
                              "c": [[1.2], [0.8]], "d": [[0.1, 0.25], [0.4, 0.0]]},
                   "feedback": [{"model": "pi", "params": {"thresholds": [0, 0.1],
                                                           "weights": [0.5, 0.3]}}]}})");
    const std::string matrix = "array of rows of numbers";
    return std::vector<DynamicModelInfo>{
        {"state_space",
         "Linear discrete-time state-space model, m inputs, p outputs, n states: x[k+1] = A x[k] "
         "+ B u[k], y[k] = C x[k] + D u[k]",
         {{"sample_time", "number", "s", "sample time Ts, finite and > 0", ""},
          {"a", matrix, "", "A, n x n (no rows when n = 0)", ""},
          {"b", matrix, "", "B, n x m (no rows when n = 0)", ""},
          {"c", matrix, "", "C, p x n (p empty rows when n = 0)", ""},
          {"d", matrix, "", "D, p x m (gives m and p)", ""}},
         {{"x", "array of numbers", "",
           "the state, n values (the whole \"state\" may be left "
           "out: zero)",
           ""}},
         "hyst fit-system --model state_space --order N --sample-time TS ...",
         state_space_to_json(state_space.model, state_space.state)},
        {"hysteretic_lfr",
         "Linear state-space block with hysteresis in feedback (inputs u, w; outputs y, z; w_i = "
         "H_i(z_i)); a Hammerstein system (fit-system --model hammerstein) is written as one",
         {{"inputs", "integer", "", "m, the number of inputs u", ""},
          {"linear", "object", "",
           "the \"params\" of a state_space file with the inputs ordered (u, w) and the outputs "
           "(y, z); D from w to z must be 0",
           ""},
          {"feedback", "array of objects", "",
           "one {\"model\": name, \"params\": {...}} per hysteresis channel, all of one kind "
           "among: " +
               feedback_model_names(),
           ""}},
         {},
         "hyst fit-system --model hysteretic_lfr (or hammerstein) [--linear lin.json] ...",
         hysteretic_lfr_to_json(hysteretic_lfr_from_json(lfr_example, "example").model)},
    };
  }();
  return models;
}

const DynamicModelInfo* find_dynamic_model(const std::string& name) {
  for (const auto& model : dynamic_models())
    if (model.name == name) return &model;
  return nullptr;
}

//! The example of an entry as a complete model file (params and initial state).
nlohmann::json example_model_file(const ModelEntry& entry) {
  return model_to_json(*entry.create(entry.example_params, nullptr));
}

//! Whether the entry's example parameter set has an inverse.
bool example_has_inverse(const ModelEntry& entry) {
  return entry.create(entry.example_params, nullptr)->has_inverse();
}

nlohmann::json schema_json(const std::vector<ParameterInfo>& parameters) {
  auto list = nlohmann::json::array();
  for (const auto& p : parameters) {
    nlohmann::json field = {
        {"name", p.name}, {"type", p.type}, {"unit", p.unit}, {"description", p.description}};
    if (!p.default_value.empty()) field["default"] = p.default_value;
    list.push_back(std::move(field));
  }
  return list;
}

nlohmann::json dynamic_json(const DynamicModelInfo& model, bool with_schema) {
  nlohmann::json json = {{"name", model.name},  {"description", model.description},
                         {"kind", "dynamic"},   {"can_fit", true},
                         {"can_invert", false}, {"fit", model.fit}};
  if (with_schema) {
    json["parameters"] = schema_json(model.parameters);
    json["state"] = schema_json(model.state);
    json["example"] = model.example;
  }
  return json;
}

nlohmann::json entry_json(const ModelEntry& entry, bool with_schema) {
  nlohmann::json json = {{"name", entry.name},
                         {"description", entry.description},
                         {"can_fit", entry.can_fit()},
                         {"can_invert", example_has_inverse(entry)}};
  if (with_schema) {
    json["parameters"] = schema_json(entry.parameters);
    json["fit_options"] = schema_json(entry.fit_options);
    json["example"] = example_model_file(entry);
    if (!entry.input_unit.empty()) json["input_unit"] = entry.input_unit;
    if (!entry.output_unit.empty()) json["output_unit"] = entry.output_unit;
  }
  return json;
}

void print_schema_table(const std::vector<ParameterInfo>& parameters) {
  std::size_t width = 4;
  for (const auto& p : parameters)
    width = std::max(width, p.name.size());
  for (const auto& p : parameters) {
    fmt::print("  {:<{}}  {}{}: {}{}\n", p.name, width, p.type,
               p.unit.empty() ? "" : fmt::format(" [{}]", p.unit), p.description,
               p.default_value.empty() ? "" : fmt::format(" (default {})", p.default_value));
  }
}

void run(const ModelsOptions& options) {
  const auto& registry = ModelRegistry::builtin();
  if (options.name.empty()) {
    if (options.json) {
      auto list = nlohmann::json::array();
      for (const auto& entry : registry.entries())
        list.push_back(entry_json(entry, false));
      for (const auto& model : dynamic_models())
        list.push_back(dynamic_json(model, false));
      fmt::print("{}\n", list.dump(2));
      return;
    }
    std::size_t width = 5;
    for (const auto& entry : registry.entries())
      width = std::max(width, entry.name.size());
    for (const auto& model : dynamic_models())
      width = std::max(width, model.name.size());
    fmt::print("{:<{}}  {:<3}  {:<6}  {}\n", "model", width, "fit", "invert", "description");
    for (const auto& entry : registry.entries()) {
      fmt::print("{:<{}}  {:<3}  {:<6}  {}\n", entry.name, width, entry.can_fit() ? "yes" : "no",
                 example_has_inverse(entry) ? "yes" : "no", entry.description);
    }
    fmt::print(
        "\nDynamic multi-input models, in files of their own form (fitted by hyst fit-system, "
        "scored by hyst evaluate):\n");
    fmt::print("{:<{}}  {:<3}  {:<6}  {}\n", "model", width, "fit", "invert", "description");
    for (const auto& model : dynamic_models())
      fmt::print("{:<{}}  {:<3}  {:<6}  {}\n", model.name, width, "yes", "no", model.description);
    fmt::print(
        "\n'hyst models NAME' shows a model's parameters, fit options (or file format) and an "
        "example.\n");
    return;
  }

  if (const auto* model = find_dynamic_model(options.name)) {
    if (options.json) {
      fmt::print("{}\n", dynamic_json(*model, true).dump(2));
      return;
    }
    fmt::print("{}: {}\n", model->name, model->description);
    fmt::print("a dynamic multi-input model in a file of its own form; fit: {}; inverse: no\n\n",
               model->fit);
    fmt::print("parameters (the \"params\" object of a model file):\n");
    print_schema_table(model->parameters);
    if (!model->state.empty()) {
      fmt::print("\nstate (the \"state\" object, optional):\n");
      print_schema_table(model->state);
    }
    fmt::print("\nexample model file:\n{}\n", model->example.dump(2));
    return;
  }
  bool known = false;
  for (const auto& entry : registry.entries())
    known = known || entry.name == options.name;
  if (!known) {
    std::string names = registry.names();
    for (const auto& model : dynamic_models())
      names += ", " + model.name;
    throw Error(fmt::format("unknown model '{}' (known: {})", options.name, names));
  }
  const auto& entry = registry.find(options.name);
  if (options.json) {
    fmt::print("{}\n", entry_json(entry, true).dump(2));
    return;
  }
  fmt::print("{}: {}\n", entry.name, entry.description);
  fmt::print("can fit: {}; inverse (for the example parameters): {}\n\n",
             entry.can_fit() ? "yes" : "no", example_has_inverse(entry) ? "yes" : "no");
  if (!entry.input_unit.empty() || !entry.output_unit.empty()) {
    fmt::print(
        "units: input in {}, output in {} ('hyst fit' refuses data whose file states others; "
        "--units-intended)\n\n",
        entry.input_unit.empty() ? "any unit" : entry.input_unit,
        entry.output_unit.empty() ? "any unit" : entry.output_unit);
  }
  fmt::print("parameters (the \"params\" object of a model file):\n");
  print_schema_table(entry.parameters);
  if (entry.can_fit()) {
    fmt::print("\nfit options (hyst fit {} --option key=value, or --options JSON):\n", entry.name);
    print_schema_table(entry.fit_options);
  }
  fmt::print("\nexample model file:\n{}\n", example_model_file(entry).dump(2));
}

}  // namespace

void add_models_command(CLI::App& app) {
  auto options = std::make_shared<ModelsOptions>();
  auto* command = app.add_subcommand(
      "models", "List the registered models, or show one model's parameters and fit options.");
  command->add_option("name", options->name,
                      "A model name: show its parameter schema, fit options and an example "
                      "model file");
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command->footer(R"(Examples:
  hyst models                       every model, whether it can be fitted and inverted
  hyst models pi                    the PI model's parameters, fit options, example file
  hyst models pi --json > pi.json   its schema as JSON; the "example" member is a model file
  hyst models state_space           the file format of a dynamic model (hyst fit-system))");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
