// Example 15: butterfly strain loops through the polarisation. The measured 1.9 kV loop of a
// piezoceramic is fitted with the polarisation as a latent signal (voltage and displacement
// only) and predicts the 1.5 kV loop; where the polarisation is measured as well (aixACCT export,
// V+, P1, D1), the two-stage fit identifies P(v) and checks the strain-polarisation map on the
// measured P directly; the inverse compensates a unipolar drive and says "not_invertible" where
// the butterfly has no inverse.
//
// Run: ./build/examples/example_15_butterfly [folder of MeasurementData.mat and RMN_TRAP_SLOW.dat]

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/error_metrics.hpp"
#include "hyst/identify/fit_butterfly_strain.hpp"
#include "hyst/inverse/inverse_butterfly_strain.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/io/mat_file.hpp"

namespace {

// The prediction of a record from its periodic steady state, zeroed at its first sample as the
// measured displacement is.
std::vector<double> predict_zeroed(const hyst::ButterflyStrain& model,
                                   const std::vector<double>& input) {
  auto state = model.periodic_state(input);
  auto y = hyst::simulate(model, state, std::span<const double>(input));
  const double first = y.front();
  for (double& value : y)
    value -= first;
  return y;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path folder =
      argc > 1 ? argv[1] : "../shared/data/piezo_pzt_aixacct_butterfly";
  const auto mat = folder / "MeasurementData.mat";

  // 1. The 1.9 kV loop: voltage and displacement only, the polarisation latent (16 levels).
  const auto v19 = hyst::io::read_mat_vector(mat, "Vplus_19kv");
  const auto y19 = hyst::io::read_mat_vector(mat, "Displacement_19kv");
  const auto fit = hyst::fit_butterfly_strain(v19, y19);
  const auto& p = fit.model.params();
  std::printf("1.9 kV loop: %s\n", fit.report.brief().c_str());
  std::printf("  map: y = %.4g + %.4g v + %.4g P + %.4g P^2 (P latent, in [-1, 1])\n", p.offset,
              p.field_coefficient, p.polarisation_coefficients[0], p.polarisation_coefficients[1]);

  // 2. The same model predicts the 1.5 kV loop it never saw.
  const auto v15 = hyst::io::read_mat_vector(mat, "Vplus_15kv");
  const auto y15 = hyst::io::read_mat_vector(mat, "Displacement_15kv");
  const auto predicted = predict_zeroed(fit.model, v15);
  std::printf("1.5 kV loop predicted from the 1.9 kV fit: NRMSE %.2f %%\n",
              hyst::error_metrics(y15, predicted).nrmse_percent);

  // 3. Measured polarisation: one triangle of the aixACCT export at 1 Hz (table 6).
  const auto export_file = hyst::io::read_aixacct(folder / "RMN_TRAP_SLOW.dat");
  const auto& table = export_file.measurement(6);
  const auto& v = table.column("V+").values;
  const auto& P = table.column("P1").values;
  const auto& d = table.column("D1").values;
  const auto two_stage = hyst::fit_butterfly_strain_with_polarisation(v, P, d);
  std::printf("aixACCT table 6 (1 Hz, 1400 V), two stages:\n");
  std::printf("  P(v) by the Preisach model:          NRMSE %.2f %%\n",
              two_stage.polarisation_report.fit.nrmse_percent);
  std::printf("  D1 from the measured P1 by the map:  NRMSE %.2f %%\n",
              two_stage.map_report.fit.nrmse_percent);
  std::printf("  D1 from v through the model's P:     NRMSE %.2f %%\n",
              two_stage.fit.report.fit.nrmse_percent);

  // 4. Feedforward on a unipolar drive below the coercive voltage: the 1.9 kV model, started in
  //    its periodic state, driven between 200 and 800 V. (Below about 120 V its polarisation
  //    passes the butterfly's vertex: the strain dips before it rises, as the measured branch
  //    does at negative voltages, and a range reaching there has no inverse.)
  hyst::InverseButterflyStrain unipolar(fit.model, {.input_min = 200.0, .input_max = 800.0});
  std::vector<double> drive;
  for (int k = 0; k <= 200; ++k)
    drive.push_back(500.0 + 290.0 * std::sin(0.05 * k));
  auto forward = fit.initial_state;
  const auto targets = hyst::simulate(fit.model, forward, std::span<const double>(drive));
  auto state = fit.initial_state;
  std::vector<double> inputs(targets.size());
  const auto report = hyst::invert(unipolar, state, targets, inputs);
  auto check = fit.initial_state;
  const auto reached = hyst::simulate(fit.model, check, std::span<const double>(inputs));
  std::printf("inverse on [200, 800] V: %zu samples limited or not invertible, max error %.2e nm\n",
              report.saturated_samples, hyst::error_metrics(targets, reached).max_error);

  // Over the whole bipolar range the butterfly has no inverse: said, not guessed.
  hyst::InverseButterflyStrain bipolar(fit.model, {.input_min = -1900.0, .input_max = 1900.0});
  auto bipolar_state = fit.initial_state;
  const auto bipolar_report = hyst::invert(bipolar, bipolar_state, targets, inputs);
  std::printf("inverse on [-1900, 1900] V: %zu of %zu samples not invertible\n",
              bipolar_report.not_invertible_samples, targets.size());
  return report.saturated_samples == 0 && bipolar_report.not_invertible_samples > 0 ? 0 : 1;
}
