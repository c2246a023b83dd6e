#include "hyst/identify/fit_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <Eigen/Core>

#include "../core/detail/enum_names.hpp"
#include "detail/regressor_matrix.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/data_split.hpp"
#include "hyst/identify/nnls.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {
namespace {

struct Record {
  std::span<const double> input;
  std::span<const double> output;
};

double range_of(std::span<const double> samples) {
  const auto [lowest, highest] = std::minmax_element(samples.begin(), samples.end());
  return *highest - *lowest;
}

void require_varying(std::span<const double> samples, std::string_view name, std::string_view why) {
  if (!(range_of(samples) > 0.0)) {
    throw Error(fmt::format("PI fit: the {} is constant (all {} samples = {}); {}", name,
                            samples.size(), samples.front(), why));
  }
}

void validate_record(const Record& record, std::string_view prefix) {
  const auto input_name = fmt::format("PI fit {}input", prefix);
  const auto output_name = fmt::format("PI fit {}output", prefix);
  require_same_size(record.input.size(), input_name, record.output.size(), output_name);
  require_not_empty(record.input.size(), input_name);
  require_finite(record.input, input_name);
  require_finite(record.output, output_name);
}

void validate_options(const PiFitOptions& options) {
  const auto& r = options.thresholds;
  if (r.empty() && options.operators == 0) {
    throw Error("PI fit operators = 0 must be >= 1", "operators");
  }
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!std::isfinite(r[j])) {
      throw Error(fmt::format("PI fit threshold r[{}] = {} is not finite", j, r[j]),
                  fmt::format("thresholds[{}]", j));
    }
  }
  require_increasing_from_zero(r, "PI fit threshold", "r", "thresholds",
                               "the r = 0 play carries the linear term");
  if (!(std::isfinite(options.min_linear_weight) && options.min_linear_weight > 0.0)) {
    throw Error(fmt::format("PI fit min_linear_weight = {} must be finite and > 0",
                            options.min_linear_weight),
                "min_linear_weight");
  }
}

