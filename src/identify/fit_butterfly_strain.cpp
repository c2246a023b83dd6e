#include "hyst/identify/fit_butterfly_strain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <Eigen/Core>
#include <Eigen/QR>

#include "../core/detail/enum_names.hpp"
#include "butterfly_relay_design.hpp"
#include "detail/convergence.hpp"
#include "detail/multistart_driver.hpp"
#include "detail/multistart_fit.hpp"
#include "detail/regressor_matrix.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/data/leakage.hpp"
#include "hyst/identify/error_metrics.hpp"
#include "hyst/models/preisach_relay_grid.hpp"
#include "strain_map_fit.hpp"
#include "weight_fit.hpp"

namespace hyst {
namespace {
// Named, so that a unity build can join this file with the other fits.
namespace butterfly_fit {

using detail::fit_map;
using detail::map_columns;
using detail::MapFit;

using Clock = std::chrono::steady_clock;
constexpr std::string_view kFit = "butterfly strain fit";
constexpr std::size_t kScreeningIterations = 10;  // per start
constexpr std::size_t kRefinedStarts = 3;         // screened starts continued
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void check_options(const ButterflyFitOptions& options) {
  if (options.levels > 64) {
    throw Error(
        fmt::format("{}: levels = {} must be in [1, 64] (or 0: automatic)", kFit, options.levels),
        "levels");
  }
  if (options.degree < 1 || options.degree > 8) {
    throw Error(fmt::format("{}: degree = {} must be in [1, 8]", kFit, options.degree), "degree");
  }
  if (options.max_iterations < 1) {
    throw Error(fmt::format("{}: max_iterations must be >= 1", kFit), "max_iterations");
  }
  if (options.lower && !std::isfinite(*options.lower)) {
    throw Error(fmt::format("{}: lower = {} is not finite", kFit, *options.lower), "lower");
  }
  if (options.upper && !std::isfinite(*options.upper)) {
    throw Error(fmt::format("{}: upper = {} is not finite", kFit, *options.upper), "upper");
  }
}

using RecordView = detail::ButterflyRecordView;

// The state a record starts from, for any Preisach-based model with periodic_state-like replay.
template <class Model>
typename Model::State start_state(const Model& model, std::span<const double> whole_input,
                                  ButterflyFitStart start) {
  auto state = model.make_state(detail::butterfly_preisach_start(start));
  if (start == ButterflyFitStart::periodic) {
    for (double v : whole_input)
      model.step(state, v);
  }
  return state;
}
ButterflyStrain::State start_state(const ButterflyStrain& model,
                                   std::span<const double> whole_input, ButterflyFitStart start) {
  return start_state(model.polarisation_model(), whole_input, start);
}

using Design = detail::ButterflyRelayDesign;

// Residuals y_model[k] - y[k] of the direct form and the scale term (F0 - 1) sigma sqrt(K), with
// the analytic Jacobian. Blocks: relay weights mu (m), map [y_off, d, q_1 .. q_N].
class LatentStrainCost final : public ceres::CostFunction {
 public:
  LatentStrainCost(const Design& design, std::size_t degree, double gauge)
      : design_(design), degree_(static_cast<Eigen::Index>(degree)), gauge_(gauge) {
    set_num_residuals(static_cast<int>(design.output.size() + 1));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(design.relays.cols()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(2 + degree));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Index rows = design_.relays.rows();
    const Eigen::Index m = design_.relays.cols();
    const Eigen::Map<const Eigen::VectorXd> mu(parameters[0], m);
    const double* map = parameters[1];
    const Eigen::VectorXd P = design_.relays * mu;
    Eigen::Map<Eigen::VectorXd> e(residuals, rows + 1);
    Eigen::VectorXd slope(rows);
    for (Eigen::Index k = 0; k < rows; ++k) {
      double value = 0.0;
      double derivative = 0.0;
      for (Eigen::Index n = degree_; n-- > 0;) {
        value = (value + map[2 + n]) * P[k];
        derivative = derivative * P[k] + static_cast<double>(n + 1) * map[2 + n];
      }
      e[k] = map[0] + map[1] * design_.input[k] + value - design_.output[k];
      slope[k] = derivative;
    }
    e[rows] = gauge_ * (mu.sum() - 1.0);
    if (!jacobians) return true;
    if (jacobians[0]) {
      Eigen::Map<RowMajor> J(jacobians[0], rows + 1, m);
      J.topRows(rows) = slope.asDiagonal() * design_.relays;
      J.row(rows).setConstant(gauge_);
    }
    if (jacobians[1]) {
      Eigen::Map<RowMajor> J(jacobians[1], rows + 1, 2 + degree_);
      J.col(0).head(rows).setOnes();
      J.col(1).head(rows) = design_.input;
      Eigen::VectorXd power = Eigen::VectorXd::Ones(rows);
      for (Eigen::Index n = 0; n < degree_; ++n) {
        power.array() *= P.array();
        J.col(2 + n).head(rows) = power;
      }
      J.row(rows).setZero();
    }
    return true;
  }

