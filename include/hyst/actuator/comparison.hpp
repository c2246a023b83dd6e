#pragma once
//! \file
//! Runs an actuator configuration under each control strategy on the same references and scores
//! the runs: the comparison of open loop, inverse feedforward alone, PID alone and PID plus
//! inverse feedforward, as a Markdown or CSV table and as tracking and error plots.
//! The hysteresis model is chosen at run time: the loop of each run executes inside one
//! std::visit of the configuration's model (no per-sample dispatch).

#include <filesystem>
#include <string>
#include <vector>

#include "hyst/actuator/actuator_config.hpp"
#include "hyst/actuator/control_loop.hpp"
#include "hyst/control/references.hpp"
#include "hyst/control/tracking_metrics.hpp"

namespace hyst {

//! One reference under one strategy.
struct ComparisonRun {
  std::string reference;
  ControlStrategy strategy = ControlStrategy::open_loop;
  control::TrackingMetrics metrics;
  LoopTrace trace;  //!< the scored part (after the lead-in)
};

struct Comparison {
  std::string actuator;
  double sample_time = 1.0;
  std::vector<ComparisonRun> runs;
};

//! Runs one strategy from the configuration's initial state; the reference is used as given.
LoopTrace simulate_loop(const ActuatorConfig& config, ControlStrategy strategy,
                        const std::vector<double>& reference);
//! The configuration's standard references: a step low -> high, sines about the middle at full
//! and half amplitude for each frequency, a triangle with internal loops.
std::vector<control::Reference> scenario_references(const ActuatorConfig& config);
//! Every reference under every strategy; each run starts at rest and holds the first reference
//! value for scenarios.lead_in, which is not scored.
Comparison compare_strategies(const ActuatorConfig& config,
                              const std::vector<control::Reference>& references);
//! The table in Markdown (errors in micrometres) and in CSV (SI units).
std::string comparison_markdown(const Comparison& comparison);
std::string comparison_csv(const Comparison& comparison);
//! Writes tracking_<reference>.png and error_<reference>.png into `folder` (which must exist);
//! returns the files written. hyst::Error when gnuplot fails or is missing.
std::vector<std::filesystem::path> write_comparison_plots(const Comparison& comparison,
                                                          const std::filesystem::path& folder);

}  // namespace hyst
