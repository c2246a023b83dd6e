// Example 08: from a raw instrument export to a fitted model.
//
// RMN_TRAP_SLOW.dat is the text export of an aixACCT ferroelectric analyser: a summary table and
// ten measurement tables, each one period of a triangular voltage on a piezoceramic with the
// polarisation P1 [uC/cm2] and displacement D1 [nm]. This example reads table 6 (1400 V, 1 Hz),
// finds the reversal points and cycles of the voltage, computes the P(V) loop's figures and
// compares them with the ones the instrument computed itself (in the table's metadata), then fits
// a Prandtl-Ishlinskii model to the loop after removing the polarisation drift (the loop does not
// close) and resampling each branch on a uniform voltage grid.
// The data are found in $HYST_SHARED_DATA_DIR or next to the repository (../shared/data).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "hyst/data/cycles.hpp"
#include "hyst/data/loop_metrics.hpp"
#include "hyst/data/reversal_points.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/registry/model_registry.hpp"

namespace fs = std::filesystem;

int main() {
  const char* env = std::getenv("HYST_SHARED_DATA_DIR");
  const fs::path data =
      env ? fs::path(env) : fs::path(__FILE__).parent_path() / "../../shared/data";
  const auto file =
      hyst::io::read_aixacct(data / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat");
  const auto& table = file.measurement(6);
  const auto& voltage = table.column("V+").values;
  const auto& polarisation = table.column("P1").values;
  std::printf("%s, table %zu (%s): %zu samples, columns", file.kind.c_str(), table.number,
              table.metadata_text("SampleName").value_or("?").c_str(), table.rows());
  for (const auto& column : table.columns)
    std::printf(" %s", column.header().c_str());
  std::printf("\n");

  // Turning points of the voltage, ignoring wiggles below 2 % of its range.
  const double band = hyst::data::default_band(voltage);
  for (const auto& point : hyst::data::reversal_points(voltage, band)) {
    std::printf("reversal: %s %.1f V at sample %zu\n", std::string(to_string(point.kind)).c_str(),
                point.value, point.index);
  }
  const auto cycles = hyst::data::cycles(voltage, band);
  std::printf("cycles: %zu\n", cycles.size());

  // The loop's figures, next to the instrument's own.
  const auto loop = hyst::data::loop_metrics(voltage, polarisation, 0, voltage.size() - 1);
  const auto instrument = [&](const char* key) { return table.metadata_number(key).value_or(NAN); };
  std::printf("loop area %.1f uJ/cm2 (instrument Wloss %.1f)\n", loop.area,
              instrument("Wloss [uJ/cm2]"));
  std::printf("coercive voltages %.2f / %.2f V (instrument Vc+ %.2f, Vc- %.2f)\n",
              loop.coercive.front().value, loop.coercive.back().value, instrument("Vc+ [V]"),
              instrument("Vc- [V]"));
  std::printf("remanent polarisation %.4f uC/cm2 (instrument Pr+ %.4f)\n",
              loop.remanent.front().value, instrument("Pr+ [uC/cm2]"));
  std::printf("loop closure error %.3f uC/cm2 (drift over the period)\n", loop.closure_error);

  // Fit with the preparation of the record listed in the report.
  hyst::FitRequest request;
  request.input = voltage;
  request.output = polarisation;
  request.options = {{"operators", 12}, {"initial_state", "periodic"}};
  request.preprocessing.detrend = true;
  request.preprocessing.resample = hyst::data::ResampleMethod::input_grid;
  const auto& entry = hyst::ModelRegistry::builtin().find("pi");
  const auto outcome = hyst::fit_model(entry, request);
  std::printf("\n%s\n", outcome.report.brief().c_str());

  const bool figures_agree =
      std::abs(loop.area - instrument("Wloss [uJ/cm2]")) < 1e-4 * loop.area &&
      std::abs(loop.coercive.front().value - instrument("Vc+ [V]")) < 0.01;
  const bool ok = cycles.size() == 1 && figures_agree &&
                  outcome.report.termination == hyst::Termination::converged &&
                  outcome.report.preprocessing.size() == 2 && outcome.report.fit.nrmse_percent < 5;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
