// Demo section "actuator": the MSMA actuator of examples/config/msma_assumed.json (coil,
// GPI force, mass-spring-damper, delay; the [ASSUMED] synthetic set of the reference) under open
// loop, inverse (IGPI) feedforward, PID and PID + feedforward, as a table and tracking/error plots.
// The figures are simulated, not measured.

#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "demo_sections.hpp"
#include "hyst/actuator/actuator_config.hpp"
#include "hyst/actuator/comparison.hpp"
#include "hyst/actuator/linearised_plant.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/plot/gnuplot.hpp"

std::string actuator_section(const std::filesystem::path& config_file,
                             const std::filesystem::path& folder) {
  const auto config = hyst::load_actuator_config(config_file);
  const auto plant = hyst::LinearisedPlant::of(config.plant, config.loop.force_gain);
  const auto comparison = hyst::compare_strategies(config, hyst::scenario_references(config));
  const auto table = hyst::comparison_markdown(comparison);
  const auto actuator_folder = folder / "actuator";
  std::filesystem::create_directories(actuator_folder);
  hyst::io::write_file_atomically(actuator_folder / "comparison.md", table);
  hyst::io::write_file_atomically(actuator_folder / "comparison.csv",
                                  hyst::comparison_csv(comparison));
  std::string plots = "no plots: gnuplot is not installed";
  if (hyst::plot::gnuplot_available()) {
    const auto written = hyst::write_comparison_plots(comparison, actuator_folder);
    plots = fmt::format(
        "{} plots in `actuator/` (tracking_<reference>.png and "
        "error_<reference>.png)",
        written.size());
  }
  std::string markdown = "## Control of a hysteretic MSMA actuator (simulated)\n\n";
  markdown += fmt::format(
      "Configuration `{}`: {}\n\nLinearised plant G(s) = k_F e^(-sT) / ((Ls + R)(ms^2 + bs + "
      "k)): DC gain {:.4g} m/V, delay {} ms, sample time {} ms. Strategies: open loop (static "
      "current k r / k_F, no compensation), inverse GPI feedforward alone, PID alone, PID + "
      "inverse feedforward; deadbeat current drive. Each run starts at rest and holds the "
      "first reference value for {} s, which is not scored. Errors in micrometres.\n\n",
      config_file.filename().string(), config.description, plant.dc_gain(),
      1e3 * config.plant.delay, 1e3 * config.plant.sample_time, config.scenarios.lead_in);
  markdown += table;
  markdown +=
      fmt::format("\nTables: `actuator/comparison.md`, `actuator/comparison.csv`; {}.\n\n", plots);
  return markdown;
}
