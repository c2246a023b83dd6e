#include "hyst/identify/fit_butterfly_strain_creep.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Core>

#include "butterfly_relay_design.hpp"
#include "creep_regressors.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/error_metrics.hpp"
#include "strain_map_fit.hpp"
#include "weight_fit.hpp"

namespace hyst {
namespace {
// Named, so that a unity build can join this file with the other fits.
namespace butterfly_creep_fit {

using Clock = std::chrono::steady_clock;
constexpr std::string_view kFit = "butterfly strain with creep fit";
constexpr double kSmoothings[] = {0.01, 0.03, 0.1, 0.3, 1.0};

void check_options(const ButterflyCreepFitOptions& options) {
  detail::check_creep_sample_time(options.sample_time, kFit);
  if (options.rounds < 1 || options.rounds > 50) {
    throw Error(fmt::format("{}: rounds = {} must be in [1, 50]", kFit, options.rounds), "rounds");
  }
  if (options.creep_thresholds.empty() && options.creep_operators < 1) {
    throw Error(fmt::format("{}: creep_operators must be >= 1", kFit), "creep_operators");
  }
  if (const auto smoothing = options.law_smoothing;
      smoothing && !(std::isfinite(*smoothing) && *smoothing >= 0.0 && *smoothing <= 1e6)) {
    throw Error(
        fmt::format("{}: law_smoothing = {} must be finite and in [0, 1e6]", kFit, *smoothing),
        "law_smoothing");
  }
}

// The fits from the strain alone cannot see a leakage charge.
void check_direct(const ButterflyCreepFitOptions& options) {
  check_options(options);
  if (options.fit_leakage || options.switching.fit_leakage) {
    throw Error(fmt::format("{}: a leakage charge strains nothing and cannot be fitted from the "
                            "strain: it needs the measured polarisation (Python "
                            "hyst.fit_butterfly_strain_creep_with_polarisation)",
                            kFit),
                "fit_leakage");
  }
}

// What step 2 works on: the fit part's input, strain, switching polarisation and lags.
struct CreepProblem {
  Eigen::VectorXd input;
  Eigen::VectorXd output;
  Eigen::VectorXd switching;  // P_s
  Eigen::MatrixXd lags;       // Z: z_ij of every sample, row-major (tau_i by r_j) per row
  Eigen::MatrixXd penalty;    // D at unit slope, or no rows
  std::size_t degree = 2;
  bool field_term = true;
};

struct CreepSolution {
  Eigen::VectorXd weights;  // c
  Eigen::VectorXd map;      // [y_off, d, q_1 .. q_N]
  double cost = std::numeric_limits<double>::infinity();
  std::size_t iterations = 0;  // NNLS iterations of every round
  NnlsResult last;
};

Eigen::VectorXd strain_of(const Eigen::VectorXd& input, const Eigen::VectorXd& polarisation,
                          const Eigen::VectorXd& map) {
  Eigen::VectorXd y = Eigen::VectorXd::Constant(input.size(), map[0]) + map[1] * input;
  Eigen::VectorXd power = Eigen::VectorXd::Ones(input.size());
  for (Eigen::Index n = 2; n < map.size(); ++n) {
    power.array() *= polarisation.array();
    y += map[n] * power;
  }
  return y;
}

Eigen::VectorXd slope_of(const Eigen::VectorXd& polarisation, const Eigen::VectorXd& map) {
  Eigen::VectorXd slope = Eigen::VectorXd::Zero(polarisation.size());
  Eigen::VectorXd power = Eigen::VectorXd::Ones(polarisation.size());
  for (Eigen::Index n = 2; n < map.size(); ++n) {
    slope += static_cast<double>(n - 1) * map[n] * power;
    power.array() *= polarisation.array();
  }
  return slope;
}

// Step 2 on the first `rows` samples: Gauss-Newton rounds of NNLS on c and least squares on the
// map, from c = 0 and the switching fit's map; the round of least strain error kept.
CreepSolution solve_creep(const CreepProblem& problem, const Eigen::VectorXd& start_map,
                          double smoothing, Eigen::Index rows, std::size_t rounds) {
  const auto v = problem.input.head(rows);
  const auto y = problem.output.head(rows);
  const auto Ps = problem.switching.head(rows);
  const auto Z = problem.lags.topRows(rows);
  // The penalty is scaled to the rows fitted, as the columns' norms are.
  const double rows_share =
      std::sqrt(static_cast<double>(rows) / static_cast<double>(problem.output.size()));
  CreepSolution best;
  CreepSolution current{Eigen::VectorXd::Zero(Z.cols()), start_map, 0.0, 0, {}};
  for (std::size_t round = 0; round < rounds; ++round) {
    const Eigen::VectorXd P0 = Ps + Z * current.weights;
    const Eigen::VectorXd slope = slope_of(P0, current.map);
    Eigen::MatrixXd A = slope.asDiagonal() * Z;
    const Eigen::VectorXd b = y - strain_of(v, P0, current.map) + A * current.weights;
    const double slope_rms = std::sqrt(slope.squaredNorm() / static_cast<double>(rows));
    const Eigen::MatrixXd penalty = smoothing * slope_rms * rows_share * problem.penalty;
    auto solved = detail::nnls_with_offset(std::move(A), b, false, penalty);
    current.weights = solved.x;
    current.iterations += solved.nnls.iterations;
    current.last = solved.nnls;
    const Eigen::VectorXd P = Ps + Z * current.weights;
    current.map = detail::fit_map(v, P, y, problem.degree, problem.field_term).coefficients;
    current.cost = 0.5 * (strain_of(v, P, current.map) - y).squaredNorm();
    if (current.cost < best.cost) best = current;
  }
  best.iterations = current.iterations;
  return best;
}

// The smoothing of the law, when not given: step 2 on the first `train_rows` samples (one
// record: its first 70 %; several: every record but the last), scored on the rest; `method`
// gains the choice.
double choose_smoothing(const CreepProblem& problem, const Eigen::VectorXd& start_map,
                        std::size_t rounds, Eigen::Index train_rows, std::string_view held_out,
                        std::string& method) {
  const Eigen::Index rows = problem.output.size();
  const Eigen::Index cut = train_rows;
  double best = 0.1;
  double best_rmse = std::numeric_limits<double>::infinity();
  if (cut >= problem.lags.cols() + 2 && rows - cut >= 1) {
    for (const double smoothing : kSmoothings) {
      const auto solved = solve_creep(problem, start_map, smoothing, cut, rounds);
      const Eigen::Index rest = rows - cut;
      const Eigen::VectorXd P =
          problem.switching.tail(rest) + problem.lags.bottomRows(rest) * solved.weights;
      const double rmse =
          std::sqrt((strain_of(problem.input.tail(rest), P, solved.map) - problem.output.tail(rest))
                        .squaredNorm() /
                    static_cast<double>(rest));
      if (rmse < best_rmse) {
        best_rmse = rmse;
        best = smoothing;
      }
    }
  }
  method += std::isfinite(best_rmse)
                ? fmt::format(
                      ", logarithmic creep law (smoothing {} chosen by forward validation "
                      "on {}: RMSE {:.4g})",
                      best, held_out, best_rmse)
                : std::string(
                      ", logarithmic creep law (smoothing 0.1: too few samples to "
                      "choose one)");
  return best;
}

// One record as the fit sees it: its whole input (for the periodic start), the fitted part and
// its strain, and its sample time.
struct CreepRecord {
  std::span<const double> whole_input;
  std::span<const double> input;
  std::span<const double> output;
  double sample_time = 1.0;
};

bool periodic_start(const ButterflyCreepFitOptions& options) {
  return options.switching.start == ButterflyFitStart::periodic;
}

// The state `model` (at the record's sample time) starts `record` from.
ButterflyStrainCreep::State start_of(const ButterflyStrainCreep& model, const CreepRecord& record,
                                     bool periodic) {
  return periodic ? model.periodic_state(record.whole_input) : model.initial_state();
}

// The creep structure (thresholds and time constants from the options and the records) and
// the regressors its law's penalty is scaled by.
detail::CreepRegressors creep_structure(std::span<const CreepRecord> records,
                                        const ButterflyCreepFitOptions& options) {
  std::vector<FitRecord> fitted;
  std::vector<double> sample_times;
  for (const auto& record : records) {
    fitted.push_back({record.input, record.output});
    sample_times.push_back(record.sample_time);
  }
  detail::CreepStructureOptions structure_options;
  structure_options.operators = options.creep_operators;
  structure_options.thresholds = options.creep_thresholds;
  structure_options.lags = options.lags;
  structure_options.time_constants = options.time_constants;
  structure_options.sample_time = sample_times.front();
  structure_options.sample_times = sample_times;
  structure_options.initial_state = periodic_start(options) ? PiFitOptions::InitialState::periodic
                                                            : PiFitOptions::InitialState::virgin;
  structure_options.creep_law = options.creep_law;
  structure_options.lags_per_decade = options.lags_per_decade;
  structure_options.longest_time_constant = options.longest_time_constant;
  auto regressors = detail::creep_regressors(fitted, structure_options, kFit);
  if (regressors.structure.lags() == 0) {
    throw Error(fmt::format("{}: no creep lags (give time_constants or lags >= 1)", kFit), "lags");
  }
  return regressors;
}

// Z: the lags z_ij of every record's samples (row-major per row, as the creep weights), each
// record at its sample time from its start.
Eigen::MatrixXd lag_columns(std::span<const CreepRecord> records,
                            const PrandtlIshlinskiiCreep& structure, bool periodic) {
  Eigen::Index rows = 0;
  for (const auto& record : records)
    rows += static_cast<Eigen::Index>(record.input.size());
  const auto columns = static_cast<Eigen::Index>(structure.size() * structure.lags());
  Eigen::MatrixXd Z(rows, columns);
  Eigen::Index row = 0;
  for (const auto& record : records) {
    const auto lags = structure.at_sample_time(record.sample_time);
    auto state = periodic ? lags.periodic_state(record.whole_input) : lags.initial_state();
    for (double v : record.input) {
      lags.step(state, v);
      Z.row(row++) = Eigen::Map<const Eigen::RowVectorXd>(state.creep.data(), columns);
    }
  }
  return Z;
}

// Steps 2 and the assembly of the model, after step 1 gave `switching` (switching part and
// map); `report` gets the method, costs and the fit metrics over every record.
ButterflyStrainCreep fit_creep(std::span<const CreepRecord> records,
                               const ButterflyStrain& switching, const FitReport& switching_report,
                               const ButterflyCreepFitOptions& options, FitReport& report) {
  const bool periodic = periodic_start(options);
  const auto regressors = creep_structure(records, options);
  const PrandtlIshlinskiiCreep& structure = regressors.structure;
  const auto creep_columns = static_cast<Eigen::Index>(structure.size() * structure.lags());
  Eigen::Index rows = 0;
  for (const auto& record : records)
    rows += static_cast<Eigen::Index>(record.input.size());

  CreepProblem problem;
  problem.input.resize(rows);
  problem.output.resize(rows);
  problem.switching.resize(rows);
  problem.lags = lag_columns(records, structure, periodic);
  const auto& polarisation_model = switching.polarisation_model();
  Eigen::Index row = 0;
  for (const auto& record : records) {
    auto p_state =
        periodic ? switching.periodic_state(record.whole_input) : switching.initial_state();
    for (std::size_t k = 0; k < record.input.size(); ++k, ++row) {
      const double v = record.input[k];
      problem.input[row] = v;
      problem.output[row] = record.output[k];
      problem.switching[row] = polarisation_model.step(p_state, v);
    }
  }
  problem.penalty = options.creep_law == CreepLaw::logarithmic
                        ? detail::creep_law_penalty(regressors, creep_columns, 1.0, 0)
                        : Eigen::MatrixXd(0, creep_columns);
  problem.degree = options.switching.degree;
  problem.field_term = options.switching.fit_field_term;

  const auto& sp = switching.params();
  Eigen::VectorXd start_map(2 + static_cast<Eigen::Index>(sp.polarisation_coefficients.size()));
  start_map[0] = sp.offset;
  start_map[1] = sp.field_coefficient;
  for (std::size_t q = 0; q < sp.polarisation_coefficients.size(); ++q)
    start_map[2 + static_cast<Eigen::Index>(q)] = sp.polarisation_coefficients[q];

  report.method = fmt::format(
      "{}, then creep weights by {} Gauss-Newton rounds of nnls (Lawson-Hanson) alternated "
      "with linear least squares on the map",
      switching_report.method, options.rounds);
  double smoothing = 0.0;
  if (options.creep_law == CreepLaw::logarithmic) {
    const bool one = records.size() == 1;
    const Eigen::Index train =
        one ? rows * 7 / 10 : rows - static_cast<Eigen::Index>(records.back().input.size());
    smoothing = options.law_smoothing
                    ? *options.law_smoothing
                    : choose_smoothing(problem, start_map, options.rounds, train,
                                       one ? "the last 30 % of the record" : "the last record",
                                       report.method);
  }
  const auto creep = solve_creep(problem, start_map, smoothing, rows, options.rounds);

  ButterflyStrainCreep::Params params;
  params.butterfly = sp;
  params.butterfly.offset = creep.map[0];
  params.butterfly.field_coefficient = creep.map[1];
  params.butterfly.polarisation_coefficients.assign(creep.map.data() + 2,
                                                    creep.map.data() + creep.map.size());
  params.creep_thresholds = structure.params().thresholds;
  params.time_constants = structure.params().time_constants;
  params.creep_weights.assign(creep.weights.data(), creep.weights.data() + creep.weights.size());
  params.sample_time = records.front().sample_time;
  ButterflyStrainCreep model(std::move(params));

  report.model = "butterfly_strain_creep";
  report.termination = creep.last.termination;
  report.message =
      fmt::format("switching part: {}; creep: {}", switching_report.message, creep.last.message);
  report.iterations = switching_report.iterations + creep.iterations;
  report.parameters = switching_report.parameters + static_cast<std::size_t>(creep_columns);
  std::vector<double> measured;
  std::vector<double> predicted;
  for (const auto& record : records) {
    const auto discretised = model.at_sample_time(record.sample_time);
    auto state = start_of(discretised, record, periodic);
    const auto y = simulate(discretised, state, record.input);
    predicted.insert(predicted.end(), y.begin(), y.end());
    measured.insert(measured.end(), record.output.begin(), record.output.end());
  }
  report.initial_cost = detail::best_constant_cost(measured);
  report.final_cost = detail::half_sum_of_squares(measured, predicted);
  report.fit = error_metrics(measured, predicted);
  return model;
}

ButterflyFitOptions switching_options_of(const ButterflyCreepFitOptions& options) {
  ButterflyFitOptions switching = options.switching;
  switching.validate_fraction = options.validate_fraction;
  switching.sample_time = options.sample_time;
  switching.progress = options.progress;
  return switching;
}

ButterflyCreepFit fit_one(std::span<const double> input, std::span<const double> output,
                          const ButterflyCreepFitOptions& options) {
  const auto begin = Clock::now();
  check_direct(options);
  // Step 1 (it checks the data and options of the switching part).
  const auto switching = fit_butterfly_strain(input, output, switching_options_of(options));
  const auto parts = detail::split_record(input, output, options.validate_fraction, kFit, 2);
  const CreepRecord record{input, parts.fit_input, parts.fit_output, options.sample_time};
  FitReport report;
  auto model = fit_creep(std::span(&record, 1), switching.model, switching.report, options, report);
  auto initial_state = start_of(model, record, periodic_start(options));
  if (!parts.validation_input.empty()) {
    auto state = initial_state;
    simulate(model, state, parts.fit_input);
    report.validation =
        error_metrics(parts.validation_output, simulate(model, state, parts.validation_input));
  }
  report.seconds = std::chrono::duration<double>(Clock::now() - begin).count();
  return {std::move(model), std::move(initial_state), std::move(report)};
}

ButterflyCreepFit fit_many(std::span<const FitRecord> records,
                           const ButterflyCreepFitOptions& options) {
  const auto begin = Clock::now();
  check_direct(options);
  detail::check_several_records(records, options.validate_fraction, kFit);
  if (!options.sample_times.empty() && options.sample_times.size() != records.size()) {
    throw Error(fmt::format("{}: {} sample times for {} records", kFit, options.sample_times.size(),
                            records.size()),
                "sample_times");
  }
  std::vector<CreepRecord> views;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const double ts = options.sample_times.empty() ? options.sample_time : options.sample_times[r];
    detail::check_creep_sample_time(ts, kFit);
    views.push_back({records[r].input, records[r].input, records[r].output, ts});
  }
  // Step 1 on every record together (the switching part has no time in it).
  const auto switching = fit_butterfly_strain(records, switching_options_of(options));
  FitReport report;
  auto model = fit_creep(views, switching.model, switching.report, options, report);
  auto initial_state = start_of(model, views.front(), periodic_start(options));
  report.seconds = std::chrono::duration<double>(Clock::now() - begin).count();
  return {std::move(model), std::move(initial_state), std::move(report)};
}

// The measured polarisation P_m = P_s + C + L of `model` from `state` (advanced) over `input`.
std::vector<double> measured_polarisation(const ButterflyStrainCreep& model,
                                          ButterflyStrainCreep::State& state,
                                          std::span<const double> input) {
  std::vector<double> P;
  P.reserve(input.size());
  for (double v : input) {
    model.step(state, v);
    P.push_back(model.measured_polarisation(state));
  }
  return P;
}

ButterflyCreepTwoStageFit fit_with_polarisation(std::span<const double> input,
                                                std::span<const double> polarisation,
                                                std::span<const double> output,
                                                const ButterflyCreepFitOptions& options) {
  const auto begin = Clock::now();
  check_options(options);
  const auto split =
      detail::split_with_polarisation(input, polarisation, output, options.validate_fraction, kFit);
  const auto& parts = split.strain;
  const auto& p_parts = split.polarisation;
  const bool periodic = periodic_start(options);
  const detail::ButterflyRecordView p_view{input, parts.fit_input, p_parts.fit_output};
  const Preisach::Params grid =
      detail::butterfly_unit_grid(std::span(&p_view, 1), options.switching);
  const auto design =
      detail::butterfly_relay_design(std::span(&p_view, 1), grid, options.switching.start);
  const CreepRecord p_record{input, parts.fit_input, p_parts.fit_output, options.sample_time};
  const auto regressors = creep_structure(std::span(&p_record, 1), options);
  const PrandtlIshlinskiiCreep& structure = regressors.structure;
  const Eigen::MatrixXd Z = lag_columns(std::span(&p_record, 1), structure, periodic);

  // Stage 1: P_m = offset + relays mu + Z c (+ g Q + i0 t) by one NNLS, the law's penalty on c.
  const Eigen::Index m = design.relays.cols();
  const Eigen::Index nz = Z.cols();
  const Eigen::Index leak = options.fit_leakage ? 3 : 0;
  const Eigen::Index rows = Z.rows();
  if (rows < m + nz + leak + 2) {
    throw Error(
        fmt::format("{}: {} samples, fewer than unknowns + 2 = {}", kFit, rows, m + nz + leak + 2));
  }
  Eigen::MatrixXd columns(rows, m + nz + leak);
  columns << design.relays, Z;
  if (options.fit_leakage) {
    const FitRecord fitted{parts.fit_input, p_parts.fit_output};
    columns.rightCols(3) =
        detail::leakage_columns(std::span(&fitted, 1), std::span(&options.sample_time, 1), rows);
  }
  const auto solve_stage1 = [&](Eigen::Index fitted_rows, double smoothing) {
    const double share = std::sqrt(static_cast<double>(fitted_rows) / static_cast<double>(rows));
    const Eigen::MatrixXd penalty =
        options.creep_law == CreepLaw::logarithmic
            ? Eigen::MatrixXd(share *
                              detail::creep_law_penalty(regressors, columns.cols(), smoothing, m))
            : Eigen::MatrixXd(0, columns.cols());
    return detail::nnls_with_offset(columns.topRows(fitted_rows), design.output.head(fitted_rows),
                                    true, penalty);
  };
  std::string p_method = "nnls (Lawson-Hanson) on relay, creep";
  p_method += options.fit_leakage ? " and leakage weights" : " weights";
  double smoothing = options.law_smoothing.value_or(0.1);
  if (options.creep_law == CreepLaw::logarithmic && !options.law_smoothing) {
    const Eigen::Index cut = rows * 7 / 10;
    double best_rmse = std::numeric_limits<double>::infinity();
    for (const double candidate : kSmoothings) {
      const auto solved = solve_stage1(cut, candidate);
      const Eigen::VectorXd predicted = columns.bottomRows(rows - cut) * solved.x +
                                        Eigen::VectorXd::Constant(rows - cut, solved.offset);
      const double rmse = std::sqrt((predicted - design.output.tail(rows - cut)).squaredNorm() /
                                    static_cast<double>(rows - cut));
      if (rmse < best_rmse) {
        best_rmse = rmse;
        smoothing = candidate;
      }
    }
    p_method += fmt::format(
        ", logarithmic creep law (smoothing {} chosen by forward validation on the last 30 % of "
        "the polarisation: RMSE {:.4g})",
        smoothing, best_rmse);
  }
  const auto stage1 = solve_stage1(rows, smoothing);

  // Stage 2: the map on the model's polarisation without the leakage charge.
  const Eigen::VectorXd P_model = design.relays * stage1.x.head(m) + Z * stage1.x.segment(m, nz) +
                                  Eigen::VectorXd::Constant(rows, stage1.offset);
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(parts.fit_output.data(), rows);
  const auto map = detail::fit_map(design.input, P_model, y, options.switching.degree,
                                   options.switching.fit_field_term);

  ButterflyStrainCreep::Params params;
  params.butterfly.polarisation = grid;
  params.butterfly.polarisation.initial_state =
      detail::butterfly_preisach_start(options.switching.start);
  params.butterfly.polarisation.everett.weights.assign(stage1.x.data(), stage1.x.data() + m);
  params.butterfly.polarisation.offset = stage1.offset;
  params.butterfly.offset = map.coefficients[0];
  params.butterfly.field_coefficient = map.coefficients[1];
  params.butterfly.polarisation_coefficients.assign(
      map.coefficients.data() + 2, map.coefficients.data() + map.coefficients.size());
  params.creep_thresholds = structure.params().thresholds;
  params.time_constants = structure.params().time_constants;
  params.creep_weights.assign(stage1.x.data() + m, stage1.x.data() + m + nz);
  params.sample_time = options.sample_time;
  if (options.fit_leakage) {
    params.leakage_conductance = stage1.x[m + nz];
    params.leakage_current = stage1.x[m + nz + 1] - stage1.x[m + nz + 2];
  }
  ButterflyStrainCreep model(std::move(params));
  const CreepRecord record{input, parts.fit_input, parts.fit_output, options.sample_time};
  auto initial_state = start_of(model, record, periodic);

  const auto parameter_count = static_cast<std::size_t>(m + nz) + 1 + (options.fit_leakage ? 2 : 0);
  auto p_state = initial_state;
  FitReport polarisation_report = detail::weight_fit_report(
      "butterfly_strain_creep_polarisation", p_method, stage1, parameter_count, p_parts.fit_output,
      measured_polarisation(model, p_state, parts.fit_input));
  if (!p_parts.validation_input.empty()) {
    polarisation_report.validation = error_metrics(
        p_parts.validation_output, measured_polarisation(model, p_state, p_parts.validation_input));
  }
  FitReport report;
  report.model = "butterfly_strain_creep";
  report.method = "two stages: " + p_method +
                  " on the measured polarisation, linear least squares on y(v, P) with the "
                  "model's P (without the leakage charge)";
  report.termination = stage1.nnls.termination;
  report.message = stage1.nnls.message;
  report.iterations = stage1.nnls.iterations;
  report.parameters =
      parameter_count + options.switching.degree + 1 + (options.switching.fit_field_term ? 1 : 0);
  auto state = initial_state;
  const auto predicted = simulate(model, state, parts.fit_input);
  report.initial_cost = detail::best_constant_cost(parts.fit_output);
  report.final_cost = detail::half_sum_of_squares(parts.fit_output, predicted);
  report.fit = error_metrics(parts.fit_output, predicted);
  if (!parts.validation_input.empty()) {
    report.validation =
        error_metrics(parts.validation_output, simulate(model, state, parts.validation_input));
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
  report.seconds = seconds;
  polarisation_report.seconds = seconds;
  return {{std::move(model), std::move(initial_state), std::move(report)},
          std::move(polarisation_report)};
}

}  // namespace butterfly_creep_fit
}  // namespace

ButterflyCreepFit fit_butterfly_strain_creep(std::span<const double> input,
                                             std::span<const double> output,
                                             const ButterflyCreepFitOptions& options) {
  return butterfly_creep_fit::fit_one(input, output, options);
}

ButterflyCreepFit fit_butterfly_strain_creep(std::span<const FitRecord> records,
                                             const ButterflyCreepFitOptions& options) {
  return butterfly_creep_fit::fit_many(records, options);
}

ButterflyCreepTwoStageFit fit_butterfly_strain_creep_with_polarisation(
    std::span<const double> input, std::span<const double> polarisation,
    std::span<const double> output, const ButterflyCreepFitOptions& options) {
  return butterfly_creep_fit::fit_with_polarisation(input, polarisation, output, options);
}

}  // namespace hyst
