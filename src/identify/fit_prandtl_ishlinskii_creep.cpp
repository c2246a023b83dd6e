#include "hyst/identify/fit_prandtl_ishlinskii_creep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "creep_regressors.hpp"
#include "hyst/core/error.hpp"
#include "hyst/identify/error_metrics.hpp"
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
  if (const auto smoothing = options.law_smoothing;
      smoothing && !(std::isfinite(*smoothing) && *smoothing >= 0.0 && *smoothing <= 1e6)) {
    throw Error(
        fmt::format("{}: law_smoothing = {} must be finite and in [0, 1e6]", kFit, *smoothing),
        "law_smoothing");
  }
}

struct Solved {
  PrandtlIshlinskiiCreep model;
  detail::OffsetNnls solution;
  std::size_t parameters = 0;
  std::vector<double> sample_times;  // of each record
  std::vector<double> outputs;       // every record's output, joined
};

// One NNLS on the columns [w_j, z_ij] of every record (and the leakage's); p_0 = eps + q.
Solved solve(std::span<const FitRecord> records, const PiCreepFitOptions& options) {
  auto regressors =
      detail::creep_regressors(records, detail::creep_structure_options(options), kFit);
  const std::size_t n = regressors.structure.size();
  const Eigen::Index creep_columns = regressors.columns.cols();
  if (options.fit_leakage) {
    const Eigen::Index rows = regressors.columns.rows();
    if (rows < creep_columns + 3 + 2) {
      throw Error(fmt::format("{}: {} samples, fewer than unknowns + 2 = {}", kFit, rows,
                              creep_columns + 3 + 2));
    }
    const Eigen::MatrixXd leakage = detail::leakage_columns(records, regressors.sample_times, rows);
    regressors.columns.conservativeResize(Eigen::NoChange, creep_columns + 3);
    regressors.columns.rightCols(3) = leakage;
  }
  const Eigen::Index columns = regressors.columns.cols();
  const double eps = options.min_linear_weight * detail::range_of(regressors.outputs) /
                     detail::range_of(regressors.inputs);
  const Eigen::VectorXd b =
      Eigen::Map<const Eigen::VectorXd>(regressors.outputs.data(), regressors.columns.rows()) -
      eps * regressors.columns.col(0);
  const Eigen::MatrixXd penalty =
      options.creep_law == CreepLaw::logarithmic
          ? detail::creep_law_penalty(regressors, columns, options.law_smoothing.value_or(0.0),
                                      static_cast<Eigen::Index>(n))
          : Eigen::MatrixXd(0, columns);
  auto solution =
      detail::nnls_with_offset(std::move(regressors.columns), b, options.fit_offset, penalty);
  auto params = regressors.structure.params();
  params.weights.assign(solution.x.data(), solution.x.data() + n);
  params.weights[0] += eps;
  params.creep_weights.assign(solution.x.data() + n, solution.x.data() + creep_columns);
  if (options.fit_leakage) {
    const auto leak = solution.x.tail(3);
    params.leakage_conductance = leak[0];
    params.leakage_current = leak[1] - leak[2];
  }
  params.offset = solution.offset;
  const auto parameters = static_cast<std::size_t>(creep_columns) + (options.fit_leakage ? 2 : 0) +
                          (options.fit_offset ? 1 : 0);
  return {PrandtlIshlinskiiCreep(std::move(params)), std::move(solution), parameters,
          std::move(regressors.sample_times), std::move(regressors.outputs)};
}

// Forward validation of one smoothing: the model fitted on `train` predicts `held_out`, each
// record from its start state, one record's held-out part continued from its fit part's end.
double held_out_rmse(std::span<const FitRecord> train, std::span<const FitRecord> held_out,
                     std::span<const double> held_out_times, bool continued,
                     const PiCreepFitOptions& options) {
  const auto solved = solve(train, options);
  std::vector<double> measured;
  std::vector<double> predicted;
  for (std::size_t r = 0; r < held_out.size(); ++r) {
    const auto model = solved.model.at_sample_time(held_out_times[r]);
    auto state = detail::creep_start_state(
        model, continued ? train.back().input : held_out[r].input, options.initial_state);
    if (continued) simulate(model, state, train.back().input);
    const auto y = simulate(model, state, held_out[r].input);
    predicted.insert(predicted.end(), y.begin(), y.end());
    measured.insert(measured.end(), held_out[r].output.begin(), held_out[r].output.end());
  }
  return error_metrics(measured, predicted).rmse;
}

