// Demo section "creep": one 1400 V triangle of a piezoceramic measured at 1, 0.1 and 0.01 Hz
// (RMN_TRAP_SLOW.dat, tables 6, 1 and 2). The PI and the modified PI, each with creep and
// rate-independent, are fitted the same way on the 1 Hz and 0.1 Hz periods and predict the
// 0.01 Hz period, for the polarisation P1 and the displacement D1.

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "demo_sections.hpp"

#include "hyst/core/simulate.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/identify/error_metrics.hpp"
#include "hyst/identify/fit_modified_prandtl_ishlinskii_creep.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii_creep.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/plot/gnuplot.hpp"

namespace {

namespace fs = std::filesystem;

struct RatePeriod {
  std::string label;  // "1 Hz"
  double sample_time = 0.0;
  std::vector<double> voltage;
  std::vector<double> output;
};

std::vector<RatePeriod> read_periods(const hyst::io::AixacctFile& file, const std::string& column) {
  std::vector<RatePeriod> periods;
  for (const auto& [table, label] : std::vector<std::pair<std::size_t, std::string>>{
           {6, "1 Hz"}, {1, "0.1 Hz"}, {2, "0.01 Hz"}}) {
    const auto& measurement = file.measurement(table);
    const double ts = hyst::data::uniform_sample_time(
        measurement.column("Time", file.source).values,
        fmt::format("{}: table {} column 'Time [s]'", file.source, table));
    periods.push_back({label, ts, measurement.column("V+", file.source).values,
                       measurement.column(column, file.source).values});
  }
  return periods;
}

// The period's prediction from its periodic state; `zeroed`: shifted to 0 at the first sample,
// as the instrument zeroes the displacement.
template <class Model>
std::vector<double> predict(const Model& fitted, const RatePeriod& period, bool zeroed) {
  const auto model = fitted.at_sample_time(period.sample_time);
  auto state = model.periodic_state(period.voltage);
  auto output = hyst::simulate(model, state, period.voltage);
  if (zeroed) {
    const double first = output.front();
    for (double& y : output)
      y -= first;
  }
  return output;
}

struct OutputCase {
  std::string column;  // "P1"
  std::string name;    // "polarisation P1 [uC/cm2]"
  bool zeroed = false;
};

// A fitted model's parameter count and its prediction of each period.
struct RateFit {
  std::size_t parameters = 0;
  std::vector<std::vector<double>> predicted;  // one per period
};

template <class Fit>
RateFit predictions_of(const Fit& fit, const std::vector<RatePeriod>& periods, bool zeroed) {
  RateFit result{fit.report.parameters, {}};
  for (const auto& period : periods)
    result.predicted.push_back(predict(fit.model, period, zeroed));
  return result;
}

// The fit on the two faster periods (1 and 0.1 Hz), each at its sample time from its periodic
// steady state; `lags` = 0: rate independent; `modified`: with the dead zones.
RateFit fit_two_rates(const std::vector<RatePeriod>& periods, std::size_t lags, bool modified,
                      bool zeroed) {
  const std::vector<hyst::FitRecord> records{{periods[0].voltage, periods[0].output},
                                             {periods[1].voltage, periods[1].output}};
  const std::vector<double> sample_times{periods[0].sample_time, periods[1].sample_time};
  if (modified) {
    hyst::ModifiedPiCreepFitOptions options;
    options.lags = lags;
    options.sample_times = sample_times;
    options.initial_state = hyst::PiFitOptions::InitialState::periodic;
    return predictions_of(hyst::fit_modified_prandtl_ishlinskii_creep(records, options), periods,
                          zeroed);
  }
  hyst::PiCreepFitOptions options;
  options.lags = lags;
  options.sample_times = sample_times;
  options.initial_state = hyst::PiFitOptions::InitialState::periodic;
  return predictions_of(hyst::fit_prandtl_ishlinskii_creep(records, options), periods, zeroed);
}

// Rows of the comparison table and of the table of lag counts.
struct CaseRows {
  std::string comparison;
  std::string sensitivity;
};

CaseRows compare_on(const hyst::io::AixacctFile& file, const OutputCase& output,
                    const fs::path& folder) {
  const auto periods = read_periods(file, output.column);
  std::string table;
  hyst::plot::Figure loops{
      fmt::format("{} at 0.01 Hz, predicted from 1 and 0.1 Hz", output.name),
      "voltage V+ [V]",
      output.name,
      {{"measured", periods[2].voltage, periods[2].output, hyst::plot::Series::Style::points}}};
  const std::size_t default_lags = hyst::PiCreepFitOptions{}.lags;
  for (const bool modified : {false, true}) {
    const std::string family = modified ? "modified PI" : "PI";
    for (const std::size_t lags : {std::size_t{0}, default_lags}) {
      const auto fit = fit_two_rates(periods, lags, modified, output.zeroed);
      const std::string model = lags == 0 ? fmt::format("{} (rate independent)", family)
                                          : fmt::format("{} + creep, {} lags", family, lags);
      std::string row = fmt::format("| {} | {} | {} |", output.name, model, fit.parameters);
      for (std::size_t p = 0; p < periods.size(); ++p) {
        row += fmt::format(" {:.2f} |",
                           hyst::error_metrics(periods[p].output, fit.predicted[p]).nrmse_percent);
      }
      loops.series.push_back({model, periods[2].voltage, fit.predicted[2]});
      table += row + "\n";
    }
  }
  hyst::plot::write_png(loops, folder / fmt::format("creep_{}.png", output.column));
  // How much the prediction depends on the number of lags (a fit choice the 0.01 Hz period
  // cannot inform).
  std::string sensitivity;
  for (const bool modified : {false, true}) {
    sensitivity += fmt::format("| {} | {} |", output.name, modified ? "modified PI" : "PI");
    for (std::size_t lags = 1; lags <= 8; ++lags) {
      const auto fit = fit_two_rates(periods, lags, modified, output.zeroed);
      sensitivity += fmt::format(
          " {:.2f} |", hyst::error_metrics(periods[2].output, fit.predicted[2]).nrmse_percent);
    }
    sensitivity += "\n";
  }
  return {table, sensitivity};
}

}  // namespace

