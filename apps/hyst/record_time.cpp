#include "record_time.hpp"

#include <fmt/format.h>

#include "commands/commands.hpp"
#include "hyst/registry/timed_simulation.hpp"

namespace hyst::cli {

void add_time_options(CLI::App& command, TimeOptions& options, std::string_view what) {
  auto* time = command.add_option(
      "--time", options.column,
      fmt::format("Time column of {} [s]: models with time in them (creep, rate dependence, "
                  "oscillators) run at its step; default: an aixACCT export's 'Time' column",
                  what));
  auto* step = command
                   .add_option("--sample-time", options.sample_time,
                               fmt::format("Sample time of {} [s], for files without a time "
                                           "column",
                                           what))
                   ->check(CLI::PositiveNumber);
  time->excludes(step);
}

std::optional<RecordTime> record_time(const DataSource& source, const TimeOptions& options,
                                      std::size_t samples) {
  const std::string file = source.path().string();
  if (options.sample_time > 0.0) {
    return RecordTime{
        {options.sample_time, {}}, {}, {}, fmt::format("--sample-time {:g}", options.sample_time)};
  }
  std::string column = options.column;
  if (column.empty()) {
    if (source.aixacct() == nullptr || !source.has_column("Time")) return std::nullopt;
    column = "Time";
  }
  RecordTime time;
  time.times = source.column(column);
  time.column = column;
  time.source = fmt::format("time column '{}'", column);
  if (time.times.size() != samples) {
    throw Error(fmt::format("{}: time column '{}' has {} samples but the record has {}", file,
                            column, time.times.size(), samples));
  }
  time.axis = data::time_axis(time.times, fmt::format("{}: time column '{}'", file, column));
  return time;
}

std::unique_ptr<DynamicModel> model_for_record(std::unique_ptr<DynamicModel> model,
                                               const std::optional<RecordTime>& time,
                                               std::string_view command, bool non_uniform_allowed) {
  if (!time) {
    if (const auto note = untimed_record_note(*model); !note.empty())
      fmt::print(stderr, "hyst: note: {}\n", note);
    return model;
  }
  if (time->axis.uniform()) return at_record_sample_time(std::move(model), time->axis.sample_time);
  if (non_uniform_allowed || model->time_dependence() == TimeDependence::none) return model;
  throw Error(
      fmt::format("{}: the {} is not uniform (median step {:.6g} s) and model '{}' is {}: "
                  "{} needs a uniform time axis for it (hyst simulate steps a continuous-"
                  "time model through a non-uniform record; or resample the record)",
                  command, time->source, time->axis.sample_time, model->name(),
                  time_dependence_name(model->time_dependence()), command));
}

void simulate_record(std::unique_ptr<DynamicModel>& model, const std::optional<RecordTime>& time,
                     std::span<const double> input, std::span<double> output) {
  if (!time) {
    model->simulate(input, output);
    return;
  }
  simulate_on_time_axis(model, time->axis, input, output);
}

}  // namespace hyst::cli
