// Example 02: fit a Prandtl-Ishlinskii model to a measured piezo loop read from a MATLAB file, and
// predict the loops measured at the other amplitudes.
//
// Each record of MeasurementData.mat (voltage [V] -> displacement [nm]) is one period of a
// triangular excitation in steady state: the fit and every prediction start from the periodic
// state, not the virgin one. The fit uses the 1.5 kV loop, the largest one without polarisation
// switching (the 1.9 kV loop rises again near -1.9 kV, which a monotone PI model cannot follow).
// Each record was zeroed at its first sample, so each prediction is zeroed there too.
// The data are found in $HYST_SHARED_DATA_DIR or next to the repository (../shared/data).

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/io/mat_file.hpp"

namespace fs = std::filesystem;

int main() {
  const char* env = std::getenv("HYST_SHARED_DATA_DIR");
  const fs::path data =
      env ? fs::path(env) : fs::path(__FILE__).parent_path() / "../../shared/data";
  const fs::path file = data / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat";
  const auto read = [&](const std::string& name) { return hyst::io::read_mat_vector(file, name); };

  // Fit: NNLS for the weights of 10 plays with uniform thresholds up to half the input range.
  const auto voltage = read("Vplus_15kv");
  const auto displacement = read("Displacement_15kv");
  const hyst::PiFit fit = hyst::fit_prandtl_ishlinskii(
      voltage, displacement,
      {.operators = 10, .initial_state = hyst::PiFitOptions::InitialState::periodic});
  std::printf("%s\n\n", fit.report.brief().c_str());

  std::printf("| record | part | RMSE [nm] | NRMSE | max error [nm] |\n|---|---|---|---|---|\n");
  const auto row = [](const char* record, const char* part, const hyst::ErrorMetrics& m) {
    std::printf("| %s | %s | %.1f | %.2f %% | %.1f |\n", record, part, m.rmse, m.nrmse_percent,
                m.max_error);
  };
  row("15kv", "fit", fit.report.fit);

  // Predict: the periodic state of each record's own input, then zero at the first sample.
  for (const char* record : {"08kv", "1kv", "11kv", "19kv"}) {
    const auto v = read(std::string("Vplus_") + record);
    const auto measured = read(std::string("Displacement_") + record);
    auto state = hyst::pi_periodic_state(fit.model, v);
    auto predicted = hyst::simulate(fit.model, state, std::span<const double>(v));
    const double first = predicted.front();
    for (double& y : predicted)
      y -= first;
    row(record, "validation", hyst::error_metrics(measured, predicted));
  }
  const bool ok =
      fit.report.termination == hyst::Termination::converged && fit.model.is_invertible();
  return ok ? 0 : 1;
}