std::string creep_section(const fs::path& data_dir, const fs::path& folder) {
  const auto path = data_dir / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat";
  const auto file = hyst::io::read_aixacct(path);
  std::string markdown = "## Creep: one piezo triangle at three rates\n\n";
  markdown += fmt::format(
      "Data: `{}`, tables 6, 1 and 2: one period of the same 1400 V triangle at 1, 0.1 and "
      "0.01 Hz (sample times 2.5 ms, 25 ms, 250 ms, read from the time column). Every model is "
      "fitted on the 1 Hz and 0.1 Hz periods together, each from its periodic steady state (the "
      "PI models by one NNLS, the modified PI models by one NNLS on the equation error, then on "
      "the output error); the 0.01 Hz period is predicted. A rate-independent model is the same "
      "fit without creep lags. NRMSE [%] of each period (the displacement zeroed at the first "
      "sample, as measured):\n\n",
      path.string());
  markdown +=
      "| output | model | parameters | 1 Hz (fit) | 0.1 Hz (fit) | 0.01 Hz (predicted) |\n"
      "|---|---|---:|---:|---:|---:|\n";
  const auto polarisation = compare_on(file, {"P1", "polarisation P1 [uC/cm2]", false}, folder);
  const auto displacement = compare_on(file, {"D1", "displacement D1 [nm]", true}, folder);
  markdown += polarisation.comparison + displacement.comparison;
  markdown +=
      "\nThe prediction's NRMSE [%] at 0.01 Hz against the number of creep lags (log-spaced from "
      "25 ms to 10 s, the longest fitted period):\n\n"
      "| output | model | 1 | 2 | 3 | 4 | 5 | 6 | 7 | 8 |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  markdown += polarisation.sensitivity + displacement.sensitivity;
  markdown += "\nPlots: `creep_P1.png`, `creep_D1.png` (the 0.01 Hz period).\n";
  return markdown;
}
