#include "hyst/identify/fit_modified_prandtl_ishlinskii_creep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "creep_regressors.hpp"
#include "dead_zone_slopes.hpp"
#include "detail/convergence.hpp"
#include "detail/multistart_fit.hpp"
#include "detail/regressor_matrix.hpp"
#include "hyst/core/error.hpp"
#include "weight_fit.hpp"

namespace hyst {
namespace modified_creep_fit {

constexpr std::string_view kFit = "modified PI with creep fit";
constexpr std::string_view kName = "modified_pi_creep";

void check_options(const ModifiedPiCreepFitOptions& options) {
  if (!std::isfinite(options.min_weight) || !(options.min_weight > 0.0)) {
    throw Error(fmt::format("{}: min_weight = {} must be finite and > 0", kFit, options.min_weight),
                "min_weight");
  }
  if (!std::isfinite(options.output_margin) || options.output_margin < 0.0) {
    throw Error(
        fmt::format("{}: output_margin = {} must be finite and >= 0", kFit, options.output_margin),
        "output_margin");
  }
  if (options.output_error_iterations > ModifiedPiCreepFitOptions::kMaxIterations) {
    throw Error(
        fmt::format("{}: output_error_iterations = {} exceeds the limit {}", kFit,
                    options.output_error_iterations, ModifiedPiCreepFitOptions::kMaxIterations),
        "output_error_iterations");
  }
  detail::check_creep_sample_time(options.sample_time, kFit);
}

// The output error of the model over the regressor rows, as a function of
// theta = [p_j, c_ij, q, t_i]: y_off + S(q + A [p; c]) - y, S written through its slopes t_i
// (dead_zone_slopes.hpp, thresholds fixed). The clamp is left out: its limits are the fitted
// outputs' range.
class OutputErrorCost final : public ceres::CostFunction {
 public:
  OutputErrorCost(const Eigen::MatrixXd& columns, std::span<const double> output, double offset,
                  const detail::DeadZoneSlopes& map)
      : columns_(columns), output_(output), offset_(offset), map_(map) {
    set_num_residuals(static_cast<int>(columns.rows()));
    mutable_parameter_block_sizes()->push_back(
        static_cast<int>(columns.cols() + 1 + static_cast<Eigen::Index>(map.unknowns())));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Index rows = columns_.rows();
    const Eigen::Index weights = columns_.cols();
    const auto slopes = static_cast<Eigen::Index>(map_.unknowns());
    const Eigen::Map<const Eigen::VectorXd> theta(parameters[0], weights + 1 + slopes);
    const std::span<const double> t(parameters[0] + weights + 1, static_cast<std::size_t>(slopes));
    const Eigen::VectorXd x = (columns_ * theta.head(weights)).array() + theta[weights];
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    std::vector<double> terms(static_cast<std::size_t>(slopes));
    for (Eigen::Index k = 0; k < rows; ++k) {
      double value = map_.terms(x[k], terms);
      for (Eigen::Index i = 0; i < slopes; ++i)
        value += terms[static_cast<std::size_t>(i)] * t[static_cast<std::size_t>(i)];
      residuals[k] = offset_ + value - output_[static_cast<std::size_t>(k)];
      if (jacobians && jacobians[0]) {
        Eigen::Map<RowMajor> J(jacobians[0], rows, weights + 1 + slopes);
        const double slope = map_.slope(x[k], t);
        J.row(k).head(weights) = slope * columns_.row(k);
        J(k, weights) = slope;
        for (Eigen::Index i = 0; i < slopes; ++i)
          J(k, weights + 1 + i) = terms[static_cast<std::size_t>(i)];
      }
    }
    return true;
  }

