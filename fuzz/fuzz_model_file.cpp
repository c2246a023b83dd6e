// Fuzz target: the model-file loader (hyst::load_model) for every model of the registry.
//
// The input is a model file. It is loaded as it is, and - when it is a JSON object - once more
// under the name of every registered model, so that each model's parameter and state validation
// sees every parameter set the fuzzer finds (models added to the registry are fuzzed without
// changes here). A model that loads must simulate a short signal to finite outputs and must
// survive a save -> load round trip with the same parameters and state.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>

#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "hyst/core/error.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"

namespace {

void exercise(const hyst::DynamicModel& loaded) {
  const auto model = loaded.clone();
  static constexpr std::array<double, 9> kInput = {0.0, 0.5, 1.0, -1.0, 2.0, -2.0, 0.25, 0.0, 1e3};
  std::array<double, kInput.size()> output{};
  try {
    model->simulate(kInput, output);
  } catch (const hyst::Error&) {
    return;  // e.g. an input outside the model's domain
  }
  for (const double value : output) {
    if (std::isnan(value)) std::abort();  // a validated model must not produce NaN
  }
  const auto document = hyst::model_to_json(*model);
  const auto reloaded = hyst::model_from_json(document, "round trip");
  if (reloaded->params() != model->params() || reloaded->state() != model->state()) std::abort();
  if (model->has_inverse()) {
    try {
      const auto inverse = model->inverse({-10.0, 10.0});
      std::array<double, kInput.size()> inputs{};
      static_cast<void>(inverse->invert(output, inputs));
      // Out-of-reach targets: answered within the limits by a bounded search, never a hang.
      static constexpr std::array<double, 2> kFar = {1e300, -1e300};
      std::array<double, kFar.size()> far{};
      static_cast<void>(inverse->invert(kFar, far));
      for (const double value : far) {
        if (!(value >= -10.0 && value <= 10.0)) std::abort();
      }
    } catch (const hyst::Error&) {
    }
  }
}

void load(const std::filesystem::path& path) {
  try {
    exercise(*hyst::load_model(path));
  } catch (const hyst::Error&) {
    // rejected with a message naming the file and the field
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = hyst::fuzz::as_text(data, size);
  load(hyst::fuzz::scratch_file("fuzz.json", text));

  const auto document = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!document.is_object()) return 0;
  for (const auto& entry : hyst::ModelRegistry::builtin().entries()) {
    auto renamed = document;
    renamed["model"] = entry.name;
    load(hyst::fuzz::scratch_file("renamed.json", renamed.dump()));
  }
  return 0;
}
