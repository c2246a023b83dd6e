// hyst simulate: runs a model file over an input column and writes input and output as CSV.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../data_source.hpp"
#include "../domain_warning.hpp"
#include "../record_time.hpp"
#include "commands.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/registry/fitted_domain_file.hpp"
#include "hyst/registry/model_file.hpp"

namespace hyst::cli {
namespace {

struct SimulateOptions {
  std::string model;
  std::string input;
  std::string column;
  std::string out;
  std::string output_column = "y";
  TimeOptions time;
  std::optional<std::size_t> table;
  bool strict = false;
};

void run(const SimulateOptions& options) {
  io::check_outputs({{options.model, "--model"}, {options.input, "--input"}},
                    {{options.out, "--out"}});
  auto model = load_model(options.model);
  const DataSource source(options.input, options.table);
  const auto column = source.choose(options.column, "v", "--column");
  if (options.output_column == column) {
    throw Error(fmt::format(
        "--output-column '{}' is the name of the input column; choose another output name",
        options.output_column));
  }

  auto input = source.column(column);
  const auto time = record_time(source, options.time, input.size());
  model = model_for_record(std::move(model), time, "hyst simulate", true);
  // Inputs beyond those the model was fitted on: checked now, said after the output is written.
  const auto domain = load_fitted_domain(options.model);
  const DomainCheck domain_check = check_record_inputs(domain, input, time);
  std::vector<double> output(input.size());
  try {
    simulate_record(model, time, input, output);
  } catch (const Error& error) {
    throw Error(fmt::format("{} column '{}' through the model of {}: {}", source.path().string(),
                            column, options.model, error.what()));
  }

  io::Table table;
  table.source = options.out;
  if (time && !time->times.empty() && time->column != column)
    table.add_column(time->column, time->times);
  table.add_column(column, std::move(input));
  table.add_column(options.output_column, std::move(output));
  write_text_output(options.out, io::format_csv(table));
  fmt::print(message_stream(is_stdout(options.out)),
             "wrote {}: {} samples of '{}' (input) and '{}' ({} model from {})\n", options.out,
             table.rows(), column, options.output_column, model->name(), options.model);
  report_domain(domain_check, table.rows(), options.model,
                fmt::format("{} column '{}'", source.path().string(), column), options.strict);
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
  add_time_options(*command, options->time, "--input");
  command->add_option("--table", options->table,
                      "Measurement table of an aixACCT export with several (1, 2, ...)");
  command->add_flag("--strict", options->strict,
                    "Exit with status 1 when inputs leave the range the model was fitted on "
                    "(the output is written)");
  command->footer(R"(Example:
  hyst simulate --model m.json --input in.csv --column v --out out.csv
      out.csv gets the columns v (the input) and y (the model output). With --time t, also the
      time column t, and a model whose output depends on time (creep, rate dependence, Bouc-Wen
      oscillator) runs at the record's step: continuous-time models are re-discretised (the
      lags exactly), stepped run by run through a non-uniform record; a NARX runs only at the
      sample time it was fitted at. Without --time or --sample-time, such a model takes the
      record as sampled at its own sample time and a note says so. Inputs more than 5 %
      of the fitted input range beyond it (the model file's info.domain, written by hyst fit)
      are extrapolation: a warning line says how many and where the first is (--strict: exit
      status 1).)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
