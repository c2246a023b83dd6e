// Example 11: from measured data to a compensator in plain C for a real-time controller.
//
// Fits a Prandtl-Ishlinskii model to the P(V) loop of a piezoceramic (aixACCT export, table 6 of
// RMN_TRAP_SLOW.dat, as in example 08), exports the model and its inverse as C99 code
// (hyst::export_c, the same as `hyst export --lang c`), compiles a tiny C program with gcc that
// compensates a desired polarisation trajectory sample by sample (inverse step -> voltage ->
// model step), and compares the C results with the library's inverse and model.
// The data are found in $HYST_SHARED_DATA_DIR or next to the repository (../shared/data); gcc
// must be on the PATH.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "hyst/export/export_c.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/registry/model_registry.hpp"

namespace fs = std::filesystem;

namespace {

// The controller: reads desired outputs, writes the inverse's input and the model's response.
constexpr const char* kProgram = R"(#include <stdio.h>
#include "piezo.h"
int main(void) {
  double desired;
  piezo_state model;
  piezo_inverse_state inverse;
  piezo_init(&model);
  piezo_inverse_init(&inverse);
  while (scanf("%lf", &desired) == 1) {
    const double voltage = piezo_inverse_step(&piezo_INVERSE_PARAMS, &inverse, desired);
    const double response = piezo_step(&piezo_PARAMS, &model, voltage);
    printf("%.17g %.17g\n", voltage, response);
  }
  return 0;
}
)";

}  // namespace

int main() {
  const char* env = std::getenv("HYST_SHARED_DATA_DIR");
  const fs::path data =
      env ? fs::path(env) : fs::path(__FILE__).parent_path() / "../../shared/data";
  const auto file =
      hyst::io::read_aixacct(data / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat");
  const auto& table = file.measurement(6);

  // 1. Fit (as example 08).
  hyst::FitRequest request;
  request.input = table.column("V+").values;
  request.output = table.column("P1").values;
  // A lower bound on p_0 keeps the inverse well conditioned (its first weight is 1 / p_0).
  request.options = {{"operators", 12}, {"initial_state", "periodic"}, {"min_linear_weight", 1e-3}};
  request.preprocessing.detrend = true;
  request.preprocessing.resample = hyst::data::ResampleMethod::input_grid;
  const auto outcome = hyst::fit_model(hyst::ModelRegistry::builtin().find("pi"), request);
  std::printf("%s\n", outcome.report.brief().c_str());
  const auto& model = *outcome.model;

  // 2. Export into a fresh folder.
  const fs::path folder = fs::temp_directory_path() / "hyst_example_11";
  fs::remove_all(folder);
  fs::create_directories(folder);
  hyst::CExportOptions options;
  options.prefix = "piezo";
  options.source = "RMN_TRAP_SLOW.dat table 6 (fitted)";
  const auto code = hyst::export_c(model, folder, options);
  std::printf("exported %s and %s\n", (folder / code.header_name).c_str(),
              (folder / code.source_name).c_str());

  // 3. A desired trajectory: two decaying sine periods inside 80 % of the measured range.
  double low = request.output.front();
  double high = low;
  for (const double p : request.output) {
    low = std::min(low, p);
    high = std::max(high, p);
  }
  std::vector<double> desired(2000);
  for (std::size_t k = 0; k < desired.size(); ++k) {
    const double phase = 2 * std::numbers::pi * static_cast<double>(k) / 1000.0;
    desired[k] = 0.5 * (low + high) +
                 0.4 * (high - low) * std::exp(-0.3 * phase / std::numbers::pi) * std::sin(phase);
  }
  {
    std::ofstream out(folder / "desired.txt");
    for (const double y : desired)
      out << std::to_string(y) << "\n";
  }
  // Read back what was written, so that the library sees exactly the C program's input.
  {
    std::ifstream in(folder / "desired.txt");
    for (double& y : desired)
      in >> y;
  }

  // 4. Compile and run the controller.
  std::ofstream(folder / "main.c") << kProgram;
  const std::string build = "cd '" + folder.string() +
                            "' && gcc -std=c99 -Wall -Wextra -Werror -pedantic -O2 -o controller "
                            "main.c piezo.c -lm && ./controller < desired.txt > compensated.txt";
  if (std::system(build.c_str()) != 0) {
    std::printf("building or running the C controller failed: %s\n", build.c_str());
    return EXIT_FAILURE;
  }
  std::vector<double> c_voltage(desired.size());
  std::vector<double> c_response(desired.size());
  {
    std::ifstream in(folder / "compensated.txt");
    for (std::size_t k = 0; k < desired.size(); ++k)
      in >> c_voltage[k] >> c_response[k];
  }

  // 5. The library on the same trajectory.
  std::vector<double> voltage(desired.size());
  std::vector<double> response(desired.size());
  model.inverse({})->invert(desired, voltage);
  model.clone()->simulate(voltage, response);
  double voltage_difference = 0.0;
  double response_difference = 0.0;
  double tracking_error = 0.0;
  for (std::size_t k = 0; k < desired.size(); ++k) {
    voltage_difference = std::max(voltage_difference, std::abs(c_voltage[k] - voltage[k]));
    response_difference = std::max(response_difference, std::abs(c_response[k] - response[k]));
    tracking_error = std::max(tracking_error, std::abs(c_response[k] - desired[k]));
  }
  std::printf(
      "C vs library: max |voltage difference| %.3g V, max |response difference| %.3g "
      "uC/cm2\n",
      voltage_difference, response_difference);
  std::printf(
      "C controller: max |model response - desired| %.3g uC/cm2 over %zu samples "
      "(range %.3g uC/cm2)\n",
      tracking_error, desired.size(), high - low);
  fs::remove_all(folder);
  // Rounding only: the sums run in another order in the library (vectorised) than in the C code.
  double voltage_low = request.input.front();
  double voltage_high = voltage_low;
  for (const double v : request.input) {
    voltage_low = std::min(voltage_low, v);
    voltage_high = std::max(voltage_high, v);
  }
  const double span = high - low;
  const bool ok = voltage_difference <= 1e-11 * (voltage_high - voltage_low) &&
                  response_difference <= 1e-11 * span && tracking_error <= 1e-11 * span;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
