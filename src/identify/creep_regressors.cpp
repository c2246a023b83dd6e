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

// lags_per_decade per decade from 10 Ts (the shortest) to longest_time_constant.
std::vector<double> law_time_constants(std::span<const double> sample_times,
                                       const CreepStructureOptions& options, std::string_view who) {
  if (options.lags_per_decade < 1 || options.lags_per_decade > 12) {
    throw Error(
        fmt::format("{}: lags_per_decade = {} must be in [1, 12]", who, options.lags_per_decade),
        "lags_per_decade");
  }
  const double shortest = 10.0 * *std::min_element(sample_times.begin(), sample_times.end());
  const double longest = options.longest_time_constant;
  if (!std::isfinite(longest) || !(longest > shortest) || longest > 1e12) {
    throw Error(fmt::format("{}: longest_time_constant = {} s must be finite, at most 1e12 s and "
                            "longer than 10 sample times ({} s)",
                            who, longest, shortest),
                "longest_time_constant");
  }
  const double decades = std::log10(longest / shortest);
  const auto count = static_cast<std::size_t>(
                         std::ceil(decades * static_cast<double>(options.lags_per_decade) - 1e-9)) +
                     1;
  return log_spaced_time_constants(shortest, longest, count);
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
  if (params.time_constants.empty() && options.creep_law == CreepLaw::logarithmic) {
    params.time_constants = law_time_constants(sample_times, options, who);
  } else if (params.time_constants.empty() && options.lags > 0) {
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

Eigen::MatrixXd creep_law_penalty(const CreepRegressors& regressors, Eigen::Index columns,
                                  double smoothing, Eigen::Index first_creep_column) {
  const auto n = static_cast<Eigen::Index>(regressors.structure.size());
  const auto lags = static_cast<Eigen::Index>(regressors.structure.lags());
  if (lags < 2 || smoothing == 0.0) return Eigen::MatrixXd(0, columns);
  Eigen::MatrixXd penalty = Eigen::MatrixXd::Zero((lags - 1) * n, columns);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto play = regressors.columns.col(j);
    const double scale = smoothing * (play.array() - play.mean()).matrix().norm();
    for (Eigen::Index i = 0; i + 1 < lags; ++i) {
      penalty(i * n + j, first_creep_column + i * n + j) = -scale;
      penalty(i * n + j, first_creep_column + (i + 1) * n + j) = scale;
    }
  }
  return penalty;
}

Eigen::MatrixXd leakage_columns(std::span<const FitRecord> records,
                                std::span<const double> sample_times, Eigen::Index rows) {
  Eigen::MatrixXd columns(rows, 3);
  Eigen::Index row = 0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    double charge = 0.0;
    double time = 0.0;
    for (double v : records[r].input) {
      charge += sample_times[r] * v;
      time += sample_times[r];
      columns.row(row++) << charge, time, -time;
    }
  }
  return columns;
}

}  // namespace hyst::detail
