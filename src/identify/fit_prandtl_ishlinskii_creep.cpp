#include "hyst/identify/fit_prandtl_ishlinskii_creep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "detail/regressor_matrix.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "weight_fit.hpp"

namespace hyst {
namespace {

constexpr std::string_view kFit = "PI with creep fit";

void check_options(const PiCreepFitOptions& options) {
  if (!std::isfinite(options.min_linear_weight) || !(options.min_linear_weight > 0.0)) {
    throw Error(fmt::format("{}: min_linear_weight = {} must be finite and > 0", kFit,
                            options.min_linear_weight),
                "min_linear_weight");
  }
  if (!std::isfinite(options.sample_time) || !(options.sample_time > 0.0)) {
    throw Error(
        fmt::format("{}: sample_time = {} must be finite and > 0", kFit, options.sample_time),
        "sample_time");
  }
}

// The sample time of each record.
std::vector<double> sample_times_of(std::span<const FitRecord> records,
                                    const PiCreepFitOptions& options) {
  if (options.sample_times.empty()) return std::vector<double>(records.size(), options.sample_time);
  if (options.sample_times.size() != records.size()) {
    throw Error(fmt::format("{}: {} sample times for {} records (one per record, or none)", kFit,
                            options.sample_times.size(), records.size()),
                "sample_times");
  }
  for (std::size_t r = 0; r < records.size(); ++r) {
    const double ts = options.sample_times[r];
    if (!std::isfinite(ts) || !(ts > 0.0)) {
      throw Error(fmt::format("{}: sample_times[{}] = {} must be finite and > 0", kFit, r, ts),
                  fmt::format("sample_times[{}]", r));
    }
  }
  return options.sample_times;
}

// The model's structure with zero weights: thresholds and time constants from the options or
// their defaults for these records.
// `inputs`: every record's input, joined.
PrandtlIshlinskiiCreep structure_of(std::span<const FitRecord> records,
                                    std::span<const double> inputs,
                                    std::span<const double> sample_times,
                                    const PiCreepFitOptions& options) {
  double duration = 0.0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    duration = std::max(duration, static_cast<double>(records[r].input.size()) * sample_times[r]);
  }
  PrandtlIshlinskiiCreep::Params params;
  params.thresholds = options.thresholds.empty() ? pi_default_thresholds(inputs, options.operators)
                                                 : options.thresholds;
  params.time_constants = options.time_constants;
  if (params.time_constants.empty() && options.lags > 0) {
    const double shortest = 10.0 * *std::min_element(sample_times.begin(), sample_times.end());
    if (!(duration > shortest)) {
      throw Error(
          fmt::format("{}: the longest record lasts {} s, not longer than 10 sample times "
                      "({} s): too short to identify creep",
                      kFit, duration, shortest));
    }
    params.time_constants = log_spaced_time_constants(shortest, duration, options.lags);
  }
  params.weights.assign(params.thresholds.size(), 0.0);
  params.creep_weights.assign(params.thresholds.size() * params.time_constants.size(), 0.0);
  params.sample_time = sample_times.front();
  return PrandtlIshlinskiiCreep(std::move(params));
}

// The state a record starts from, for the model discretised at the record's sample time.
PrandtlIshlinskiiCreep::State start_state(const PrandtlIshlinskiiCreep& model,
                                          std::span<const double> input,
                                          const PiCreepFitOptions& options) {
  return options.initial_state == PiFitOptions::InitialState::periodic ? model.periodic_state(input)
                                                                       : model.initial_state();
}

struct Solved {
  PrandtlIshlinskiiCreep model;
  detail::OffsetNnls solution;
  std::size_t parameters = 0;
  std::vector<double> sample_times;  // of each record
};

// Columns [w_j, z_ij] of every record from rest at its first input; p_0 = eps + q.
Solved solve(std::span<const FitRecord> records, const PiCreepFitOptions& options) {
  auto sample_times = sample_times_of(records, options);
  std::vector<double> inputs;
  std::vector<double> outputs;
  for (const auto& record : records) {
    inputs.insert(inputs.end(), record.input.begin(), record.input.end());
    outputs.insert(outputs.end(), record.output.begin(), record.output.end());
  }
  const PrandtlIshlinskiiCreep probe = structure_of(records, inputs, sample_times, options);
  const std::size_t n = probe.size();
  const auto columns = static_cast<Eigen::Index>(n + probe.params().creep_weights.size());
  const auto rows = static_cast<Eigen::Index>(inputs.size());
  if (rows < columns + 2) {
    throw Error(
        fmt::format("{}: {} samples, fewer than unknowns + 2 = {}", kFit, rows, columns + 2));
  }
  const double eps =
      options.min_linear_weight * detail::range_of(outputs) / detail::range_of(inputs);
  Eigen::MatrixXd A = detail::regressor_matrix(rows, columns, kFit);
  Eigen::VectorXd b(rows);
  Eigen::Index row = 0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto& record = records[r];
    const auto discretised = probe.at_sample_time(sample_times[r]);
    auto state = start_state(discretised, record.input, options);
    for (std::size_t k = 0; k < record.input.size(); ++k, ++row) {
      discretised.step(state, record.input[k]);
      A.row(row).head(static_cast<Eigen::Index>(n)) =
          Eigen::Map<const Eigen::RowVectorXd>(state.play.data(), static_cast<Eigen::Index>(n));
      A.row(row).tail(columns - static_cast<Eigen::Index>(n)) =
          Eigen::Map<const Eigen::RowVectorXd>(state.creep.data(),
                                               static_cast<Eigen::Index>(state.creep.size()));
      b[row] = record.output[k] - eps * state.play[0];
    }
  }
  auto solution = detail::nnls_with_offset(std::move(A), std::move(b), options.fit_offset);
  auto params = probe.params();
  params.weights.assign(solution.x.data(), solution.x.data() + n);
  params.weights[0] += eps;
  params.creep_weights.assign(solution.x.data() + n, solution.x.data() + columns);
  params.offset = solution.offset;
  const auto parameters = static_cast<std::size_t>(columns) + (options.fit_offset ? 1 : 0);
  return {PrandtlIshlinskiiCreep(std::move(params)), std::move(solution), parameters,
          std::move(sample_times)};
}

}  // namespace

