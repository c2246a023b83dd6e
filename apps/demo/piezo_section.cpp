// Demo section "piezo": fits a Prandtl-Ishlinskii model to measured piezoceramic voltage ->
// displacement loops (one amplitude), predicts the loops at the four other amplitudes, then uses
// the analytic inverse of the fitted model as a feedforward compensator of a desired displacement
// with internal loops.

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "demo_sections.hpp"

#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/io/mat_file.hpp"
#include "hyst/plot/gnuplot.hpp"
#include "hyst/signals/generators.hpp"

namespace {

namespace fs = std::filesystem;

struct Record {
  std::string label;  // e.g. "1.9 kV"
  std::vector<double> voltage;
  std::vector<double> displacement;
};

// The five amplitudes of MeasurementData.mat (one period each, see its PROVENANCE.md).
std::vector<Record> read_piezo_records(const fs::path& mat) {
  const std::vector<std::pair<std::string, std::string>> names{{"08kv", "0.8 kV"},
                                                               {"1kv", "1.0 kV"},
                                                               {"11kv", "1.1 kV"},
                                                               {"15kv", "1.5 kV"},
                                                               {"19kv", "1.9 kV"}};
  std::vector<Record> records;
  for (const auto& [suffix, label] : names) {
    records.push_back({label, hyst::io::read_mat_vector(mat, "Vplus_" + suffix),
                       hyst::io::read_mat_vector(mat, "Displacement_" + suffix)});
  }
  return records;
}

// Each record is one period in steady state, and its displacement was zeroed at its first
// sample: the prediction starts from the periodic state and is zeroed the same way.
std::vector<double> predict(const hyst::PrandtlIshlinskii& model,
                            const std::vector<double>& input) {
  auto state = hyst::pi_periodic_state(model, input);
  auto output = hyst::simulate(model, state, input);
  const double first = output.front();
  for (double& y : output)
    y -= first;
  return output;
}

std::string fit_section(const fs::path& folder, const std::vector<Record>& records,
                        const hyst::PiFit& fit, std::size_t fitted) {
  std::string table =
      "| record | role | RMSE [nm] | NRMSE [%] | max error [nm] |\n|---|---|---:|---:|---:|\n";
  hyst::plot::Figure loops{
      "PI model vs measured piezo loops", "voltage [V]", "displacement [nm]", {}};
  // One colour per amplitude: measured as points, the model's prediction as a line.
  const std::vector<std::string> colours{"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"};
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& record = records[i];
    const auto predicted = predict(fit.model, record.voltage);
    const auto metrics = hyst::error_metrics(record.displacement, predicted);
    table += fmt::format("| {} | {} | {:.2f} | {:.2f} | {:.2f} |\n", record.label,
                         i == fitted ? "fit" : "validation", metrics.rmse, metrics.nrmse_percent,
                         metrics.max_error);
    loops.series.push_back({"measured " + record.label, record.voltage, record.displacement,
                            hyst::plot::Series::Style::points, colours[i % colours.size()]});
    loops.series.push_back({"model " + record.label, record.voltage, predicted,
                            hyst::plot::Series::Style::lines, colours[i % colours.size()]});
    if (i == 1) {
      std::vector<double> sample(record.voltage.size()), error(record.voltage.size());
      for (std::size_t k = 0; k < sample.size(); ++k) {
        sample[k] = static_cast<double>(k);
        error[k] = record.displacement[k] - predicted[k];
      }
      hyst::plot::write_png(
          {"Validation record " + record.label + ": time series",
           "sample",
           "displacement [nm]",
           {{"measured", sample, record.displacement}, {"model", sample, predicted}}},
          folder / "validation_time_series.png");
      hyst::plot::write_png({"Validation record " + record.label + ": error",
                             "sample",
                             "measured - model [nm]",
                             {{"error", sample, error}}},
                            folder / "validation_error.png");
    }
  }
  hyst::plot::write_png(loops, folder / "piezo_loops.png");
  return table;
}

