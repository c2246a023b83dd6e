// hyst actuator: closed-loop simulation of a hysteretic actuator from a configuration file, and
// the comparison of open loop, inverse feedforward, PID and PID + feedforward.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "hyst/actuator/actuator_config.hpp"
#include "hyst/actuator/comparison.hpp"
#include "hyst/actuator/linearised_plant.hpp"
#include "hyst/control/references.hpp"
#include "hyst/control/tracking_metrics.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/io/output_set.hpp"
#include "hyst/plot/gnuplot.hpp"
#include "progress_display.hpp"

namespace hyst::cli {
namespace {

struct SimulateOptions {
  std::string config;
  std::string reference;
  std::string out;
  std::string strategy = "pid_feedforward";
};

struct ActuatorCompareOptions {
  std::string config;
  std::string out_dir;
  bool no_plots = false;
  ProgressFlags progress;
};

void simulate(const SimulateOptions& options) {
  const auto strategy = control_strategy_from_string(options.strategy);
  io::check_outputs({{options.config, "--config"}, {options.reference, "--reference"}},
                    {{options.out, "--out"}});
  const auto config = load_actuator_config(options.config);
  const auto reference = control::reference_from_csv(options.reference, config.plant.sample_time);
  const auto trace = simulate_loop(config, strategy, reference.values);
  io::Table table;
  table.add_column("t", reference.times());
  table.add_column("reference", trace.reference);
  table.add_column("measured", trace.measured);
  table.add_column("position", trace.position);
  table.add_column("current_reference", trace.current_reference);
  table.add_column("current", trace.current);
  table.add_column("force", trace.force);
  table.add_column("voltage", trace.voltage);
  write_text_output(options.out, io::format_csv(table));
  const auto metrics = control::tracking_metrics(trace.reference, trace.measured, trace.voltage,
                                                 config.plant.sample_time, std::nullopt);
  fmt::print(message_stream(is_stdout(options.out)),
             "wrote {}: {} samples of {} under {}; RMS error {:.4g} m, max error {:.4g} m, RMS "
             "voltage {:.4g} V\n",
             options.out, trace.reference.size(), config.name, to_string(strategy),
             metrics.rms_error, metrics.max_error, metrics.control_effort);
}

void compare(const ActuatorCompareOptions& options) {
  const std::filesystem::path folder = options.out_dir;
  // The tables and plots in --out-dir are published as one set (hyst/io/output_set.hpp).
  std::optional<io::OutputSet> set;
  if (!options.out_dir.empty()) {
    create_output_folder(folder, "--out-dir");
    io::check_outputs({{options.config, "--config"}}, {{folder / "comparison.md", "--out-dir"},
                                                       {folder / "comparison.csv", "--out-dir"}});
    set.emplace(folder, std::vector<std::string>{"comparison.md", "comparison.csv"});
  }
  const auto config = load_actuator_config(options.config);
  const auto plant = LinearisedPlant::of(config.plant, config.loop.force_gain);
  fmt::print("{}: {}\n", config.name, config.description);
  fmt::print("linearised plant: DC gain {:.6g} m/V, poles", plant.dc_gain());
  for (const auto& pole : plant.poles())
    fmt::print(" ({:.6g}{:+.6g}j)", pole.real(), pole.imag());
  fmt::print(" rad/s, delay {} s (simulated, not measured)\n\n", config.plant.delay);
  ProgressDisplay display("hyst actuator compare", options.progress.mode());
  const auto comparison = display.run("simulating every strategy on every scenario", [&] {
    return compare_strategies(config, scenario_references(config));
  });
  const auto markdown = comparison_markdown(comparison);
  fmt::print("{}", markdown);
  if (options.out_dir.empty()) return;
  io::write_file_atomically(set->staged("comparison.md"), markdown);
  io::write_file_atomically(set->staged("comparison.csv"), comparison_csv(comparison));
  const bool plots = !options.no_plots && plot::gnuplot_available();
  std::vector<std::filesystem::path> written;
  if (plots) written = write_comparison_plots(comparison, set->staged(""));
  set->publish();
  fmt::print("\nwrote {} and {}\n", (folder / "comparison.md").string(),
             (folder / "comparison.csv").string());
  if (options.no_plots) return;
  if (!plots) {
    warn("gnuplot not found: no plots written (install gnuplot-nox, or pass --no-plots)");
    return;
  }
  fmt::print("wrote {} plots (tracking_*.png, error_*.png) into {}\n", written.size(),
             folder.string());
}

}  // namespace

void add_actuator_command(CLI::App& app) {
  auto* command = app.add_subcommand(
      "actuator",
      "Simulate and control a hysteretic actuator (coil, hysteresis, mechanics, delay).");
  command->require_subcommand(1);

  auto simulate_options = std::make_shared<SimulateOptions>();
  auto* sim = command->add_subcommand(
      "simulate", "Run one control strategy on a reference trajectory; write every signal as CSV.");
  sim->add_option("--config", simulate_options->config, "Actuator configuration (JSON)")
      ->required();
  sim->add_option("--reference", simulate_options->reference,
                  "CSV with a column 'reference' [m] (else the last column) and optionally 't' "
                  "[s], spaced by the sample time")
      ->required();
  sim->add_option("--out", simulate_options->out,
                  "CSV to write: t, reference, measured, position, current_reference, current, "
                  "force, voltage ('-': standard output)")
      ->required();
  sim->add_option("--strategy", simulate_options->strategy,
                  "open_loop, feedforward, pid or pid_feedforward (also pid+ff)")
      ->capture_default_str();
  sim->footer(R"(Example:
  hyst actuator simulate --config examples/config/msma_assumed.json --reference r.csv --out o.csv)");
  sim->callback([simulate_options] { simulate(*simulate_options); });

  auto compare_options = std::make_shared<ActuatorCompareOptions>();
  auto* cmp = command->add_subcommand(
      "compare",
      "Compare open loop, inverse feedforward, PID and PID + feedforward on the configuration's "
      "scenarios (step, sines, triangle with internal loops); print the table.");
  cmp->add_option("--config", compare_options->config, "Actuator configuration (JSON)")->required();
  cmp->add_option(
      "--out-dir", compare_options->out_dir,
      "Folder (created when missing) for comparison.md, comparison.csv and the tracking and "
      "error plots");
  cmp->add_flag("--no-plots", compare_options->no_plots, "Write the tables only");
  add_progress_flags(*cmp, compare_options->progress);
  cmp->footer(R"(Example:
  hyst actuator compare --config examples/config/msma_assumed.json --out-dir results)");
  cmp->callback([compare_options] { compare(*compare_options); });
}

}  // namespace hyst::cli
