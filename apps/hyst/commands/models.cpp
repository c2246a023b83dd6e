// hyst models [NAME] [--json]: the registered models, or one model's schema.

#include <memory>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst::cli {
namespace {

struct ModelsOptions {
  std::string name;
  bool json = false;
};

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
      fmt::print("{}\n", list.dump(2));
      return;
    }
    std::size_t width = 5;
    for (const auto& entry : registry.entries())
      width = std::max(width, entry.name.size());
    fmt::print("{:<{}}  {:<3}  {:<6}  {}\n", "model", width, "fit", "invert", "description");
    for (const auto& entry : registry.entries()) {
      fmt::print("{:<{}}  {:<3}  {:<6}  {}\n", entry.name, width, entry.can_fit() ? "yes" : "no",
                 example_has_inverse(entry) ? "yes" : "no", entry.description);
    }
    fmt::print("\n'hyst models NAME' shows a model's parameters, fit options and an example.\n");
    return;
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
  hyst models pi --json > pi.json   its schema as JSON; the "example" member is a model file)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