PiCreepFit fit_prandtl_ishlinskii_creep(std::span<const double> input,
                                        std::span<const double> output,
                                        const PiCreepFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  check_options(options);
  const auto parts = detail::split_record(input, output, options.validate_fraction, kFit, 2);
  const FitRecord record{parts.fit_input, parts.fit_output};
  auto solved = solve(std::span(&record, 1), options);
  auto initial_state = start_state(solved.model, parts.fit_input, options);
  PiCreepFit result{std::move(solved.model), initial_state, {}};
  result.report =
      detail::weight_fit_report("pi_creep", "nnls (Lawson-Hanson)", solved.solution,
                                solved.parameters, result.model, initial_state, parts, start);
  return result;
}

PiCreepFit fit_prandtl_ishlinskii_creep(std::span<const FitRecord> records,
                                        const PiCreepFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  check_options(options);
  detail::check_several_records(records, options.validate_fraction, kFit);
  auto solved = solve(records, options);
  std::vector<double> measured;
  std::vector<double> predicted;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto& record = records[r];
    measured.insert(measured.end(), record.output.begin(), record.output.end());
    const auto discretised = solved.model.at_sample_time(solved.sample_times[r]);
    auto state = start_state(discretised, record.input, options);
    const auto y = simulate(discretised, state, record.input);
    predicted.insert(predicted.end(), y.begin(), y.end());
  }
  auto initial_state = start_state(solved.model, records.front().input, options);
  PiCreepFit result{std::move(solved.model), std::move(initial_state), {}};
  result.report = detail::weight_fit_report("pi_creep", "nnls (Lawson-Hanson)", solved.solution,
                                            solved.parameters, measured, predicted);
  result.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace hyst
