#include "creep_regressors.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "detail/regressor_matrix.hpp"
#include "hyst/core/error.hpp"

namespace hyst::detail {
namespace creep_fit {

std::vector<double> sample_times_of(std::span<const FitRecord> records,
                                    const CreepStructureOptions& options, std::string_view who) {
  if (options.sample_times.empty()) return std::vector<double>(records.size(), options.sample_time);
  if (options.sample_times.size() != records.size()) {
    throw Error(fmt::format("{}: {} sample times for {} records (one per record, or none)", who,
                            options.sample_times.size(), records.size()),
                "sample_times");
  }
  for (std::size_t r = 0; r < records.size(); ++r) {
    const double ts = options.sample_times[r];
    if (!std::isfinite(ts) || !(ts > 0.0)) {
      throw Error(fmt::format("{}: sample_times[{}] = {} must be finite and > 0", who, r, ts),
                  fmt::format("sample_times[{}]", r));
    }
  }
  return {options.sample_times.begin(), options.sample_times.end()};
}

PrandtlIshlinskiiCreep structure_of(std::span<const FitRecord> records,
                                    std::span<const double> inputs,
                                    std::span<const double> sample_times,
                                    const CreepStructureOptions& options, std::string_view who) {
  double duration = 0.0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    duration = std::max(duration, static_cast<double>(records[r].input.size()) * sample_times[r]);
  }
  PrandtlIshlinskiiCreep::Params params;
  params.thresholds = options.thresholds.empty() ? pi_default_thresholds(inputs, options.operators)
                                                 : std::vector<double>(options.thresholds.begin(),
                                                                       options.thresholds.end());
  params.time_constants.assign(options.time_constants.begin(), options.time_constants.end());
  if (params.time_constants.empty() && options.lags > 0) {
    const double shortest = 10.0 * *std::min_element(sample_times.begin(), sample_times.end());
    if (!(duration > shortest)) {
      throw Error(
          fmt::format("{}: the longest record lasts {} s, not longer than 10 sample times "
                      "({} s): too short to identify creep",
                      who, duration, shortest));
    }
    params.time_constants = log_spaced_time_constants(shortest, duration, options.lags);
  }
  params.weights.assign(params.thresholds.size(), 0.0);
  params.creep_weights.assign(params.thresholds.size() * params.time_constants.size(), 0.0);
  params.sample_time = sample_times.front();
  return PrandtlIshlinskiiCreep(std::move(params));
}

}  // namespace creep_fit

void check_creep_sample_time(double sample_time, std::string_view who) {
  if (!std::isfinite(sample_time) || !(sample_time > 0.0)) {
    throw Error(fmt::format("{}: sample_time = {} must be finite and > 0", who, sample_time),
                "sample_time");
  }
}

CreepRegressors creep_regressors(std::span<const FitRecord> records,
                                 const CreepStructureOptions& options, std::string_view who) {
  auto sample_times = creep_fit::sample_times_of(records, options, who);
  std::vector<double> inputs;
  std::vector<double> outputs;
  for (const auto& record : records) {
    inputs.insert(inputs.end(), record.input.begin(), record.input.end());
    outputs.insert(outputs.end(), record.output.begin(), record.output.end());
  }
  auto structure = creep_fit::structure_of(records, inputs, sample_times, options, who);
  const std::size_t n = structure.size();
  const auto columns = static_cast<Eigen::Index>(n + structure.params().creep_weights.size());
  const auto rows = static_cast<Eigen::Index>(inputs.size());
  if (rows < columns + 2) {
    throw Error(
        fmt::format("{}: {} samples, fewer than unknowns + 2 = {}", who, rows, columns + 2));
  }
  Eigen::MatrixXd A = regressor_matrix(rows, columns, who);
  Eigen::Index row = 0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto& record = records[r];
    const auto discretised = structure.at_sample_time(sample_times[r]);
    auto state = creep_start_state(discretised, record.input, options.initial_state);
    for (std::size_t k = 0; k < record.input.size(); ++k, ++row) {
      discretised.step(state, record.input[k]);
      A.row(row).head(static_cast<Eigen::Index>(n)) =
          Eigen::Map<const Eigen::RowVectorXd>(state.play.data(), static_cast<Eigen::Index>(n));
      A.row(row).tail(columns - static_cast<Eigen::Index>(n)) =
          Eigen::Map<const Eigen::RowVectorXd>(state.creep.data(),
                                               static_cast<Eigen::Index>(state.creep.size()));
    }
  }
  return {std::move(structure), std::move(sample_times), std::move(A), std::move(inputs),
          std::move(outputs)};
}

}  // namespace hyst::detail
