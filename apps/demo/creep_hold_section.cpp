// Demo section "hold": the 60 s hold of a piezoceramic (piezo_pzt_trapezoid_creep_table1), fitted
// on its first half and predicting its second - the part of a hold no fit saw. The PI with creep
// with free weights, with the logarithmic law and with the leakage drift (P1), and the butterfly
// strain models without and with creep (D1).

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "demo_sections.hpp"

#include "hyst/core/simulate.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/identify/fit_butterfly_strain.hpp"
#include "hyst/identify/fit_butterfly_strain_creep.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii_creep.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/plot/gnuplot.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kHeldOut = 0.5;  // the record's second half

struct Record {
  std::vector<double> time;
  std::vector<double> voltage;
  std::vector<double> output;
  double sample_time = 0.0;
};

// A fit's prediction of the whole record from its start and its scores.
struct Prediction {
  std::string model;
  std::size_t parameters = 0;
  double fit_nrmse = 0.0;
  double held_out_nrmse = 0.0;
  std::vector<double> output;
};

template <class Fit>
Prediction prediction_of(std::string model, const Fit& fit, const Record& record) {
  auto state = fit.initial_state;
  return {std::move(model), fit.report.parameters, fit.report.fit.nrmse_percent,
          fit.report.validation ? fit.report.validation->nrmse_percent : 0.0,
          hyst::simulate(fit.model, state, record.voltage)};
}

Prediction pi_creep(const Record& record, hyst::CreepLaw law, bool leakage) {
  hyst::PiCreepFitOptions options;
  options.sample_time = record.sample_time;
  options.validate_fraction = kHeldOut;
  options.creep_law = law;
  options.fit_leakage = leakage;
  return prediction_of(
      fmt::format("pi_creep, {} law{}", hyst::to_string(law), leakage ? ", leakage" : ""),
      hyst::fit_prandtl_ishlinskii_creep(record.voltage, record.output, options), record);
}

std::vector<Prediction> displacement_fits(const Record& record) {
  hyst::ButterflyFitOptions butterfly;
  butterfly.validate_fraction = kHeldOut;
  hyst::ButterflyCreepFitOptions creep;
  creep.sample_time = record.sample_time;
  creep.validate_fraction = kHeldOut;
  return {
      pi_creep(record, hyst::CreepLaw::logarithmic, false),
      prediction_of("butterfly_strain",
                    hyst::fit_butterfly_strain(record.voltage, record.output, butterfly), record),
      prediction_of("butterfly_strain_creep",
                    hyst::fit_butterfly_strain_creep(record.voltage, record.output, creep), record),
  };
}

std::string rows_and_plot(const std::string& name, const Record& record,
                          const std::vector<Prediction>& predictions, const fs::path& png) {
  hyst::plot::Figure figure{
      fmt::format("{}: fitted on the first half, the second predicted", name),
      "time [s]",
      name,
      {{"measured", record.time, record.output, hyst::plot::Series::Style::points, "black"}}};
  std::string rows;
  for (const auto& prediction : predictions) {
    rows += fmt::format("| {} | {} | {} | {:.2f} | {:.2f} |\n", name, prediction.model,
                        prediction.parameters, prediction.fit_nrmse, prediction.held_out_nrmse);
    figure.series.push_back({prediction.model, record.time, prediction.output});
  }
  hyst::plot::write_png(figure, png);
  return rows;
}

}  // namespace

std::string creep_hold_section(const fs::path& data_dir, const fs::path& folder) {
  const auto path =
      data_dir / "piezo_pzt_trapezoid_creep_table1" / "RMN_TRAP_1400V_1000V_60S_TABLE1.dat";
  const auto file = hyst::io::read_aixacct(path);
  const auto& table = file.measurement(1);
  const auto column = [&](const char* name) { return table.column(name, file.source).values; };
  Record polarisation{column("Time"), column("V+"), column("P1")};
  polarisation.sample_time = hyst::data::uniform_sample_time(
      polarisation.time, fmt::format("{}: column 'Time [s]'", file.source));
  Record displacement = polarisation;
  displacement.output = column("D1");

  std::string markdown = "## Creep beyond the fitted hold: the 60 s record's second half\n\n";
  markdown += fmt::format(
      "Data: `{}`: switching steps, then a 72 V hold of 60 s (5000 samples at {:.4g} ms). Every "
      "model is fitted on the first 34 s and predicts the last 34 s continued from there (the "
      "rest of the hold); NRMSE [%] by each part's range:\n\n"
      "| output | model | parameters | fit | held-out |\n|---|---|---:|---:|---:|\n",
      path.string(), 1e3 * polarisation.sample_time);
  markdown += rows_and_plot("polarisation P1 [uC/cm2]", polarisation,
                            {pi_creep(polarisation, hyst::CreepLaw::free, false),
                             pi_creep(polarisation, hyst::CreepLaw::logarithmic, false),
                             pi_creep(polarisation, hyst::CreepLaw::free, true)},
                            folder / "hold_P1.png");
  markdown += rows_and_plot("displacement D1 [nm]", displacement, displacement_fits(displacement),
                            folder / "hold_D1.png");
  markdown += "\nPlots: `hold_P1.png`, `hold_D1.png`.\n\n";
  return markdown;
}
