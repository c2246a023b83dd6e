// hyst info: what a model file holds - the model, its parameters and state, whether it has an
// inverse, and the fit report that produced it.

#include <memory>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/registry/model_file.hpp"

namespace hyst::cli {
namespace {

struct InfoOptions {
  std::string file;
  bool json = false;
};

void run(const InfoOptions& options) {
  const auto model = load_model(options.file);
  // The "info" object is not part of the model; load_model() checked it is an object if present.
  const auto document = io::parse_json_text(io::read_file(options.file), options.file);
  const auto info = document.contains("info") ? document.at("info") : nlohmann::json();

  if (options.json) {
    nlohmann::json out = {{"file", options.file},
                          {"model", std::string(model->name())},
                          {"params", model->params()},
                          {"state", model->state()},
                          {"parameter_count", model->parameter_count()},
                          {"has_inverse", model->has_inverse()}};
    if (!info.is_null()) out["info"] = info;
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("file:       {}\n", options.file);
  fmt::print("model:      {}\n", model->name());
  fmt::print("parameters: {} free\n", model->parameter_count());
  fmt::print("inverse:    {}\n", model->has_inverse() ? "yes" : "no");
  fmt::print("state:      {}\n\n", model->state().dump());
  fmt::print("{}", model->describe());
  if (!info.is_null()) fmt::print("\ninfo (how the file was made):\n{}\n", info.dump(2));
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto options = std::make_shared<InfoOptions>();
  auto* command =
      app.add_subcommand("info", "Show a model file: model, parameters, state, fit report.");
  command->add_option("file", options->file, "Model file (JSON)")->required();
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command->footer(R"(Example:
  hyst info m.json
      the model and its parameters, its state, whether it has an inverse, and the
      "info" object (for files written by 'hyst fit': the fit report).)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
