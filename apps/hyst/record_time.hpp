#pragma once
// The time axis of a record on the command line: --time COLUMN or --sample-time SECONDS on every
// command that reads records, else an aixACCT export's own 'Time' column; and a saved model made
// ready for it (hyst/registry/timed_simulation.hpp): re-discretised, refused, or, without a time
// axis, run at its own sample time with a note saying so.

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "data_source.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst::cli {

struct TimeOptions {
  std::string column;        //!< --time COLUMN
  double sample_time = 0.0;  //!< --sample-time SECONDS; 0: not given
};

//! Adds --time and --sample-time (mutually exclusive) to `command`; `what` names the data option
//! whose records they time ("--data", "--input").
void add_time_options(CLI::App& command, TimeOptions& options, std::string_view what);

//! A record's time axis with the values of its time column (empty for --sample-time).
struct RecordTime {
  data::TimeAxis axis;
  std::vector<double> times;  //!< t[k] [s] from the file; empty when only a step was given
  std::string column;         //!< the time column's name; empty for --sample-time
  std::string source;         //!< for messages: "time column 'Time [s]'" or "--sample-time 0.01"
};

//! The time axis of `source` for `samples` samples: --time COLUMN, --sample-time, else an
//! aixACCT export's 'Time' column; none without any. Throws hyst::Error naming the file and column
//! for a time column that is not finite and increasing or whose length differs.
std::optional<RecordTime> record_time(const DataSource& source, const TimeOptions& options,
                                      std::size_t samples);

//! `model` at the record's sample time (at_record_sample_time()); without a time axis the model
//! as it is, with a note on stderr when its output depends on time. A non-uniform axis is kept for
//! simulate_on_time_axis() when `non_uniform_allowed`, else refused for a model that depends on
//! time, naming `command`.
std::unique_ptr<DynamicModel> model_for_record(std::unique_ptr<DynamicModel> model,
                                               const std::optional<RecordTime>& time,
                                               std::string_view command,
                                               bool non_uniform_allowed = false);

//! Runs `model` over `input` on the record's time axis (simulate_on_time_axis()), or at the
//! model's own sample time without one.
void simulate_record(std::unique_ptr<DynamicModel>& model, const std::optional<RecordTime>& time,
                     std::span<const double> input, std::span<double> output);

}  // namespace hyst::cli
