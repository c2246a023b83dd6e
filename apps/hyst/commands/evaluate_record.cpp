#include "evaluate_record.hpp"

#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "../data_source.hpp"
#include "../domain_warning.hpp"
#include "commands.hpp"
#include "hyst/registry/fitted_domain_file.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/record_score.hpp"
#include "hyst/registry/timed_simulation.hpp"

namespace hyst::cli {
namespace {

std::string record_rule_text(const RecordEvaluation& options, const ValidationRule& rule) {
  if (rule.start != ValidationStart::continued) return describe(rule);
  return fmt::format(
      "separate record, started from the state the model file holds (validation "
      "start 'file'), {} (validation align '{}')",
      rule.align == ValidationAlignment::first_sample
          ? "prediction shifted to the measured first sample"
          : "prediction compared as it is",
      options.align);
}

// The record's time axis and how the model took it, in words.
std::string time_text(const DynamicModel& model, const std::optional<RecordTime>& time) {
  const std::string record =
      time ? fmt::format("sampled at {:.6g} s{} ({})", time->axis.sample_time,
                         time->axis.uniform() ? "" : " (median step; not uniform)", time->source)
           : std::string("no time axis (--time COLUMN or --sample-time SECONDS)");
  if (model.time_dependence() == TimeDependence::none)
    return record + "; the model is rate independent (time does not change its output)";
  const auto own = model.sample_time();
  return fmt::format("{}; the model is {}{}", record, time_dependence_name(model.time_dependence()),
                     own ? fmt::format(", run at {:.6g} s", *own) : std::string());
}

nlohmann::json prediction_json(const PredictionScore& s) {
  return {{"rmse", s.metrics.rmse},
          {"nrmse_range_percent", s.metrics.nrmse_percent},
          {"nrmse_std_percent", s.nrmse_std_percent},
          {"max_error", s.metrics.max_error}};
}

}  // namespace

void evaluate_record(const RecordEvaluation& options) {
  const DataSource source(options.data, options.table);
  const auto record = read_column_pair(source, options.input, options.output, "data");
  const auto time = record_time(source, options.time, record.input.size());
  const auto model = model_for_record(load_model(options.model), time, "hyst evaluate");
  const auto rule = saved_model_rule(options.start, options.align, "'hyst evaluate'");
  RecordScore score;
  try {
    score = score_on_record(*model, record.input, record.output, rule);
  } catch (const Error& error) {
    throw Error(fmt::format("{} --input '{}' --output '{}' through the model of {}: {}",
                            options.data, options.input, options.output, options.model,
                            error.what()));
  }
  const auto unit = source.unit(options.output);
  const auto domain = load_fitted_domain(options.model);
  const DomainCheck domain_check = check_record_inputs(domain, record.input, time);
  report_domain(domain_check, record.input.size(), options.model,
                fmt::format("{} --input '{}'", options.data, options.input), options.strict);

  if (options.json) {
    nlohmann::json out = prediction_json(score.model);
    out["model"] = options.model;
    out["model_name"] = model->name();
    out["data"] = options.data;
    out["input"] = options.input;
    out["output"] = options.output;
    out["output_unit"] = unit;
    out["samples"] = score.model.metrics.samples;
    out["validation_start"] = options.start;
    out["validation_align"] = options.align;
    out["time_dependence"] = time_dependence_name(model->time_dependence());
    out["sample_time"] = time ? nlohmann::json{{"seconds", time->axis.sample_time},
                                               {"source", time->source},
                                               {"uniform", time->axis.uniform()}}
                              : nlohmann::json(nullptr);
    out["domain"] = domain ? nlohmann::json{{"known", true},
                                            {"inside", domain_check.inside()},
                                            {"message", domain_check.message(record.input.size())}}
                           : nlohmann::json{{"known", false}};
    auto& yardsticks = out["yardsticks_on_this_record"] = nlohmann::json::object();
    for (const auto& yardstick : score.yardsticks)
      yardsticks[yardstick.name] = prediction_json(yardstick.score);
    fmt::print("{}\n", out.dump(2));
    return;
  }
  const std::string in_unit = unit.empty() ? "" : fmt::format(" [{}]", unit);
  fmt::print("model: {} ({}, {} parameters)\n", options.model, model->name(),
             model->parameter_count());
  fmt::print("data:  {}: input '{}', output '{}', {} samples\n", options.data, options.input,
             options.output, record.input.size());
  fmt::print("time:  {}\n", time_text(*model, time));
  fmt::print("rule:  {}\n\n", record_rule_text(options, rule));
  fmt::print("{:<36} {:>13} {:>14} {:>12} {:>13}\n", "predictor", "RMSE" + in_unit, "NRMSE (range)",
             "NRMSE (std)", "max error" + in_unit);
  const auto row = [](std::string_view name, const PredictionScore& s) {
    fmt::print("{:<36} {:>13.6g} {:>12.3f} % {:>10.3f} % {:>13.6g}\n", name, s.metrics.rmse,
               s.metrics.nrmse_percent, s.nrmse_std_percent, s.metrics.max_error);
  };
  row(model->name(), score.model);
  for (const auto& yardstick : score.yardsticks)
    row(yardstick.name + " (fitted on this record)", yardstick.score);
}

}  // namespace hyst::cli
