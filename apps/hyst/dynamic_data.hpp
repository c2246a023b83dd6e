#pragma once
// The data of the dynamic (multi-input multi-output) commands: periodic experiments from NumPy
// files (--input-npy/--output-npy with a --layout) or from columns of CSV/.mat files (--data with
// --input u1,u2,u3 --output y1,y2,y3, cut into periods of --samples-per-period).

#include <cstddef>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "hyst/dynamics/best_linear_approximation.hpp"
#include "hyst/io/output_paths.hpp"

namespace hyst::cli {

struct DynamicDataOptions {
  std::vector<std::string> input_npy;
  std::vector<std::string> output_npy;
  std::string layout = "N,channel,realisation,period";
  std::vector<std::string> data;
  std::string input_columns;
  std::string output_columns;
  std::size_t samples_per_period = 0;
};

//! Adds the options above; `repeated`: several experiments may be given (a fit), else one.
void add_dynamic_data_options(CLI::App& command, DynamicDataOptions& options, bool repeated);

//! The experiments, in the order given; throws hyst::Error naming the file and option.
std::vector<PeriodicExperiment> read_experiments(const DynamicDataOptions& options);

//! The data files as inputs of the command (for io::check_outputs).
std::vector<io::NamedPath> dynamic_data_inputs(const DynamicDataOptions& options);

//! "u.npy / y.npy: 3 realisations x 2 periods x 8192 samples, 3 inputs, 3 outputs".
std::string describe_experiment(const DynamicDataOptions& options, std::size_t index,
                                const PeriodicExperiment& experiment);

}  // namespace hyst::cli
