// hyst info: what a model file holds - the model, its parameters and state, whether it has an
// inverse, and the fit report that produced it.

#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/registry/hysteretic_lfr_file.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/state_space_file.hpp"

namespace hyst::cli {
namespace {

struct InfoOptions {
  std::string file;
  bool json = false;
};

//! The parameters of a state-space model as its fit counts them: A by its order (its
//! eigenvalues), the entries of B, C and D.
std::size_t state_space_parameters(const StateSpace& model) {
  const auto& p = model.params();
  return std::size_t(p.a.rows() + p.b.size() + p.c.size() + p.d.size());
}

//! A linear state-space model file (hyst/registry/state_space_file.hpp): sizes, poles, stability.
void show_state_space(const InfoOptions& options, const nlohmann::json& document) {
  const auto file = state_space_from_json(document, options.file);
  const auto& model = file.model;
  const auto info = document.contains("info") ? document.at("info") : nlohmann::json();
  if (options.json) {
    nlohmann::json out = {{"file", options.file},
                          {"model", "state_space"},
                          {"order", model.order()},
                          {"inputs", model.inputs()},
                          {"outputs", model.outputs()},
                          {"parameters", state_space_parameters(model)},
                          {"sample_time", model.sample_time()},
                          {"spectral_radius", model.spectral_radius()},
                          {"stable", model.is_stable()}};
    if (!info.is_null()) out["info"] = info;
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("file:        {}\n", options.file);
  fmt::print("model:       state_space (linear, discrete time)\n");
  fmt::print("size:        {} states, {} inputs, {} outputs\n", model.order(), model.inputs(),
             model.outputs());
  fmt::print(
      "parameters:  {} (A by its {} eigenvalues, a change of state coordinates changes its "
      "entries, not the model; B, C and D)\n",
      state_space_parameters(model), model.order());
  fmt::print("sample time: {:g} s\n", model.sample_time());
  fmt::print("poles:       largest magnitude {:.6g} ({})\n", model.spectral_radius(),
             model.is_stable() ? "stable" : "not stable");
  if (!info.is_null()) fmt::print("\ninfo (how the file was made):\n{}\n", info.dump(2));
}

//! A hysteretic LFR model file (hyst/registry/hysteretic_lfr_file.hpp): sizes, the feedback, the
//! linear block's poles.
void show_hysteretic_lfr(const InfoOptions& options, const nlohmann::json& document) {
  const auto file = hysteretic_lfr_from_json(document, options.file);
  const auto& model = file.model;
  const auto& linear = model.linear();
  // What the fit counted (info.fit.parameters): the parameters it did not hold fixed.
  std::optional<std::size_t> fitted;
  if (const auto fit = file.info.find("fit"); fit != file.info.end() && fit->is_object()) {
    if (const auto count = fit->find("parameters");
        count != fit->end() && count->is_number_unsigned())
      fitted = count->get<std::size_t>();
  }
  if (options.json) {
    nlohmann::json out = {{"file", options.file},
                          {"model", "hysteretic_lfr"},
                          {"order", model.order()},
                          {"inputs", model.inputs()},
                          {"outputs", model.outputs()},
                          {"feedback_model", model.feedback_model()},
                          {"feedback_channels", model.feedback_channels()},
                          {"parameters", model.parameter_count()},
                          {"feedback_parameters", model.feedback_parameter_count()},
                          {"sample_time", model.sample_time()},
                          {"linear_spectral_radius", linear.spectral_radius()}};
    if (fitted) out["fitted_parameters"] = *fitted;
    if (!file.info.empty()) out["info"] = file.info;
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("file:        {}\n", options.file);
  fmt::print("model:       hysteretic_lfr (linear block with hysteresis in feedback)\n");
  fmt::print("size:        {} states, {} inputs, {} outputs\n", model.order(), model.inputs(),
             model.outputs());
  fmt::print(
      "parameters:  {} (A by its {} eigenvalues, a change of state coordinates changes its "
      "entries, not the model; B, C and D without the zero Dzw block; the channels' {})\n",
      model.parameter_count(), model.order(), model.feedback_parameter_count());
  if (fitted) {
    fmt::print("fitted:      {} (info.fit.parameters: the fit held the others fixed)\n", *fitted);
  }
  fmt::print("feedback:    {} '{}' channels\n", model.feedback_channels(), model.feedback_model());
  fmt::print("sample time: {:g} s\n", model.sample_time());
  fmt::print("linear poles: largest magnitude {:.6g} (without the feedback)\n",
             linear.spectral_radius());
  if (!file.info.empty()) fmt::print("\ninfo (how the file was made):\n{}\n", file.info.dump(2));
}

void run(const InfoOptions& options) {
  const auto document = io::parse_json_text(io::read_file(options.file), options.file);
  if (document.is_object() && document.contains("model") && document.at("model") == "state_space")
    return show_state_space(options, document);
  if (document.is_object() && document.contains("model") &&
      document.at("model") == "hysteretic_lfr")
    return show_hysteretic_lfr(options, document);
  const auto model = load_model(options.file);
  // The "info" object is not part of the model; load_model() checked it is an object if present.
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
      "info" object (for files written by 'hyst fit': the fit report). A state-space
      file (from 'hyst fit-system') shows its size, sample time and stability.)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