 private:
  const Eigen::MatrixXd& columns_;
  std::span<const double> output_;
  double offset_;
  const detail::DeadZoneSlopes& map_;
};

struct Refined {
  ModifiedPrandtlIshlinskiiCreep::Params params;
  Termination termination = Termination::failed;
  std::string message;
  std::size_t iterations = 0;
};

// Bounded Levenberg-Marquardt on the output error from the equation-error solution `start`:
// p_0 >= eps_p, p_j >= 0, c_ij >= 0, every slope of S >= eps; the thresholds stay.
Refined refine_output_error(const ModifiedPrandtlIshlinskiiCreep::Params& start,
                            const detail::CreepRegressors& regressors, double eps_p,
                            const ModifiedPiCreepFitOptions& options) {
  const detail::DeadZoneSlopes map(start.dead_zone.thresholds, options.min_weight);
  const auto& core = start.pi_creep;
  const std::size_t weights = core.weights.size() + core.creep_weights.size();
  std::vector<double> theta(core.weights);
  theta.insert(theta.end(), core.creep_weights.begin(), core.creep_weights.end());
  theta.push_back(core.offset);
  const auto t = map.unknowns_of(DeadZoneSuperposition(start.dead_zone));
  theta.insert(theta.end(), t.begin(), t.end());

  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  problem.AddResidualBlock(
      new OutputErrorCost(regressors.columns, regressors.outputs, start.offset, map), nullptr,
      theta.data());
  for (std::size_t i = 0; i < theta.size(); ++i) {
    if (i == weights) continue;  // q is free
    problem.SetParameterLowerBound(theta.data(), static_cast<int>(i), i == 0 ? eps_p : 0.0);
  }
  auto solver = detail::levenberg_marquardt_options(options.output_error_iterations,
                                                    detail::kFunctionTolerance);
  detail::StagnationStop stagnation;
  solver.callbacks.push_back(&stagnation);
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);

  Refined refined{start, detail::termination_of_ceres(summary), summary.message,
                  summary.iterations.size()};
  if (stagnation.stopped()) {
    refined.termination = Termination::converged;
    refined.message = stagnation.message();
  }
  if (!summary.IsSolutionUsable() ||
      !std::all_of(theta.begin(), theta.end(), [](double v) { return std::isfinite(v); })) {
    refined.termination = Termination::failed;
    return refined;  // the equation-error solution stands
  }
  auto& p = refined.params.pi_creep;
  const std::size_t n = p.weights.size();
  std::copy_n(theta.begin(), n, p.weights.begin());
  std::copy_n(theta.begin() + static_cast<std::ptrdiff_t>(n), weights - n, p.creep_weights.begin());
  p.offset = theta[weights];
  refined.params.dead_zone =
      map.map(std::span(theta.data() + weights + 1, map.unknowns())).params();
  return refined;
}

struct Solved {
  ModifiedPrandtlIshlinskiiCreep model;
  detail::OffsetNnls solution;
  std::size_t parameters = 0;
  std::vector<double> sample_times;  // of each record
  std::vector<double> outputs;       // every record's output, joined
  std::optional<Refined> refined;    // the output-error stage, when it ran
};

// One NNLS on [w_j, z_ij, slopes of S'] with the equation error S'(y - y_off) - Gamma_c[v], then
// the output-error refinement.
Solved solve(std::span<const FitRecord> records, const ModifiedPiCreepFitOptions& options) {
  auto regressors =
      detail::creep_regressors(records, detail::creep_structure_options(options), kFit);
  const auto& outputs = regressors.outputs;
  const auto [y_min, y_max] = std::minmax_element(outputs.begin(), outputs.end());
  const double y_off = options.output_offset.value_or(0.5 * (*y_min + *y_max));
  if (!std::isfinite(y_off)) {
    throw Error(fmt::format("{}: output_offset = {} is not finite", kFit, y_off), "output_offset");
  }
  // The inverse map S', linear in its slopes.
  const detail::DeadZoneSlopes inverse_map(
      options.dead_zone_thresholds.empty() ? detail::DeadZoneSlopes::default_thresholds(
                                                 options.dead_zones, y_off - *y_min, *y_max - y_off)
                                           : options.dead_zone_thresholds,
      options.min_weight);
  const Eigen::Index rows = regressors.columns.rows();
  const Eigen::Index creep_columns = regressors.columns.cols();
  const auto slopes = static_cast<Eigen::Index>(inverse_map.unknowns());
  if (rows < creep_columns + slopes + 2) {
    throw Error(fmt::format("{}: {} samples, fewer than unknowns + 2 = {}", kFit, rows,
                            creep_columns + slopes + 2));
  }
  const double eps_p =
      options.min_weight * detail::range_of(outputs) / detail::range_of(regressors.inputs);
  Eigen::MatrixXd A = detail::regressor_matrix(rows, creep_columns + slopes, kFit);
  A.leftCols(creep_columns) = regressors.columns;
  Eigen::VectorXd b(rows);
  std::vector<double> slope_terms(static_cast<std::size_t>(slopes));
  for (Eigen::Index k = 0; k < rows; ++k) {
    b[k] = inverse_map.terms(outputs[static_cast<std::size_t>(k)] - y_off, slope_terms) -
           eps_p * A(k, 0);
    A.row(k).tail(slopes) = -Eigen::Map<const Eigen::RowVectorXd>(slope_terms.data(), slopes);
  }
  auto solution = detail::nnls_with_offset(std::move(A), std::move(b), true);

  const std::size_t n = regressors.structure.size();
  ModifiedPrandtlIshlinskiiCreep::Params params;
  params.pi_creep = regressors.structure.params();
  params.pi_creep.weights.assign(solution.x.data(), solution.x.data() + n);
  params.pi_creep.weights[0] += eps_p;
  params.pi_creep.creep_weights.assign(solution.x.data() + n, solution.x.data() + creep_columns);
  params.pi_creep.offset = solution.offset;
  params.dead_zone =
      inverse_map
          .map(std::span(solution.x.data() + creep_columns, static_cast<std::size_t>(slopes)))
          .inverse()
          .params();
  params.offset = y_off;
  std::optional<Refined> refined;
  if (options.output_error_iterations > 0) {
    refined = refine_output_error(params, regressors, eps_p, options);
    params = refined->params;
  }
  if (options.clamp_output) {
    const double margin = options.output_margin * (*y_max - *y_min);
    params.output_min = *y_min - margin;
    params.output_max = *y_max + margin;
  }
  // The weights, the PI offset q and y_off.
  const auto parameters = static_cast<std::size_t>(creep_columns + slopes) + 2;
  return {ModifiedPrandtlIshlinskiiCreep(std::move(params)),
          std::move(solution),
          parameters,
          std::move(regressors.sample_times),
          std::move(regressors.outputs),
          std::move(refined)};
}

// The report of both stages: the NNLS's, then the refinement's termination and iterations.
FitReport report_of(const Solved& solved, std::span<const double> measured,
                    std::span<const double> predicted) {
  FitReport report = detail::weight_fit_report(
      kName, "nnls (Lawson-Hanson) on PI, creep and inverse dead-zone weights, equation error",
      solved.solution, solved.parameters, measured, predicted);
  if (!solved.refined) return report;
  report.method += ", then bounded Levenberg-Marquardt (Ceres) on the output error";
  report.termination = solved.refined->termination;
  report.message =
      fmt::format("equation error: {}; output error: {}", report.message, solved.refined->message);
  report.iterations += solved.refined->iterations;
  return report;
}

}  // namespace modified_creep_fit

