// Uses the installed hyst::hyst: a PI model built from a model-file document through the model
// registry, checked against hand-computed play operator outputs.
#include <cmath>
#include <cstdio>
#include <vector>

#include <nlohmann/json.hpp>

#include <hyst/registry/model_file.hpp>
#include <hyst/registry/model_registry.hpp>

int main() {
  // y = 1.0 * v + 0.5 * w, with w the play of half-width 0.5 started at 0:
  //   v  0    1     0     -1     0.5
  //   w  0    0.5   0.5   -0.5   0
  //   y  0    1.25  0.25  -1.25  0.5
  const auto document = nlohmann::json::parse(R"({"model": "pi", "version": 1,
      "params": {"thresholds": [0, 0.5], "weights": [1.0, 0.5], "offset": 0}})");
  const auto model = hyst::model_from_json(document, "consumer");
  const std::vector<double> input{0.0, 1.0, 0.0, -1.0, 0.5};
  const std::vector<double> expected_output{0.0, 1.25, 0.25, -1.25, 0.5};
  std::vector<double> output(input.size());
  model->simulate(input, output);

  double worst = 0;
  for (std::size_t k = 0; k < input.size(); ++k) {
    worst = std::fmax(worst, std::fabs(output[k] - expected_output[k]));
  }
  std::printf("hyst::hyst: models %s; PI model from its file, largest error %.3g\n",
              hyst::ModelRegistry::builtin().names().c_str(), worst);
  return worst < 1e-12 ? 0 : 1;
}
