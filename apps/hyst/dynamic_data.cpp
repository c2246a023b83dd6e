#include "dynamic_data.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "data_source.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/numpy_file.hpp"

namespace hyst::cli {
namespace {

std::vector<std::string> split_names(const std::string& list) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    names.push_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return names;
}

PeriodicSignals columns_of(const DataSource& source, const std::string& list,
                           std::size_t samples_per_period, std::string_view option) {
  if (list.empty())
    throw Error(fmt::format("--data needs {} (column names, comma-separated)", option));
  std::vector<std::vector<double>> columns;
  for (const auto& name : split_names(list)) {
    if (name.empty()) throw Error(fmt::format("{} '{}': an empty column name", option, list));
    columns.push_back(source.column(name));
  }
  return periodic_signals_from_columns(
      columns, samples_per_period, fmt::format("{} {} '{}'", source.path().string(), option, list));
}

PeriodicSignals numpy_signals(const std::string& spec, const std::string& layout,
                              std::string_view option) {
  try {
    return io::arrange_periodic(io::read_numpy_array(spec), layout, spec);
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", option, error.what()));
  }
}

//! `more` (one realisation) appended to `signals` as its next realisation.
void append_realisation(PeriodicSignals& signals, const PeriodicSignals& more) {
  if (signals.values.empty()) {
    signals = more;
    return;
  }
  if (more.samples != signals.samples || more.channels != signals.channels ||
      more.periods != signals.periods)
    throw Error(
        fmt::format("--data: every file must have the same number of samples and periods "
                    "({} x {}), found {} x {}",
                    signals.samples, signals.periods, more.samples, more.periods));
  signals.values.insert(signals.values.end(), more.values.begin(), more.values.end());
  ++signals.realisations;
}

}  // namespace

void add_dynamic_data_options(CLI::App& command, DynamicDataOptions& options, bool repeated) {
  const std::string several = repeated ? " (repeat for several experiments)" : "";
  auto* input_npy =
      command.add_option("--input-npy", options.input_npy,
                         "Inputs as a NumPy array: file.npy, file.npz or file.npz:name" + several);
  auto* output_npy = command.add_option(
      "--output-npy", options.output_npy,
      "Outputs as a NumPy array, one per --input-npy, in the same order" + several);
  command
      .add_option("--layout", options.layout,
                  "Axes of the NumPy arrays: a comma-separated order of N (samples of a period), "
                  "channel, realisation and period; axes left out have size 1")
      ->capture_default_str();
  auto* data = command.add_option(
      "--data", options.data,
      "A CSV or .mat file with input and output columns" +
          (repeated ? std::string(" (repeat: each file one realisation of the experiment)") : ""));
  command.add_option("--input", options.input_columns,
                     "With --data: the input columns, comma-separated (u1,u2,u3)");
  command.add_option("--output", options.output_columns,
                     "With --data: the output columns, comma-separated (y1,y2,y3)");
  command.add_option("--samples-per-period", options.samples_per_period,
                     "With --data: samples per period of a periodic input (default: the whole "
                     "record is one period)");
  input_npy->excludes(data);
  output_npy->excludes(data);
  if (!repeated) {
    input_npy->expected(1);
    output_npy->expected(1);
    data->expected(1);
  }
}

std::vector<PeriodicExperiment> read_experiments(const DynamicDataOptions& options) {
  std::vector<PeriodicExperiment> experiments;
  if (!options.data.empty()) {
    // Every file is one realisation of the same experiment (e.g. multisines of other phases).
    PeriodicExperiment experiment;
    for (const auto& file : options.data) {
      const DataSource source(file);
      append_realisation(experiment.input, columns_of(source, options.input_columns,
                                                      options.samples_per_period, "--input"));
      append_realisation(experiment.output, columns_of(source, options.output_columns,
                                                       options.samples_per_period, "--output"));
    }
    experiments.push_back(std::move(experiment));
    return experiments;
  }
  if (options.input_npy.empty())
    throw Error("no data: give --input-npy and --output-npy, or --data with --input and --output");
  if (options.input_npy.size() != options.output_npy.size())
    throw Error(
        fmt::format("{} --input-npy but {} --output-npy: give one output array per input "
                    "array",
                    options.input_npy.size(), options.output_npy.size()));
  for (std::size_t i = 0; i < options.input_npy.size(); ++i)
    experiments.push_back({numpy_signals(options.input_npy[i], options.layout, "--input-npy"),
                           numpy_signals(options.output_npy[i], options.layout, "--output-npy")});
  return experiments;
}

std::vector<io::NamedPath> dynamic_data_inputs(const DynamicDataOptions& options) {
  std::vector<io::NamedPath> inputs;
  const auto file_of = [](const std::string& spec) {
    // "file.npz:name" names a member of file.npz
    const auto colon = spec.rfind(':');
    const bool member = colon != std::string::npos && spec.find(".npz:") == colon - 4;
    return member ? spec.substr(0, colon) : spec;
  };
  for (const auto& spec : options.input_npy)
    inputs.push_back({file_of(spec), "--input-npy"});
  for (const auto& spec : options.output_npy)
    inputs.push_back({file_of(spec), "--output-npy"});
  for (const auto& file : options.data)
    inputs.push_back({file, "--data"});
  return inputs;
}

std::string describe_experiment(const DynamicDataOptions& options, std::size_t index,
                                const PeriodicExperiment& experiment) {
  const std::string files = options.data.empty() ? fmt::format("{} / {}", options.input_npy[index],
                                                               options.output_npy[index])
                                                 : options.data[index];
  return fmt::format("{}: {} realisations x {} periods x {} samples, {} inputs, {} outputs", files,
                     experiment.input.realisations, experiment.input.periods,
                     experiment.input.samples, experiment.input.channels,
                     experiment.output.channels);
}

}  // namespace hyst::cli