// Play outputs w_j[k] for the record, starting from (and advancing) `state`.
Eigen::MatrixXd play_columns(const std::vector<double>& thresholds, std::vector<double>& state,
                             std::span<const double> input) {
  Eigen::MatrixXd columns =
      detail::regressor_matrix(static_cast<Eigen::Index>(input.size()),
                               static_cast<Eigen::Index>(thresholds.size()), "PI fit");
  for (std::size_t k = 0; k < input.size(); ++k) {
    for (std::size_t j = 0; j < thresholds.size(); ++j) {
      state[j] = play_step(input[k], thresholds[j], state[j]);
      columns(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = state[j];
    }
  }
  return columns;
}

std::vector<double> periodic_plays(const std::vector<double>& thresholds,
                                   std::span<const double> input) {
  std::vector<double> state(thresholds.size(), 0.0);
  for (double v : input) {
    for (std::size_t j = 0; j < thresholds.size(); ++j)
      state[j] = play_step(v, thresholds[j], state[j]);
  }
  return state;
}

PiFit fit(const Record& record, const std::optional<Record>& held_out,
          const PiFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  validate_options(options);
  validate_record(record, "");
  if (held_out) {
    validate_record(*held_out, "validation ");
    if (options.validate_fraction != 0.0) {
      throw Error(fmt::format("PI fit validate_fraction = {} must be 0 when a separate validation "
                              "record is given",
                              options.validate_fraction),
                  "validate_fraction");
    }
  }
  DataSplit split;
  try {
    split = split_by_fraction(record.input.size(), options.validate_fraction);
  } catch (const Error& error) {
    throw Error(fmt::format("PI fit: {}", error.what()), "validate_fraction");
  }

  const auto fit_input = record.input.subspan(split.fit_begin, split.fit_size());
  const auto fit_output = record.output.subspan(split.fit_begin, split.fit_size());
  const std::size_t operators =
      options.thresholds.empty() ? options.operators : options.thresholds.size();
  if (fit_input.size() < operators + 2) {
    throw Error(fmt::format("PI fit: the fit part has {} samples, fewer than operators + 2 = {}",
                            fit_input.size(), operators + 2));
  }
  require_varying(fit_input, "input of the fit part",
                  "the play operators need a varying input to be identified");
  require_varying(fit_output, "output of the fit part", "there is no hysteresis to fit");
  if (held_out) {
    require_varying(held_out->output, "validation output",
                    "its range normalises the validation NRMSE");
  }

  const std::vector<double> thresholds =
      options.thresholds.empty() ? pi_default_thresholds(fit_input, operators) : options.thresholds;
  const bool periodic = options.initial_state == PiFitOptions::InitialState::periodic;
  const std::vector<double> initial_plays = periodic ? periodic_plays(thresholds, record.input)
                                                     : std::vector<double>(thresholds.size(), 0.0);

  // Columns w_j[k]; substitute p_0 = eps + q so that every unknown is >= 0.
  std::vector<double> plays = initial_plays;
  Eigen::MatrixXd W = play_columns(thresholds, plays, fit_input);
  const Eigen::Map<const Eigen::VectorXd> y(fit_output.data(),
                                            static_cast<Eigen::Index>(fit_output.size()));
  const double eps = options.min_linear_weight * range_of(fit_output) / range_of(fit_input);
  Eigen::VectorXd b = y - eps * W.col(0);
  Eigen::RowVectorXd column_means = Eigen::RowVectorXd::Zero(W.cols());
  double b_mean = 0.0;
  if (options.fit_offset) {
    column_means = W.colwise().mean();
    b_mean = b.mean();
    W.rowwise() -= column_means;
    b.array() -= b_mean;
  }
  const NnlsResult solution = nnls(W, b);

  PrandtlIshlinskii::Params params;
  params.thresholds = thresholds;
  params.weights.assign(solution.x.data(), solution.x.data() + solution.x.size());
  params.weights[0] += eps;
  if (options.fit_offset) {
    const Eigen::Map<const Eigen::VectorXd> p(params.weights.data(), W.cols());
    params.offset = y.mean() - column_means.dot(p);
  }
  PiFit result{PrandtlIshlinskii(std::move(params)), {}, {}};
  result.initial_state = result.model.make_state(initial_plays);

  // Errors of the fitted model, simulated as a user would run it.
  auto state = result.initial_state;
  const auto predicted = simulate(result.model, state, fit_input);
  FitReport& report = result.report;
  report.model = "pi";
  report.method = "nnls (Lawson-Hanson)";
  report.termination = solution.termination;
  std::size_t zero_weights = 0;
  for (Eigen::Index j = 0; j < solution.x.size(); ++j)
    zero_weights += solution.x[j] == 0.0 ? 1 : 0;
  const std::string how =
      solution.converged()
          ? fmt::format("KKT conditions hold within tolerance {:.3g}", solution.tolerance)
          : solution.message;
  report.message = fmt::format("{}; {} of {} weights at their lower bound (p_0 = eps, p_j = 0)",
                               how, zero_weights, thresholds.size());
  report.iterations = solution.iterations;
  report.parameters = thresholds.size() + (options.fit_offset ? 1 : 0);
  const double best_constant = options.fit_offset ? y.mean() : 0.0;
  report.initial_cost = 0.5 * (y.array() - best_constant).square().sum();
  report.final_cost = 0.0;
  for (std::size_t k = 0; k < fit_output.size(); ++k) {
    const double e = fit_output[k] - predicted[k];
    report.final_cost += 0.5 * e * e;
  }
  report.fit = error_metrics(fit_output, predicted);

  if (split.has_validation()) {
    const auto validation_input =
        record.input.subspan(split.validation_begin, split.validation_size());
    const auto validation_output =
        record.output.subspan(split.validation_begin, split.validation_size());
    const auto prediction = simulate(result.model, state, validation_input);
    report.validation = error_metrics(validation_output, prediction);
  } else if (held_out) {
    auto validation_state =
        periodic ? pi_periodic_state(result.model, held_out->input) : result.model.initial_state();
    const auto prediction = simulate(result.model, validation_state, held_out->input);
    report.validation = error_metrics(held_out->output, prediction);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

PiFitOptions::InitialState pi_initial_state_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<PiFitOptions::InitialState>, "PI initial state",
                             "initial_state");
}

std::vector<double> pi_default_thresholds(std::span<const double> input, std::size_t operators) {
  if (operators == 0) throw Error("PI fit operators = 0 must be >= 1", "operators");
  require_not_empty(input.size(), "PI fit input");
  require_finite(input, "PI fit input");
  require_varying(input, "input", "it sets the threshold spacing");
  const double spacing = range_of(input) / (2.0 * static_cast<double>(operators));
  return uniform_thresholds(operators, spacing);
}

PrandtlIshlinskii::State pi_periodic_state(const PrandtlIshlinskii& model,
                                           std::span<const double> input) {
  require_not_empty(input.size(), "PI periodic input");
  require_finite(input, "PI periodic input");
  return model.make_state(periodic_plays(model.params().thresholds, input));
}

PiFit fit_prandtl_ishlinskii(std::span<const double> input, std::span<const double> output,
                             const PiFitOptions& options) {
  return fit(Record{input, output}, std::nullopt, options);
}

PiFit fit_prandtl_ishlinskii(std::span<const double> input, std::span<const double> output,
                             std::span<const double> validation_input,
                             std::span<const double> validation_output,
                             const PiFitOptions& options) {
  return fit(Record{input, output}, Record{validation_input, validation_output}, options);
}

}  // namespace hyst