ModifiedPiCreepFit fit_modified_prandtl_ishlinskii_creep(std::span<const double> input,
                                                         std::span<const double> output,
                                                         const ModifiedPiCreepFitOptions& options) {
  using namespace modified_creep_fit;
  const auto start = std::chrono::steady_clock::now();
  check_options(options);
  const auto parts = detail::split_record(input, output, options.validate_fraction, kFit, 2);
  const FitRecord record{parts.fit_input, parts.fit_output};
  const auto solved = solve(std::span(&record, 1), options);
  auto state = detail::creep_start_state(solved.model, parts.fit_input, options.initial_state);
  ModifiedPiCreepFit result{solved.model, state, {}};
  result.report =
      report_of(solved, parts.fit_output, simulate(result.model, state, parts.fit_input));
  if (!parts.validation_input.empty()) {
    result.report.validation = error_metrics(parts.validation_output,
                                             simulate(result.model, state, parts.validation_input));
  }
  result.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

ModifiedPiCreepFit fit_modified_prandtl_ishlinskii_creep(std::span<const FitRecord> records,
                                                         const ModifiedPiCreepFitOptions& options) {
  using namespace modified_creep_fit;
  const auto start = std::chrono::steady_clock::now();
  check_options(options);
  detail::check_several_records(records, options.validate_fraction, kFit);
  const auto solved = solve(records, options);
  const auto predicted = detail::simulate_creep_records(solved.model, records, solved.sample_times,
                                                        options.initial_state);
  auto initial_state =
      detail::creep_start_state(solved.model, records.front().input, options.initial_state);
  ModifiedPiCreepFit result{solved.model, std::move(initial_state), {}};
  result.report = report_of(solved, solved.outputs, predicted);
  result.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace hyst
