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
  if (options.time_constants.empty() && options.lags == 0) {
    throw Error(fmt::format("{}: lags = 0 must be >= 1 (or give time_constants)", kFit), "lags");
  }
}

// The model's structure with zero weights: thresholds and time constants from the options or
// their defaults for these records.
PrandtlIshlinskiiCreep structure_of(std::span<const FitRecord> records,
                                    const PiCreepFitOptions& options) {
  std::vector<double> inputs;
  std::size_t longest = 0;
  for (const auto& record : records) {
    inputs.insert(inputs.end(), record.input.begin(), record.input.end());
    longest = std::max(longest, record.input.size());
  }
  PrandtlIshlinskiiCreep::Params params;
  params.thresholds = options.thresholds.empty()
                          ? pi_default_thresholds(inputs, options.operators)
                          : options.thresholds;
  params.time_constants = options.time_constants;
  if (params.time_constants.empty()) {
    const double shortest = 10.0 * options.sample_time;
    const double duration = static_cast<double>(longest) * options.sample_time;
    if (!(duration > shortest)) {
      throw Error(fmt::format("{}: the longest record lasts {} s, not longer than 10 sample times "
                              "({} s): too short to identify creep",
                              kFit, duration, shortest));
    }
    params.time_constants = log_spaced_time_constants(shortest, duration, options.lags);
  }
  params.weights.assign(params.thresholds.size(), 0.0);
  params.creep_weights.assign(params.thresholds.size() * params.time_constants.size(), 0.0);
  params.sample_time = options.sample_time;
  return PrandtlIshlinskiiCreep(std::move(params));
}

struct Solved {
  PrandtlIshlinskiiCreep model;
  detail::OffsetNnls solution;
  std::size_t parameters = 0;
};

// Columns [w_j, z_ij] of every record from rest at its first input; p_0 = eps + q.
Solved solve(std::span<const FitRecord> records, const PiCreepFitOptions& options) {
  const PrandtlIshlinskiiCreep probe = structure_of(records, options);
  const std::size_t n = probe.size();
  const auto columns = static_cast<Eigen::Index>(n + probe.params().creep_weights.size());
  Eigen::Index rows = 0;
  std::vector<double> inputs;
  std::vector<double> outputs;
  for (const auto& record : records) {
    rows += static_cast<Eigen::Index>(record.input.size());
    inputs.insert(inputs.end(), record.input.begin(), record.input.end());
    outputs.insert(outputs.end(), record.output.begin(), record.output.end());
  }
  if (rows < columns + 2) {
    throw Error(fmt::format("{}: {} samples, fewer than unknowns + 2 = {}", kFit, rows,
                            columns + 2));
  }
  const double eps =
      options.min_linear_weight * detail::range_of(outputs) / detail::range_of(inputs);
  Eigen::MatrixXd A = detail::regressor_matrix(rows, columns, kFit);
  Eigen::VectorXd b(rows);
  Eigen::Index row = 0;
  for (const auto& record : records) {
    auto state = probe.state_at_rest(record.input.front());
    for (std::size_t k = 0; k < record.input.size(); ++k, ++row) {
      probe.step(state, record.input[k]);
      A.row(row).head(static_cast<Eigen::Index>(n)) =
          Eigen::Map<const Eigen::RowVectorXd>(state.play.data(), static_cast<Eigen::Index>(n));
      A.row(row).tail(columns - static_cast<Eigen::Index>(n)) = Eigen::Map<const Eigen::RowVectorXd>(
          state.creep.data(), static_cast<Eigen::Index>(state.creep.size()));
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
  return {PrandtlIshlinskiiCreep(std::move(params)), std::move(solution), parameters};
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
  auto initial_state = solved.model.state_at_rest(parts.fit_input.front());
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
  if (options.validate_fraction != 0.0) {
    throw Error(fmt::format("{} of several records: validate_fraction = {} must be 0 (hold out a "
                            "record instead)",
                            kFit, options.validate_fraction),
                "validate_fraction");
  }
  if (records.empty()) throw Error(fmt::format("{}: no records", kFit), "records");
  for (std::size_t r = 0; r < records.size(); ++r)
    check_fit_record(records[r], fmt::format("records[{}]", r), {.min_samples = 2});
  auto solved = solve(records, options);
  std::vector<double> measured;
  std::vector<double> predicted;
  for (const auto& record : records) {
    measured.insert(measured.end(), record.output.begin(), record.output.end());
    auto state = solved.model.state_at_rest(record.input.front());
    const auto y = simulate(solved.model, state, record.input);
    predicted.insert(predicted.end(), y.begin(), y.end());
  }
  auto initial_state = solved.model.state_at_rest(records.front().input.front());
  PiCreepFit result{std::move(solved.model), std::move(initial_state), {}};
  result.report = detail::weight_fit_report("pi_creep", "nnls (Lawson-Hanson)", solved.solution,
                                            solved.parameters, measured, predicted);
  result.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace hyst
