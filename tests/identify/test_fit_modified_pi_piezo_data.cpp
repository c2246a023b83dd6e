// The modified PI fit on measured piezo loops (../shared/data/piezo_pzt_aixacct_butterfly),
// against the classical PI fitted the same way: fitted on the 1.5 kV record (one period in
// steady state), every other amplitude predicted from its own periodic state and zeroed at its
// first sample like the measurement. Prints the table of docs/results.md.

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_modified_prandtl_ishlinskii.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/io/mat_file.hpp"

namespace hyst {
namespace {

namespace fs = std::filesystem;

struct ModifiedPiRecord {
  std::string name;
  std::vector<double> voltage;
  std::vector<double> displacement;
};

std::vector<double> zeroed(std::vector<double> y) {
  const double first = y.front();
  for (double& value : y)
    value -= first;
  return y;
}

TEST(FitModifiedPiPiezoData, AsymmetricMapVersusClassicalPi) {
  const fs::path mat =
      fs::path(HYST_SHARED_DATA_DIR) / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat";
  if (!fs::exists(mat)) GTEST_SKIP() << mat << " not found";
  std::vector<ModifiedPiRecord> records;
  for (const std::string name : {"08kv", "1kv", "11kv", "15kv", "19kv"}) {
    records.push_back({name, io::read_mat_vector(mat, "Vplus_" + name),
                       io::read_mat_vector(mat, "Displacement_" + name)});
  }
  const ModifiedPiRecord& fitted = records[3];
  PiFitOptions pi_options;
  pi_options.operators = 10;
  pi_options.initial_state = PiFitOptions::InitialState::periodic;
  const auto pi = fit_prandtl_ishlinskii(fitted.voltage, fitted.displacement, pi_options);
  ModifiedPiFitOptions options;
  options.operators = 10;
  options.dead_zones = 3;
  options.initial_state = PiFitOptions::InitialState::periodic;
  const auto mpi = fit_modified_prandtl_ishlinskii(fitted.voltage, fitted.displacement, options);
  EXPECT_TRUE(mpi.model.is_invertible());

  std::printf("| record | part | PI NRMSE | modified PI NRMSE |\n|---|---|---:|---:|\n");
  std::vector<double> pi_errors, mpi_errors;
  for (const auto& record : records) {
    auto pi_state = pi_periodic_state(pi.model, record.voltage);
    const auto pi_prediction = zeroed(simulate(pi.model, pi_state, record.voltage));
    auto mpi_state =
        mpi.model.make_state(pi_periodic_state(mpi.model.hysteresis(), record.voltage).play);
    const auto mpi_prediction = zeroed(simulate(mpi.model, mpi_state, record.voltage));
    pi_errors.push_back(error_metrics(record.displacement, pi_prediction).nrmse_percent);
    mpi_errors.push_back(error_metrics(record.displacement, mpi_prediction).nrmse_percent);
    std::printf("| %s | %s | %.2f %% | %.2f %% |\n", record.name.c_str(),
                &record == &fitted ? "fit" : "validation", pi_errors.back(), mpi_errors.back());
  }
  std::printf("\nPI: %s\nmodified PI: %s\n", pi.report.brief().c_str(), mpi.report.brief().c_str());
  // The PI fit of docs/results.md (3.66 % NRMSE with the fitted offset) is reproduced, and the
  // asymmetric dead-zone map explains the fitted loop better than the odd-symmetric PI.
  EXPECT_NEAR(pi.report.fit.nrmse_percent, 3.66, 0.05);
  EXPECT_LT(mpi.report.fit.nrmse_percent, pi.report.fit.nrmse_percent);
  // Every prediction is finite and within the order of the data's range.
  for (double e : mpi_errors)
    EXPECT_LT(e, 100.0);
}

}  // namespace
}  // namespace hyst
