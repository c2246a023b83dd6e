// hyst plot: time series or hysteresis loops of a data file as PNG, optionally with a model's
// simulated output beside the measurement.

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
#include "hyst/plot/gnuplot.hpp"
#include "hyst/registry/fitted_domain_file.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/validation_rule.hpp"

namespace hyst::cli {
namespace {

struct PlotOptions {
  std::string data;
  std::string x;
  std::vector<std::string> y;
  std::string out;
  std::string title;
  std::string kind = "series";
  std::string model;
  std::string input;
  std::string validation_start = "rest";
  std::string validation_align = "none";
  TimeOptions time;
  std::optional<std::size_t> table;
};

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names)
    text += (text.empty() ? "" : ", ") + name;
  return text;
}

void run(const PlotOptions& options) {
  const bool loop = options.kind == "loop";
  if (loop && options.x.empty()) {
    throw Error("--kind loop needs --x, the input column (the loop is output over input)");
  }
  refuse_stdout(options.out, "--out");
  std::vector<io::NamedPath> inputs{{options.data, "--data"}};
  if (!options.model.empty()) inputs.push_back({options.model, "--model"});
  io::check_outputs(inputs, {{options.out, "--out"}});
  const DataSource source(options.data, options.table);
  if (options.y.empty()) throw Error("--y: give at least one column");
  const auto samples = source.column(options.y.front()).size();
  const auto time = record_time(source, options.time, samples);

  std::vector<double> x;
  std::string x_label = options.x;
  if (!options.x.empty()) {
    x = source.column(options.x);
    if (const auto unit = source.unit(options.x); !unit.empty())
      x_label = fmt::format("{} [{}]", options.x, unit);
  } else if (!loop && time) {
    // A time series is drawn over the record's time, in seconds.
    x = time->times;
    if (x.empty()) {
      x.resize(samples);
      for (std::size_t k = 0; k < x.size(); ++k)
        x[k] = static_cast<double>(k) * time->axis.sample_time;
    }
    x_label = "time [s]";
  }
  plot::Figure figure;
  figure.title = options.title.empty() ? options.data : options.title;
  figure.x_label = x_label.empty() ? "sample" : x_label;
  figure.y_label = joined(options.y);

  for (const auto& name : options.y) {
    auto y = source.column(name);
    if (x.empty()) {
      x.resize(y.size());
      for (std::size_t k = 0; k < x.size(); ++k)
        x[k] = static_cast<double>(k);
    }
    if (y.size() != x.size()) {
      throw Error(fmt::format(
          "{}: --y column '{}' has {} samples but --x {} has {}", options.data, name, y.size(),
          options.x.empty() ? "(the time axis or the sample index)" : "'" + options.x + "'",
          x.size()));
    }
    figure.series.push_back(
        {.label = options.model.empty() ? name : name + " (measured)", .x = x, .y = std::move(y)});
  }

  if (!options.model.empty()) {
    const auto model = model_for_record(load_model(options.model), time, "hyst plot");
    const auto input_name = !options.input.empty() ? options.input : loop ? options.x : "";
    if (input_name.empty()) {
      throw Error("--model with --kind series needs --input, the model's input column");
    }
    const auto input = source.column(input_name);
    // The prediction that `hyst evaluate` and `hyst fit --validation-data` score, compared with
    // the first --y column.
    const auto& measured = figure.series.front().y;
    if (measured.size() != input.size())
      throw Error(fmt::format("{}: --input column '{}' has {} samples but --y '{}' has {}",
                              options.data, input_name, input.size(), options.y.front(),
                              measured.size()));
    const auto rule =
        saved_model_rule(options.validation_start, options.validation_align, "'hyst plot'");
    std::vector<double> output;
    try {
      output = predict_record(*model, input, measured, rule);
    } catch (const Error& error) {
      throw Error(fmt::format("{} column '{}': {}", options.data, input_name, error.what()));
    }
    report_domain(check_record_inputs(load_fitted_domain(options.model), input, time), input.size(),
                  options.model, fmt::format("{} column '{}'", options.data, input_name), false);
    plot::Series simulated{.label = fmt::format("model ({}, {})", model->name(), options.model)};
    if (loop) {
      simulated.x = input;
    } else if (x.empty()) {
      simulated.x.resize(output.size());
      for (std::size_t k = 0; k < output.size(); ++k)
        simulated.x[k] = static_cast<double>(k);
    } else {
      if (x.size() != output.size()) {
        throw Error(fmt::format("{}: --input column '{}' has {} samples but --x '{}' has {}",
                                options.data, input_name, output.size(), figure.x_label, x.size()));
      }
      simulated.x = x;
    }
    simulated.y = std::move(output);
    figure.series.push_back(std::move(simulated));
  }

  plot::write_png(figure, options.out);
  fmt::print("wrote {}: {} of {} ({} series)\n", options.out, loop ? "loop" : "time series",
             options.data, figure.series.size());
}

}  // namespace

void add_plot_command(CLI::App& app) {
  auto options = std::make_shared<PlotOptions>();
  auto* command = app.add_subcommand(
      "plot", "Plot time series or hysteresis loops of a data file as PNG (needs gnuplot).");
  command->add_option("--data", options->data, "Data: CSV, or a MATLAB .mat file")->required();
  command->add_option("--x", options->x,
                      "x column: time for --kind series (default: the sample index), the input "
                      "for --kind loop (required)");
  command->add_option("--y", options->y, "y column(s), comma-separated: the measured output(s)")
      ->required()
      ->delimiter(',');
  command->add_option("--out", options->out, "PNG file to write")->required();
  command->add_option("--title", options->title, "Title (default: the data file name)");
  command->add_option("--kind", options->kind, "series (y over time) or loop (y over input)")
      ->check(CLI::IsMember({"series", "loop"}))
      ->capture_default_str();
  command->add_option("--model", options->model,
                      "Model file: add its output, simulated from the --input column");
  command->add_option("--input", options->input,
                      "Input column the model is simulated from (default for loops: --x)");
  add_time_options(*command, options->time, "--data");
  command->add_option("--table", options->table,
                      "Measurement table of an aixACCT export with several (1, 2, ...)");
  command
      ->add_option("--validation-start", options->validation_start,
                   "With --model: where its prediction starts, as for 'hyst evaluate': rest, "
                   "periodic or file (the state the model file holds)")
      ->capture_default_str();
  command
      ->add_option("--validation-align", options->validation_align,
                   "With --model: none, or first-sample (shifted to the first --y column's "
                   "first sample)")
      ->capture_default_str();
  command->footer(R"(Examples:
  hyst plot --data d.csv --x t --y v,y --out series.png
  hyst plot --data d.csv --x v --y y --kind loop --model m.json --out loop.png
      measured loop y(v) and the model's loop simulated from the column v
  hyst plot --data d.csv --x t --y y --model m.json --input v --out fit.png
  hyst plot --data d.csv --time t --y y --model creep.json --input v --out fit.png
      the series over t in seconds; the creep model runs at the step of t)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
