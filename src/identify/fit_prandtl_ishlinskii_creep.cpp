#include "hyst/identify/fit_prandtl_ishlinskii_creep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "creep_regressors.hpp"
#include "hyst/core/error.hpp"
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
  detail::check_creep_sample_time(options.sample_time, kFit);
}

struct Solved {
  PrandtlIshlinskiiCreep model;
  detail::OffsetNnls solution;
  std::size_t parameters = 0;
  std::vector<double> sample_times;  // of each record
  std::vector<double> outputs;       // every record's output, joined
};

// One NNLS on the columns [w_j, z_ij] of every record; p_0 = eps + q.
Solved solve(std::span<const FitRecord> records, const PiCreepFitOptions& options) {
  auto regressors =
      detail::creep_regressors(records, detail::creep_structure_options(options), kFit);
  const std::size_t n = regressors.structure.size();
  const Eigen::Index columns = regressors.columns.cols();
  const double eps = options.min_linear_weight * detail::range_of(regressors.outputs) /
                     detail::range_of(regressors.inputs);
  const Eigen::VectorXd b =
      Eigen::Map<const Eigen::VectorXd>(regressors.outputs.data(), regressors.columns.rows()) -
      eps * regressors.columns.col(0);
  auto solution = detail::nnls_with_offset(std::move(regressors.columns), b, options.fit_offset);
  auto params = regressors.structure.params();
  params.weights.assign(solution.x.data(), solution.x.data() + n);
  params.weights[0] += eps;
  params.creep_weights.assign(solution.x.data() + n, solution.x.data() + columns);
  params.offset = solution.offset;
  const auto parameters = static_cast<std::size_t>(columns) + (options.fit_offset ? 1 : 0);
  return {PrandtlIshlinskiiCreep(std::move(params)), std::move(solution), parameters,
          std::move(regressors.sample_times), std::move(regressors.outputs)};
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
  auto initial_state =
      detail::creep_start_state(solved.model, parts.fit_input, options.initial_state);
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
  const auto predicted = detail::simulate_creep_records(solved.model, records, solved.sample_times,
                                                        options.initial_state);
  auto initial_state =
      detail::creep_start_state(solved.model, records.front().input, options.initial_state);
  PiCreepFit result{std::move(solved.model), std::move(initial_state), {}};
  result.report = detail::weight_fit_report("pi_creep", "nnls (Lawson-Hanson)", solved.solution,
                                            solved.parameters, solved.outputs, predicted);
  result.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace hyst
