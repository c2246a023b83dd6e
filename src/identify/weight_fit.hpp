#pragma once
// Shared steps of the fits whose model output is linear in non-negative weights (KP,
// Maxwell-slip, modified PI): record checks and split, NNLS with a free offset, and the report.

#include <chrono>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <Eigen/Core>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/identify/nnls.hpp"

namespace hyst::detail {

// The fit part and the validation part (possibly empty) of one record.
struct RecordParts {
  std::span<const double> fit_input;
  std::span<const double> fit_output;
  std::span<const double> validation_input;
  std::span<const double> validation_output;
};

// Checks lengths, finiteness, a varying input and output and at least unknowns + 2 samples in
// the fit part, then splits off the last validate_fraction. Messages start with `who`.
RecordParts split_record(std::span<const double> input, std::span<const double> output,
                         double validate_fraction, std::string_view who, std::size_t unknowns);

// min ||A x + offset - b||^2 over x >= 0 (and the offset when fit_offset; else offset = 0).
struct OffsetNnls {
  Eigen::VectorXd x;
  double offset = 0.0;
  NnlsResult nnls;
};
OffsetNnls nnls_with_offset(Eigen::MatrixXd A, Eigen::VectorXd b, bool fit_offset);
// The same with the penalty ||penalty x||^2 added (rows appended after the offset is removed,
// so the offset stays the mean residual of the data rows).
OffsetNnls nnls_with_offset(Eigen::MatrixXd A, Eigen::VectorXd b, bool fit_offset,
                            const Eigen::MatrixXd& penalty);

// 0.5 sum (measured - predicted)^2, the cost of a FitReport.
double half_sum_of_squares(std::span<const double> measured, std::span<const double> predicted);
// The cost of the best constant: the mean (or 0 without a fitted offset) - a report's
// initial_cost.
double best_constant_cost(std::span<const double> measured, bool fit_offset = true);

// The records of a fit of several records: validate_fraction must be 0 (a record is held out
// instead), at least one record, each valid with two samples or more. Messages start with `who`.
void check_several_records(std::span<const FitRecord> records, double validate_fraction,
                           std::string_view who);

// Range max - min of the samples.
double range_of(std::span<const double> samples);

// The report of a weight fit from its NNLS solution and the model's prediction of the fitted
// samples: termination, costs (final against the output's own variance) and fit metrics.
FitReport weight_fit_report(std::string_view name, std::string method, const OffsetNnls& solution,
                            std::size_t parameters, std::span<const double> measured,
                            std::span<const double> predicted);

// The same for one record: the fit part simulated from `state` (which is advanced), then the
// validation part continuing from there.
template <class Model>
FitReport weight_fit_report(std::string_view name, std::string method, const OffsetNnls& solution,
                            std::size_t parameters, const Model& model, typename Model::State state,
                            const RecordParts& parts, std::chrono::steady_clock::time_point start) {
  const auto predicted = simulate(model, state, parts.fit_input);
  FitReport report =
      weight_fit_report(name, std::move(method), solution, parameters, parts.fit_output, predicted);
  if (!parts.validation_input.empty()) {
    const auto validation = simulate(model, state, parts.validation_input);
    report.validation = error_metrics(parts.validation_output, validation);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace hyst::detail
