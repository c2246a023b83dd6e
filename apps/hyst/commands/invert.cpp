// hyst invert: the inputs that make a model file produce a target output (feedforward
// compensation), within optional input limits.

#include <cmath>
#include <cstddef>
#include <limits>
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

struct InvertOptions {
  std::string model;
  std::string target;
  std::string column;
  std::string out;
  std::string input_column = "v";
  double input_min = -std::numeric_limits<double>::infinity();
  double input_max = std::numeric_limits<double>::infinity();
  TimeOptions time;
  std::optional<std::size_t> table;
  bool strict = false;
};

void run(const InvertOptions& options) {
  if (std::isnan(options.input_min) || std::isnan(options.input_max) ||
      !(options.input_min < options.input_max)) {
    throw Error(fmt::format("--input-min {} must be less than --input-max {}", options.input_min,
                            options.input_max));
  }
  io::check_outputs({{options.model, "--model"}, {options.target, "--target"}},
                    {{options.out, "--out"}});
  auto model = load_model(options.model);
  if (!model->has_inverse()) {
    // inverse() says why (e.g. which weight breaks invertibility).
    try {
      static_cast<void>(model->inverse({}));
    } catch (const Error& error) {
      throw Error(fmt::format("{}: the {} model has no inverse: {}", options.model, model->name(),
                              error.what()));
    }
    throw Error(fmt::format("{}: the {} model has no inverse", options.model, model->name()));
  }
  const DataSource source(options.target, options.table);
  const auto column = source.choose(options.column, "y", "--column");
  if (options.input_column == column) {
    throw Error(fmt::format(
        "--input-column '{}' is the name of the target column; choose another input name",
        options.input_column));
  }
  auto target = source.column(column);
  // The inverse of a model with time in it holds at the record's sample time.
  const auto time = record_time(source, options.time, target.size());
  std::unique_ptr<DynamicInverse> inverse;
  try {
    inverse = model_for_record(std::move(model), time, "hyst invert")
                  ->inverse({options.input_min, options.input_max});
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", options.model, error.what()));
  }

  // Targets beyond every output the fit measured: checked now, said after the output is written.
  const auto domain = load_fitted_domain(options.model);
  DomainCheck domain_check = domain ? check_targets(*domain, target) : DomainCheck{};
  std::vector<double> input(target.size());
  InverseReport report;
  try {
    report = inverse->invert(target, input);
  } catch (const Error& error) {
    throw Error(fmt::format("{} column '{}': {}", source.path().string(), column, error.what()));
  }
  // The inputs the inverse asks for: rates and holds beyond the fitted ones.
  if (domain) {
    domain_check.append(time ? check_timing(*domain, input, time->axis.sample_time)
                             : check_timing(*domain, input, std::nullopt));
  }

  io::Table table;
  table.source = options.out;
  if (time && !time->times.empty() && time->column != column)
    table.add_column(time->column, time->times);
  table.add_column(column, std::move(target));
  table.add_column(options.input_column, std::move(input));
  write_text_output(options.out, io::format_csv(table));
  fmt::print(message_stream(is_stdout(options.out)),
             "wrote {}: {} samples of '{}' (target) and '{}' (input)\n", options.out, table.rows(),
             column, options.input_column);
  report_domain(domain_check, table.rows(), options.model,
                fmt::format("{} column '{}'", source.path().string(), column), options.strict);
  if (!report.ok()) {
    const std::size_t limited = report.limited_samples;
    std::string message;
    if (limited > 0) {
      message = fmt::format(
          "{} of {} samples saturated: out of reach within the input limits [{}, {}] and the "
          "model's reach (first at sample {}); their inputs are the nearest reachable ones",
          limited, table.rows(), options.input_min, options.input_max, report.first_limited);
    }
    if (report.not_invertible_samples > 0) {
      message += fmt::format(
          "{}{} of {} samples not invertible: the model is not monotone in the input over "
          "[{}, {}] there (first at sample {}); the previous input was held",
          message.empty() ? "" : "; ", report.not_invertible_samples, table.rows(),
          options.input_min, options.input_max, report.first_not_invertible);
    }
    if (options.strict) throw Error(message + " (--strict)");
    warn(message);
  }
}

}  // namespace

void add_invert_command(CLI::App& app) {
  auto options = std::make_shared<InvertOptions>();
  auto* command = app.add_subcommand(
      "invert",
      "Compute the input that makes a model produce a target output (inverse compensation).");
  command->add_option("--model", options->model, "Model file (JSON); must have an inverse")
      ->required();
  command->add_option("--target", options->target, "Target output data: CSV or .mat")->required();
  command->add_option("--column", options->column,
                      "Target column (default: the only column, else the column 'y')");
  command
      ->add_option("--out", options->out,
                   "Output CSV: the target column and the input column ('-': standard output)")
      ->required();
  command->add_option("--input-column", options->input_column, "Name of the input column")
      ->capture_default_str();
  add_time_options(*command, options->time, "--target");
  command->add_option("--table", options->table,
                      "Measurement table of an aixACCT export with several (1, 2, ...)");
  command->add_option("--input-min", options->input_min, "Lowest admissible input (default: none)");
  command->add_option("--input-max", options->input_max,
                      "Highest admissible input (default: none)");
  command->add_flag("--strict", options->strict,
                    "Exit with status 1 when a target is out of reach or beyond the outputs the "
                    "model was fitted on (the output is written)");
  command->footer(R"(Example:
  hyst invert --model m.json --target y.csv --column y --out v.csv --input-min -10 --input-max 10
      v.csv gets the columns y (the target) and v (the input), and with --time t the time
      column t. The inverse of a model with time in it (creep) is taken at the record's sample
      time (--time or --sample-time; without them the model's own, and a note says so); a
      non-uniform time axis is refused for it. The inverse starts consistent
      with the model file's state. Targets that need an input outside the limits get the
      nearest limit, and a warning line says how many samples saturated and where the first is.
      The numerical inverses search a bounded range (Preisach: its input range; Bouc-Wen,
      Duhem, backlash-like, Jiles-Atherton without limits: about 1e12 max(1, |v|) around the
      input they start from); a target the model cannot reach there (e.g. above a saturating
      Bouc-Wen's force bound) gets the input of the nearest reachable output and counts as
      saturated. Targets more than 5 % of the fitted output range beyond it (the model
      file's info.domain, written by hyst fit) are extrapolation: one more warning line says
      how many and where the first is. With --strict such samples make the exit status 1.)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
