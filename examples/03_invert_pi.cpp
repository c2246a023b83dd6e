// Example 03: compensate hysteresis with the inverse model, through the model registry.
//
// A model file (here written by the example itself, as `hyst fit` would) is loaded at run time;
// its inverse starts in the state consistent with the model's, is limited to the actuator's
// admissible input, and reports targets it cannot reach instead of throwing.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "hyst/registry/model_file.hpp"
#include "hyst/signals/generators.hpp"

int main() {
  const auto path = std::filesystem::temp_directory_path() / "hyst_example_03.json";
  const auto document = nlohmann::json::parse(R"({
      "model": "pi", "version": 1,
      "params": {"thresholds": [0, 100, 200, 300, 400], "weights": [0.5, 0.3, 0.2, 0.1, 0.05],
                 "offset": 0}})");
  hyst::save_model(path, *hyst::model_from_json(document, "example"));
  auto model = hyst::load_model(path);
  std::filesystem::remove(path);

  // Desired output: a decaying oscillation, so every reversal lies inside the previous one.
  const auto desired = hyst::signals::generate(
      hyst::signals::TimeGrid{3000, 1e-3},
      hyst::signals::DecayingSine{.amplitude = 400, .frequency = 3, .time_constant = 0.8});

  // The actuator accepts -1000 .. 1000 V; the inverse saturates there and says so.
  auto inverse = model->inverse({.input_min = -1000, .input_max = 1000});
  std::vector<double> input(desired.size());
  const auto report = inverse->invert(desired, input);

  std::vector<double> output(input.size());
  model->simulate(input, output);
  double worst = 0;
  for (std::size_t k = 0; k < output.size(); ++k) {
    worst = std::max(worst, std::abs(output[k] - desired[k]));
  }
  std::printf("%s model, %zu samples: max |y - y_desired| = %.3g, saturated samples: %zu\n",
              std::string(model->name()).c_str(), output.size(), worst, report.saturated_samples);
  return report.ok() && worst < 1e-9 ? 0 : 1;
}