 private:
  const Design& design_;
  Eigen::Index degree_;
  double gauge_;
};

// A Gaussian density around the coercive voltage v_c (alpha = c + v_c, beta = c - v_c), unit
// total weight.
Eigen::VectorXd coercive_density(const Preisach::Params& grid, double coercive, double width) {
  const auto thresholds = preisach_thresholds(grid.everett.levels, grid.everett.lower,
                                              grid.everett.upper, grid.everett.layout);
  const double centre = 0.5 * (grid.everett.lower + grid.everett.upper);
  Eigen::VectorXd mu(static_cast<Eigen::Index>(grid.everett.weights.size()));
  for (std::size_t i = 0; i < thresholds.size(); ++i) {
    for (std::size_t j = 0; j <= i; ++j) {
      const double half_width = 0.5 * (thresholds[i] - thresholds[j]) - coercive;
      const double bias = 0.5 * (thresholds[i] + thresholds[j]) - centre;
      mu[static_cast<Eigen::Index>(preisach_relay_index(i, j))] =
          std::exp(-0.5 * (half_width * half_width + bias * bias) / (width * width));
    }
  }
  return mu / mu.sum();
}

struct Start {
  Eigen::VectorXd mu;
  Eigen::VectorXd map;
  double residual = 0.0;
};

// The coercive-density starts (file comment of the header), v_c = 0.1, 0.2, ... 0.9 of the
// half range.
std::vector<Start> initial_guesses(const Design& design, const Preisach::Params& grid,
                                   const ButterflyFitOptions& options) {
  const double half = 0.5 * (grid.everett.upper - grid.everett.lower);
  std::vector<Start> starts;
  for (int tenth = 1; tenth <= 9; ++tenth) {
    Eigen::VectorXd mu = coercive_density(grid, 0.1 * tenth * half, 0.15 * half);
    const Eigen::VectorXd P = design.relays * mu;
    MapFit map = fit_map(design.input, P, design.output, options.degree, options.fit_field_term);
    starts.push_back({std::move(mu), std::move(map.coefficients), map.residual});
  }
  return starts;
}

// One Levenberg-Marquardt run of at most `iterations` from `params`, as the multistart engine
// (detail/multistart_driver.hpp) ranks and continues it.
struct Run {
  Start params;
  double cost = std::numeric_limits<double>::infinity();
  bool usable = false;
  bool finished = false;  // converged or stagnated: no continuation
  std::size_t iterations = 0;
  Termination termination = Termination::failed;
  std::string message;
};
Run refine(Start params, const Design& design, const ButterflyFitOptions& options, double gauge,
           std::size_t iterations) {
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  problem.AddResidualBlock(new LatentStrainCost(design, options.degree, gauge), nullptr,
                           params.mu.data(), params.map.data());
  for (Eigen::Index r = 0; r < params.mu.size(); ++r)
    problem.SetParameterLowerBound(params.mu.data(), static_cast<int>(r), 0.0);
  if (!options.fit_field_term) {
    problem.SetManifold(params.map.data(),
                        new ceres::SubsetManifold(static_cast<int>(params.map.size()), {1}));
  }
  auto solver = detail::levenberg_marquardt_options(iterations, detail::kFunctionTolerance);
  detail::StagnationStop stagnation;
  solver.callbacks.push_back(&stagnation);
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  Run run;
  run.params = std::move(params);
  run.cost = summary.final_cost;
  run.usable = summary.IsSolutionUsable() && run.params.mu.allFinite() &&
               run.params.map.allFinite() && run.params.mu.sum() > 0.0;
  run.finished = stagnation.stopped() || summary.termination_type == ceres::CONVERGENCE;
  run.iterations = summary.iterations.size();
  run.termination =
      stagnation.stopped() ? Termination::converged : detail::termination_of_ceres(summary);
  run.message = stagnation.stopped() ? stagnation.message() : summary.message;
  return run;
}

ButterflyStrain model_of(const Preisach::Params& grid, const Eigen::VectorXd& mu,
                         const Eigen::VectorXd& map, ButterflyFitStart start) {
  ButterflyStrain::Params params;
  params.polarisation = grid;
  params.polarisation.initial_state = detail::butterfly_preisach_start(start);
  params.polarisation.everett.weights.assign(mu.data(), mu.data() + mu.size());
  params.offset = map[0];
  params.field_coefficient = map[1];
  params.polarisation_coefficients.assign(map.data() + 2, map.data() + map.size());
  return ButterflyStrain(std::move(params));
}

// Simulates every record from its start and fills the report's costs and fit metrics.
void score(FitReport& report, const ButterflyStrain& model, std::span<const RecordView> records,
           ButterflyFitStart start) {
  std::vector<double> measured;
  std::vector<double> predicted;
  for (const auto& record : records) {
    auto state = start_state(model, record.whole_input, start);
    const auto y = simulate(model, state, record.input);
    measured.insert(measured.end(), record.output.begin(), record.output.end());
    predicted.insert(predicted.end(), y.begin(), y.end());
  }
  report.initial_cost = detail::best_constant_cost(measured);
  report.final_cost = detail::half_sum_of_squares(measured, predicted);
  report.fit = error_metrics(measured, predicted);
}

ButterflyStrain solve_direct(std::span<const RecordView> records,
                             const ButterflyFitOptions& options, FitReport& report) {
  const Preisach::Params grid = detail::butterfly_unit_grid(records, options);
  const Design design = detail::butterfly_relay_design(records, grid, options.start);
  const auto m = design.relays.cols();
  const auto unknowns = static_cast<std::size_t>(m) + options.degree + 2;
  if (static_cast<std::size_t>(design.output.size()) < unknowns + 2) {
    throw Error(fmt::format("{}: {} samples, fewer than unknowns + 2 = {} (use fewer levels)", kFit,
                            design.output.size(), unknowns + 2),
                "levels");
  }
  const double mean = design.output.mean();
  const double sigma = std::sqrt((design.output.array() - mean).square().mean());
  const double gauge = sigma * std::sqrt(static_cast<double>(design.output.size()));
  // The cost is not convex: every start screened by a short run, the best few continued, the
  // lowest cost kept (the multistart engine of every Ceres-based fit).
  const auto starts = initial_guesses(design, grid, options);
  const detail::MultistartBudget budget{.screening_iterations = kScreeningIterations,
                                        .refined_starts = kRefinedStarts,
                                        .max_iterations = options.max_iterations,
                                        .progress = options.progress};
  const auto runs = detail::run_multistart(
      starts.size(), budget,
      [&](std::size_t s, std::size_t iterations) {
        return refine(starts[s], design, options, gauge, iterations);
      },
      [&](const Run& run, std::size_t iterations) {
        return refine(run.params, design, options, gauge, iterations);
      });
  if (!runs.found || !runs.best.usable) {
    throw Error(fmt::format("{}: no start gave a usable solution ({})", kFit,
                            runs.found ? runs.best.message : "every run failed"));
  }
  Start start = runs.best.params;
  // F0 = 1 exactly: P -> P / F0, q_n -> q_n F0^n.
  const double total = start.mu.sum();
  start.mu /= total;
  double power = 1.0;
  for (Eigen::Index n = 2; n < start.map.size(); ++n) {
    power *= total;
    start.map[n] *= power;
  }
  report.model = "butterfly_strain";
  report.method =
      "levenberg-marquardt (ceres) on relay weights and strain map, latent polarisation";
  report.termination = runs.best.termination;
  report.message =
      fmt::format("start {} of {} (coercive voltage {}/10 of the half range): {}",
                  runs.best_start + 1, starts.size(), runs.best_start + 1, runs.best.message);
  report.iterations = runs.iterations;
  report.parameters =
      static_cast<std::size_t>(m) - 1 + options.degree + 1 + (options.fit_field_term ? 1 : 0);
  return model_of(grid, start.mu, start.map, options.start);
}

std::vector<RecordView> views_of(std::span<const FitRecord> records) {
  std::vector<RecordView> views;
  for (const auto& record : records)
    views.push_back({record.input, record.input, record.output});
  return views;
}

// The direct form has no measured polarisation whose leakage could be fitted.
void check_direct(const ButterflyFitOptions& options) {
  check_options(options);
  if (options.fit_leakage) {
    throw Error(
        fmt::format("{}: fit_leakage needs the measured polarisation (the two-stage fit)", kFit),
        "fit_leakage");
  }
}

ButterflyFit fit_one(std::span<const double> input, std::span<const double> output,
                     const ButterflyFitOptions& options) {
  const auto begin = Clock::now();
  check_direct(options);
  const auto parts = detail::split_record(input, output, options.validate_fraction, kFit, 2);
  const RecordView record{input, parts.fit_input, parts.fit_output};
  FitReport report;
  auto model = solve_direct(std::span(&record, 1), options, report);
  score(report, model, std::span(&record, 1), options.start);
  auto initial_state = start_state(model, input, options.start);
  if (!parts.validation_input.empty()) {
    auto state = initial_state;
    simulate(model, state, parts.fit_input);
    report.validation =
        error_metrics(parts.validation_output, simulate(model, state, parts.validation_input));
  }
  report.seconds = std::chrono::duration<double>(Clock::now() - begin).count();
  return {std::move(model), std::move(initial_state), std::move(report)};
}

ButterflyFit fit_many(std::span<const FitRecord> records, const ButterflyFitOptions& options) {
  const auto begin = Clock::now();
  check_direct(options);
  detail::check_several_records(records, options.validate_fraction, kFit);
  const auto views = views_of(records);
  FitReport report;
  auto model = solve_direct(views, options, report);
  score(report, model, views, options.start);
  auto initial_state = start_state(model, views.front().whole_input, options.start);
  report.seconds = std::chrono::duration<double>(Clock::now() - begin).count();
  return {std::move(model), std::move(initial_state), std::move(report)};
}

ButterflyTwoStageFit fit_two_stages(std::span<const double> input,
                                    std::span<const double> polarisation,
                                    std::span<const double> output,
                                    const ButterflyFitOptions& options) {
  const auto begin = Clock::now();
  check_options(options);
  const auto split =
      detail::split_with_polarisation(input, polarisation, output, options.validate_fraction, kFit);
  const auto& parts = split.strain;
  const auto& p_parts = split.polarisation;
  const RecordView p_record{input, parts.fit_input, p_parts.fit_output};
  const RecordView record{input, parts.fit_input, parts.fit_output};
  const Preisach::Params grid = detail::butterfly_unit_grid(std::span(&p_record, 1), options);
  const Design design =
      detail::butterfly_relay_design(std::span(&p_record, 1), grid, options.start);

  // Stage 1: P(v) by NNLS with a free P offset, and the leakage charge's conductance.
  const auto relay_count = design.relays.cols();
  // The leakage charge of the whole record (fit and held-out part), or none.
  const std::vector<double> charge = options.fit_leakage
                                         ? data::leakage_charge(input, options.sample_time)
                                         : std::vector<double>(input.size(), 0.0);
  const Eigen::Map<const Eigen::VectorXd> leakage(charge.data(), design.output.size());
  Eigen::MatrixXd columns = design.relays;
  if (options.fit_leakage) {
    columns.conservativeResize(Eigen::NoChange, relay_count + 1);
    columns.col(relay_count) = leakage;
  }
  auto stage1 = detail::nnls_with_offset(std::move(columns), design.output, true);
  const double conductance = options.fit_leakage ? stage1.x[relay_count] : 0.0;
  ButterflyStrain::Params params;
  params.polarisation = grid;
  params.polarisation.initial_state = detail::butterfly_preisach_start(options.start);
  params.polarisation.everett.weights.assign(stage1.x.data(), stage1.x.data() + relay_count);
  params.polarisation.offset = stage1.offset;
  const Preisach polarisation_model(params.polarisation);
  auto p_state = start_state(polarisation_model, input, options.start);
  const auto initial_state = p_state;
  const auto p_fit = simulate(polarisation_model, p_state, parts.fit_input);
  std::vector<double> p_measured_fit = p_fit;  // the model of the measured P: leakage included
  for (std::size_t k = 0; k < p_fit.size(); ++k)
    p_measured_fit[k] += conductance * charge[k];
  FitReport polarisation_report = detail::weight_fit_report(
      "preisach",
      options.fit_leakage ? "nnls (Lawson-Hanson) on relay weights and leakage conductance"
                          : "nnls (Lawson-Hanson) on relay weights",
      stage1, static_cast<std::size_t>(stage1.x.size()) + 1, p_parts.fit_output, p_measured_fit);
  if (!p_parts.validation_input.empty()) {
    auto p_validation = simulate(polarisation_model, p_state, p_parts.validation_input);
    for (std::size_t k = 0; k < p_validation.size(); ++k)
      p_validation[k] += conductance * charge[parts.fit_input.size() + k];
    polarisation_report.validation = error_metrics(p_parts.validation_output, p_validation);
  }

  // Stage 2: the map on the model's polarisation (the fitted chain) ...
  const Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(
      parts.fit_input.data(), static_cast<Eigen::Index>(parts.fit_input.size()));
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(
      parts.fit_output.data(), static_cast<Eigen::Index>(parts.fit_output.size()));
  const Eigen::VectorXd P_model =
      Eigen::Map<const Eigen::VectorXd>(p_fit.data(), static_cast<Eigen::Index>(p_fit.size()));
  const MapFit chain = fit_map(v, P_model, y, options.degree, options.fit_field_term);
  params.offset = chain.coefficients[0];
  params.field_coefficient = chain.coefficients[1];
  params.polarisation_coefficients.assign(chain.coefficients.data() + 2,
                                          chain.coefficients.data() + chain.coefficients.size());
  ButterflyStrain model(std::move(params));
  FitReport report;
  report.model = "butterfly_strain";
  report.method = "two stages: nnls (Lawson-Hanson) on P(v), linear least squares on y(v, P)";
  report.termination = stage1.nnls.termination;
  report.message = stage1.nnls.message;
  report.iterations = stage1.nnls.iterations;
  report.parameters = static_cast<std::size_t>(stage1.x.size()) + 1 + options.degree + 1 +
                      (options.fit_field_term ? 1 : 0);
  score(report, model, std::span(&record, 1), options.start);
  if (!parts.validation_input.empty()) {
    auto state = initial_state;
    simulate(model, state, parts.fit_input);
    report.validation =
        error_metrics(parts.validation_output, simulate(model, state, parts.validation_input));
  }

  // ... and on the measured polarisation without its leakage charge, scored on its own.
  const Eigen::VectorXd p_measured = design.output - conductance * leakage;
  const MapFit direct = fit_map(v, p_measured, y, options.degree, options.fit_field_term);
  const Eigen::VectorXd mapped =
      map_columns(v, p_measured, options.degree, true) * direct.coefficients;
  const std::vector<double> mapped_samples(mapped.data(), mapped.data() + mapped.size());
  FitReport map_report;
  map_report.model = "butterfly_strain_map";
  map_report.method = "linear least squares on y(v, P) with measured P";
  map_report.termination = Termination::converged;
  map_report.message = "closed-form least-squares solution (column-pivoting QR)";
  map_report.parameters = options.degree + 1 + (options.fit_field_term ? 1 : 0);
  map_report.initial_cost = detail::best_constant_cost(parts.fit_output);
  map_report.final_cost = detail::half_sum_of_squares(parts.fit_output, mapped_samples);
  map_report.fit = error_metrics(parts.fit_output, mapped_samples);

  const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
  report.seconds = seconds;
  polarisation_report.seconds = seconds;
  map_report.seconds = seconds;
  return {{std::move(model), initial_state, std::move(report)},
          std::move(polarisation_report),
          std::move(map_report),
          conductance};
}

}  // namespace butterfly_fit
}  // namespace

ButterflyFitStart butterfly_fit_start_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<ButterflyFitStart>, "butterfly fit start",
                             "initial_state");
}

ButterflyFit fit_butterfly_strain(std::span<const double> input, std::span<const double> output,
                                  const ButterflyFitOptions& options) {
  return butterfly_fit::fit_one(input, output, options);
}

ButterflyFit fit_butterfly_strain(std::span<const FitRecord> records,
                                  const ButterflyFitOptions& options) {
  return butterfly_fit::fit_many(records, options);
}

ButterflyTwoStageFit fit_butterfly_strain_with_polarisation(std::span<const double> input,
                                                            std::span<const double> polarisation,
                                                            std::span<const double> output,
                                                            const ButterflyFitOptions& options) {
  return butterfly_fit::fit_two_stages(input, polarisation, output, options);
}

}  // namespace hyst
