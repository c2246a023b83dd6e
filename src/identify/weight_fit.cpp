#include "weight_fit.hpp"

#include <algorithm>
#include <utility>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/identify/data_split.hpp"
#include "hyst/identify/fit_record.hpp"

namespace hyst::detail {

double range_of(std::span<const double> samples) {
  const auto [lowest, highest] = std::minmax_element(samples.begin(), samples.end());
  return *highest - *lowest;
}

RecordParts split_record(std::span<const double> input, std::span<const double> output,
                         double validate_fraction, std::string_view who, std::size_t unknowns) {
  check_fit_record({input, output}, who, {});
  DataSplit split;
  try {
    split = split_by_fraction(input.size(), validate_fraction);
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", who, error.what()), "validate_fraction");
  }
  RecordParts parts{input.subspan(split.fit_begin, split.fit_size()),
                    output.subspan(split.fit_begin, split.fit_size()),
                    input.subspan(split.validation_begin, split.validation_size()),
                    output.subspan(split.validation_begin, split.validation_size())};
  if (parts.fit_input.size() < unknowns + 2) {
    throw Error(fmt::format("{}: the fit part has {} samples, fewer than unknowns + 2 = {}", who,
                            parts.fit_input.size(), unknowns + 2));
  }
  if (!(range_of(parts.fit_input) > 0.0)) {
    throw Error(
        fmt::format("{}: the input of the fit part is constant (= {}); hysteresis needs "
                    "a varying input to be identified",
                    who, parts.fit_input.front()));
  }
  if (!(range_of(parts.fit_output) > 0.0)) {
    throw Error(
        fmt::format("{}: the output of the fit part is constant (= {}); there is no "
                    "hysteresis to fit",
                    who, parts.fit_output.front()));
  }
  return parts;
}

OffsetNnls nnls_with_offset(Eigen::MatrixXd A, Eigen::VectorXd b, bool fit_offset) {
  return nnls_with_offset(std::move(A), std::move(b), fit_offset, Eigen::MatrixXd(0, 0));
}

OffsetNnls nnls_with_offset(Eigen::MatrixXd A, Eigen::VectorXd b, bool fit_offset,
                            const Eigen::MatrixXd& penalty) {
  Eigen::RowVectorXd means = Eigen::RowVectorXd::Zero(A.cols());
  double b_mean = 0.0;
  if (fit_offset) {
    // The best offset for any x is mean(b - A x): centring removes it from the problem.
    means = A.colwise().mean();
    b_mean = b.mean();
    A.rowwise() -= means;
    b.array() -= b_mean;
  }
  if (penalty.rows() > 0) {
    const Eigen::Index data_rows = A.rows();
    A.conservativeResize(data_rows + penalty.rows(), Eigen::NoChange);
    A.bottomRows(penalty.rows()) = penalty;
    b.conservativeResize(data_rows + penalty.rows());
    b.tail(penalty.rows()).setZero();
  }
  OffsetNnls solution;
  solution.nnls = nnls(A, b);
  solution.x = solution.nnls.x;
  if (fit_offset) solution.offset = b_mean - means.dot(solution.x);
  return solution;
}

double half_sum_of_squares(std::span<const double> measured, std::span<const double> predicted) {
  double cost = 0.0;
  for (std::size_t k = 0; k < measured.size(); ++k)
    cost += 0.5 * (measured[k] - predicted[k]) * (measured[k] - predicted[k]);
  return cost;
}

double best_constant_cost(std::span<const double> measured, bool fit_offset) {
  double mean = 0.0;
  if (fit_offset) {
    for (double y : measured)
      mean += y;
    mean /= static_cast<double>(measured.size());
  }
  double cost = 0.0;
  for (double y : measured)
    cost += 0.5 * (y - mean) * (y - mean);
  return cost;
}

void check_several_records(std::span<const FitRecord> records, double validate_fraction,
                           std::string_view who) {
  if (validate_fraction != 0.0) {
    throw Error(fmt::format("{} of several records: validate_fraction = {} must be 0 (hold out a "
                            "record instead)",
                            who, validate_fraction),
                "validate_fraction");
  }
  if (records.empty()) throw Error(fmt::format("{}: no records", who), "records");
  for (std::size_t r = 0; r < records.size(); ++r)
    check_fit_record(records[r], fmt::format("records[{}]", r), {.min_samples = 2});
}

FitReport weight_fit_report(std::string_view name, std::string method, const OffsetNnls& solution,
                            std::size_t parameters, std::span<const double> measured,
                            std::span<const double> predicted) {
  FitReport report;
  report.model = std::string(name);
  report.method = std::move(method);
  report.termination = solution.nnls.termination;
  std::size_t zero = 0;
  for (Eigen::Index j = 0; j < solution.x.size(); ++j)
    zero += solution.x[j] == 0.0 ? 1 : 0;
  report.message = fmt::format(
      "{}; {} of {} unknowns at their lower bound",
      solution.nnls.converged()
          ? fmt::format("KKT conditions hold within tolerance {:.3g}", solution.nnls.tolerance)
          : solution.nnls.message,
      zero, solution.x.size());
  report.iterations = solution.nnls.iterations;
  report.parameters = parameters;
  report.final_cost = half_sum_of_squares(measured, predicted);
  report.initial_cost = best_constant_cost(measured);
  report.fit = error_metrics(measured, predicted);
  return report;
}

}  // namespace hyst::detail
