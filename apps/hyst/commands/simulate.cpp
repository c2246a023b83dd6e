// hyst simulate: runs a model file over an input column and writes input and output as CSV.

#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../data_source.hpp"
#include "commands.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/registry/model_file.hpp"

namespace hyst::cli {
namespace {

struct SimulateOptions {
  std::string model;
  std::string input;
  std::string column;
  std::string out;
  std::string output_column = "y";
};

void run(const SimulateOptions& options) {
  io::check_outputs({{options.model, "--model"}, {options.input, "--input"}},
                    {{options.out, "--out"}});
  auto model = load_model(options.model);
  const DataSource source(options.input);
  const auto column = source.choose(options.column, "v", "--column");
  if (options.output_column == column) {
    throw Error(fmt::format(
        "--output-column '{}' is the name of the input column; choose another output name",
        options.output_column));
  }

  auto input = source.column(column);
  std::vector<double> output(input.size());
  try {
    model->simulate(input, output);
  } catch (const Error& error) {
    throw Error(fmt::format("{} column '{}' through the model of {}: {}", source.path().string(),
                            column, options.model, error.what()));
  }

  io::Table table;
  table.source = options.out;
  table.add_column(column, std::move(input));
  table.add_column(options.output_column, std::move(output));
  write_text_output(options.out, io::format_csv(table));
  fmt::print(message_stream(is_stdout(options.out)),
             "wrote {}: {} samples of '{}' (input) and '{}' ({} model from {})\n", options.out,
             table.rows(), column, options.output_column, model->name(), options.model);
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  auto* command = app.add_subcommand(
      "simulate", "Run a model file over an input signal, starting from the file's state.");
  command->add_option("--model", options->model, "Model file (JSON)")->required();
  command->add_option("--input", options->input, "Input data: CSV, or a MATLAB .mat file")
      ->required();
  command->add_option("--column", options->column,
                      "Input column (default: the only column, else the column 'v')");
  command
      ->add_option("--out", options->out,
                   "Output CSV: the input column and the output column ('-': standard output)")
      ->required();
  command->add_option("--output-column", options->output_column, "Name of the output column")
      ->capture_default_str();
  command->footer(R"(Example:
  hyst simulate --model m.json --input in.csv --column v --out out.csv
      out.csv gets the columns v (the input) and y (the model output).)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