// The logarithmic law's smoothing when it is not given (fit_prandtl_ishlinskii_creep.hpp), with
// the thresholds and time constants of the whole fit fixed; `method` gains the choice.
PiCreepFitOptions with_law_smoothing(std::span<const FitRecord> records, PiCreepFitOptions options,
                                     std::string& method) {
  if (options.creep_law != CreepLaw::logarithmic || options.law_smoothing) return options;
  const auto structure =
      detail::creep_regressors(records, detail::creep_structure_options(options), kFit).structure;
  options.thresholds = structure.params().thresholds;
  options.time_constants = structure.params().time_constants;
  std::vector<double> times = options.sample_times.empty()
                                  ? std::vector<double>(records.size(), options.sample_time)
                                  : options.sample_times;
  std::vector<FitRecord> train;
  std::vector<FitRecord> held_out;
  std::vector<double> held_out_times;
  const bool one_record = records.size() == 1;
  if (one_record) {
    const std::size_t cut = records[0].input.size() * 7 / 10;
    train.push_back({records[0].input.first(cut), records[0].output.first(cut)});
    held_out.push_back({records[0].input.subspan(cut), records[0].output.subspan(cut)});
    held_out_times.push_back(times[0]);
  } else {
    train.assign(records.begin(), records.end() - 1);
    held_out.push_back(records.back());
    held_out_times.push_back(times.back());
  }
  PiCreepFitOptions inner = options;
  if (!one_record) inner.sample_times.assign(times.begin(), times.end() - 1);
  double best = 0.0;
  double best_rmse = std::numeric_limits<double>::infinity();
  for (const double smoothing : {0.01, 0.03, 0.1, 0.3, 1.0}) {
    inner.law_smoothing = smoothing;
    double rmse = std::numeric_limits<double>::infinity();
    try {
      rmse = held_out_rmse(train, held_out, held_out_times, one_record, inner);
    } catch (const Error&) {
      continue;  // too few samples in the part: that smoothing cannot be judged
    }
    if (rmse < best_rmse) {
      best_rmse = rmse;
      best = smoothing;
    }
  }
  if (!std::isfinite(best_rmse)) {
    best = 0.1;
    method += ", logarithmic creep law (smoothing 0.1: too few samples to choose one)";
  } else {
    method += fmt::format(
        ", logarithmic creep law (smoothing {} chosen by forward validation on {}: RMSE {:.4g})",
        best, one_record ? "the last 30 % of the record" : "the last record", best_rmse);
  }
  options.law_smoothing = best;
  return options;
}

}  // namespace

PiCreepFit fit_prandtl_ishlinskii_creep(std::span<const double> input,
                                        std::span<const double> output,
                                        const PiCreepFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  check_options(options);
  const auto parts = detail::split_record(input, output, options.validate_fraction, kFit, 2);
  const FitRecord record{parts.fit_input, parts.fit_output};
  std::string method = "nnls (Lawson-Hanson)";
  const auto chosen = with_law_smoothing(std::span(&record, 1), options, method);
  auto solved = solve(std::span(&record, 1), chosen);
  auto initial_state =
      detail::creep_start_state(solved.model, parts.fit_input, options.initial_state);
  PiCreepFit result{std::move(solved.model), initial_state, {}};
  result.report =
      detail::weight_fit_report("pi_creep", std::move(method), solved.solution, solved.parameters,
                                result.model, initial_state, parts, start);
  return result;
}

PiCreepFit fit_prandtl_ishlinskii_creep(std::span<const FitRecord> records,
                                        const PiCreepFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  check_options(options);
  detail::check_several_records(records, options.validate_fraction, kFit);
  std::string method = "nnls (Lawson-Hanson)";
  auto solved = solve(records, with_law_smoothing(records, options, method));
  const auto predicted = detail::simulate_creep_records(solved.model, records, solved.sample_times,
                                                        options.initial_state);
  auto initial_state =
      detail::creep_start_state(solved.model, records.front().input, options.initial_state);
  PiCreepFit result{std::move(solved.model), std::move(initial_state), {}};
  result.report = detail::weight_fit_report("pi_creep", std::move(method), solved.solution,
                                            solved.parameters, solved.outputs, predicted);
  result.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace hyst