std::string compensation_section(const fs::path& folder, const hyst::PrandtlIshlinskii& model,
                                 double amplitude) {
  const hyst::InversePrandtlIshlinskii inverse(model);
  const hyst::signals::TimeGrid grid{3000, 1e-3};
  const auto time = hyst::signals::times(grid);
  // A desired displacement with nested internal loops around the middle of the range.
  auto desired = hyst::signals::generate(
      grid,
      hyst::signals::DecayingSine{.amplitude = amplitude, .frequency = 4.0, .time_constant = 1.2});
  for (auto& y : desired)
    y += model.params().offset + amplitude;

  auto inverse_state = inverse.state_consistent_with(model.state_at_rest(0.0));
  std::vector<double> voltage(desired.size());
  const auto report = hyst::invert(inverse, inverse_state, desired, voltage);
  auto model_state = model.state_at_rest(0.0);
  const auto compensated = hyst::simulate(model, model_state, voltage);

  // Without compensation: a linear gain, 1 / (the slope of the model when every play moves).
  double slope = 0;
  for (double p : model.params().weights)
    slope += p;
  std::vector<double> linear_voltage(desired.size());
  for (std::size_t k = 0; k < desired.size(); ++k) {
    linear_voltage[k] = (desired[k] - model.params().offset) / slope;
  }
  model_state = model.state_at_rest(0.0);
  const auto uncompensated = hyst::simulate(model, model_state, linear_voltage);

  double worst_compensated = 0, worst_linear = 0;
  for (std::size_t k = 0; k < desired.size(); ++k) {
    worst_compensated = std::max(worst_compensated, std::abs(compensated[k] - desired[k]));
    worst_linear = std::max(worst_linear, std::abs(uncompensated[k] - desired[k]));
  }
  hyst::io::Table table;
  table.add_column("t", time);
  table.add_column("x_desired", desired);
  table.add_column("u_inverse", voltage);
  table.add_column("x_compensated", compensated);
  table.add_column("x_linear_gain", uncompensated);
  hyst::io::write_csv(folder / "compensation.csv", table);
  hyst::plot::write_png({"Feedforward compensation with the inverse PI model",
                         "time [s]",
                         "displacement [nm]",
                         {{"desired", time, desired},
                          {"model driven by the inverse", time, compensated},
                          {"model driven by a linear gain", time, uncompensated}}},
                        folder / "compensation.png");
  return fmt::format(
      "| feedforward | max tracking error [nm] |\n|---|---:|\n"
      "| inverse PI model | {:.2e} |\n| linear gain 1/sum(p) | {:.1f} |\n\n"
      "The inverse saturated on {} samples.\n",
      worst_compensated, worst_linear, report.saturated_samples);
}

}  // namespace

std::string piezo_section(const fs::path& data_dir, const fs::path& folder) {
  const auto mat = data_dir / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat";
  const auto records = read_piezo_records(mat);
  // The largest record a PI model can represent: 1.5 kV excites the thresholds needed by the
  // smaller loops; at 1.9 kV the piezo starts to switch polarisation (a butterfly loop, see
  // tests/identify/test_fit_piezo_data.cpp), which no PI model follows.
  const std::size_t fitted = 3;
  hyst::PiFitOptions options;
  options.operators = 12;
  options.initial_state = hyst::PiFitOptions::InitialState::periodic;
  const auto fit =
      hyst::fit_prandtl_ishlinskii(records[fitted].voltage, records[fitted].displacement, options);

  std::string markdown = "## 1. PI model fitted to measured piezo loops\n\n";
  markdown += fmt::format(
      "Data: `{}` (one period per amplitude). Fitted on the {} record, "
      "{} play operators, weights by NNLS; the other amplitudes are "
      "predictions (1.9 kV: an extrapolation into polarisation switching, "
      "which PI cannot follow).\n\n",
      mat.string(), records[fitted].label, fit.model.size());
  markdown += fit_section(folder, records, fit, fitted);
  markdown +=
      "\nEvery row is a prediction from the record's periodic state, zeroed at its first "
      "sample like the measurement; the fit report below scores the fit with the fitted "
      "offset instead.\n";
  markdown += "\n```\n" + fit.report.brief() + "\n```\n\n";
  markdown += "## 2. Compensation with the inverse model\n\n";
  markdown += compensation_section(folder, fit.model, 250.0);
  markdown +=
      "\nPlots: `piezo_loops.png`, `validation_time_series.png`, `validation_error.png`, "
      "`compensation.png`.\n";
  return markdown;
}
