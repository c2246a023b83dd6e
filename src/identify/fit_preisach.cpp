#include "hyst/identify/fit_preisach.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <Eigen/Core>

#include "detail/regressor_matrix.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/data_split.hpp"
#include "hyst/identify/nnls.hpp"
#include "hyst/models/preisach_relay_grid.hpp"
#include "weight_fit.hpp"

namespace hyst {
namespace {

using Clock = std::chrono::steady_clock;
using Neighbours = std::vector<std::pair<std::size_t, std::size_t>>;

// Pairs of triangle entries (i, j), j <= i, stored at i(i+1)/2 + j, that are next to each other
// along alpha or beta. Diagonal entries (the reversible part) are paired only among themselves.
Neighbours triangle_neighbours(std::size_t n) {
  Neighbours pairs;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j <= i; ++j) {
      const std::size_t here = preisach_relay_index(i, j);
      if (i == j) {
        if (i + 1 < n) pairs.emplace_back(here, preisach_relay_index(i + 1, i + 1));
        continue;
      }
      if (i + 1 < n) pairs.emplace_back(here, preisach_relay_index(i + 1, j));
      if (j + 1 < i) pairs.emplace_back(here, preisach_relay_index(i, j + 1));
    }
  }
  return pairs;
}

struct WeightSolution {
  Eigen::VectorXd weights;
  double offset = 0.0;
  NnlsResult nnls;
};

// min ||y - y_off - A w||^2 + smoothness^2 M sum (w_r - w_r')^2 over w >= 0 (and y_off).
WeightSolution solve_weights(Eigen::MatrixXd A, Eigen::VectorXd y, const Neighbours& neighbours,
                             double smoothness, bool fit_offset) {
  const Eigen::Index m = A.rows();
  const Eigen::Index n = A.cols();
  Eigen::RowVectorXd means = Eigen::RowVectorXd::Zero(n);
  double y_mean = 0.0;
  if (fit_offset) {
    means = A.colwise().mean();
    y_mean = y.mean();
    A.rowwise() -= means;
    y.array() -= y_mean;
  }
  if (smoothness > 0.0 && !neighbours.empty()) {
    const auto extra = static_cast<Eigen::Index>(neighbours.size());
    A.conservativeResize(m + extra, n);
    A.bottomRows(extra).setZero();
    y.conservativeResize(m + extra);
    y.tail(extra).setZero();
    const double scale = smoothness * std::sqrt(static_cast<double>(m));
    for (Eigen::Index q = 0; q < extra; ++q) {
      const auto& [a, b] = neighbours[static_cast<std::size_t>(q)];
      A(m + q, static_cast<Eigen::Index>(a)) = scale;
      A(m + q, static_cast<Eigen::Index>(b)) = -scale;
    }
  }
  WeightSolution solution;
  solution.nnls = nnls(A, y);
  solution.weights = solution.nnls.x;
  if (fit_offset) solution.offset = y_mean - means.dot(solution.weights);
  return solution;
}

void check_smoothness(double smoothness, std::string_view what) {
  if (!std::isfinite(smoothness) || smoothness < 0.0) {
    throw Error(fmt::format("{} smoothness = {} must be finite and >= 0", what, smoothness),
                "smoothness");
  }
}

void check_range(std::optional<double> lower, std::optional<double> upper, double lo, double hi,
                 std::string_view what) {
  if (lower && !std::isfinite(*lower)) {
    throw Error(fmt::format("{} lower = {} is not finite", what, *lower), "lower");
  }
  if (upper && !std::isfinite(*upper)) {
    throw Error(fmt::format("{} upper = {} is not finite", what, *upper), "upper");
  }
  if (!(lo < hi)) {
    throw Error(fmt::format("{}: the input range [{}, {}] is empty (lower must be < upper; a "
                            "constant input cannot identify hysteresis)",
                            what, lo, hi),
                "upper");
  }
}

std::string termination_message(const NnlsResult& solution, const Eigen::VectorXd& weights,
                                std::string_view unknowns) {
  std::size_t zero = 0;
  for (Eigen::Index r = 0; r < weights.size(); ++r)
    zero += weights[r] == 0.0 ? 1 : 0;
  const std::string how =
      solution.converged()
          ? fmt::format("KKT conditions hold within tolerance {:.3g}", solution.tolerance)
          : solution.message;
  return fmt::format("{}; {} of {} {} are 0", how, zero, weights.size(), unknowns);
}

// The report of a weight fit by NNLS: how it ended, the costs (the initial one: the best constant
// output) and the fit errors.
FitReport weight_fit_report(std::string model, std::string_view unknowns,
                            std::string_view short_name, const WeightSolution& solution,
                            double smoothness, bool fit_offset, std::span<const double> measured,
                            std::span<const double> predicted) {
  FitReport report;
  report.model = std::move(model);
  report.method = fmt::format("nnls (Lawson-Hanson) on {}", unknowns);
  if (smoothness > 0.0) report.method += fmt::format(", smoothness {:.3g}", smoothness);
  report.termination = solution.nnls.termination;
  report.message = termination_message(solution.nnls, solution.weights, short_name);
  report.iterations = solution.nnls.iterations;
  report.parameters = static_cast<std::size_t>(solution.weights.size()) + (fit_offset ? 1 : 0);
  report.initial_cost = detail::best_constant_cost(measured, fit_offset);
  report.final_cost = detail::half_sum_of_squares(measured, predicted);
  report.fit = error_metrics(measured, predicted);
  return report;
}

// ---------------------------------------------------------------------------------------------
// (b) Regressors of the tabulated Everett function along a history.

struct TableRegressors {
  std::size_t k;                    // K intervals
  std::vector<double> node;         // coefficients of E(x_a, x_c) at a * (K+1) + c
  std::vector<double> accumulated;  // work: sum over rows a > i
};

void add_everett(const TabulatedEverett& table, TableRegressors& r, double alpha, double beta,
                 double factor) {
  const auto stencil = table.stencil(alpha, beta);
  for (std::size_t n = 0; n < stencil.size; ++n) {
    r.node[stencil.alpha_level[n] * (r.k + 1) + stencil.beta_level[n]] +=
        factor * stencil.weight[n];
  }
}

// Row of coefficients of the cell weights w_ij for the output in `state` (without the offset).
void cell_row(const TabulatedEverett& table, const PreisachState& state, TableRegressors& r,
              double* row) {
  const std::size_t k = r.k;
  const std::size_t stride = k + 1;
  std::fill(r.node.begin(), r.node.end(), 0.0);
  // y - y_off = -F0 + 2 mu(S+), mu(S+) = B + sum of the staircase terms; F0 = E(x_K, x_0).
  r.node[k * stride] += state.from_positive_saturation() ? 1.0 : -1.0;
  for (std::size_t t = 1; t < state.size; ++t) {
    const double from = state.extrema[t - 1];
    const double to = state.extrema[t];
    if (state.is_minimum(t - 1)) {
      add_everett(table, r, to, from, 2.0);
    } else {
      add_everett(table, r, from, to, -2.0);
    }
  }
  const std::size_t top = state.size - 1;
  if (state.is_minimum(top)) {
    add_everett(table, r, state.input, state.extrema[top], 2.0);
  } else {
    add_everett(table, r, state.extrema[top], state.input, -2.0);
  }
  // E(x_a, x_c) = sum_{c <= j <= i <= a-1} w_ij, so w_ij collects sum_{a > i, c <= j} node(a, c).
  std::fill(r.accumulated.begin(), r.accumulated.end(), 0.0);
  for (std::size_t i = k; i-- > 0;) {
    const double* node_row = &r.node[(i + 1) * stride];
    double prefix = 0.0;
    for (std::size_t j = 0; j <= i; ++j) {
      prefix += node_row[j];
      r.accumulated[j] += prefix;
      row[preisach_relay_index(i, j)] = r.accumulated[j];
    }
  }
}

// E(x_a, x_c) for c < a from the cell weights, in TabulatedEverett::Params::values order.
std::vector<double> everett_values(std::size_t k, const Eigen::VectorXd& w) {
  std::vector<double> values(k * (k + 1) / 2);
  std::vector<double> previous(k + 1, 0.0);  // E(x_{a-1}, x_c)
  std::vector<double> current(k + 1, 0.0);
  for (std::size_t a = 1; a <= k; ++a) {
    const std::size_t i = a - 1;
    double row_suffix = 0.0;
    std::fill(current.begin(), current.end(), 0.0);
    for (std::size_t c = a; c-- > 0;) {
      row_suffix += w[static_cast<Eigen::Index>(preisach_relay_index(i, c))];
      current[c] = previous[c] + row_suffix;
      values[everett_table_index(a, c)] = current[c];
    }
    std::swap(previous, current);
  }
  return values;
}

void validate_curves(std::span<const ReversalCurve> curves) {
  if (curves.empty()) throw Error("FORC fit: no curves");
  for (std::size_t n = 0; n < curves.size(); ++n)
    check_fit_record(curves[n], fmt::format("FORC {}", n), {});
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// (a)

PreisachWeightFit fit_preisach_weights(std::span<const double> input,
                                       std::span<const double> output,
                                       const PreisachWeightFitOptions& options) {
  const auto start = Clock::now();
  require_same_size(input.size(), "Preisach fit input", output.size(), "Preisach fit output");
  require_not_empty(input.size(), "Preisach fit input");
  require_finite(input, "Preisach fit input");
  require_finite(output, "Preisach fit output");
  check_smoothness(options.smoothness, "Preisach fit");
  if (options.levels == 0) throw Error("Preisach fit levels = 0 must be >= 1", "levels");
  DataSplit split;
  try {
    split = split_by_fraction(input.size(), options.validate_fraction);
  } catch (const Error& error) {
    throw Error(fmt::format("Preisach fit: {}", error.what()), "validate_fraction");
  }
  const auto fit_input = input.subspan(split.fit_begin, split.fit_size());
  const auto fit_output = output.subspan(split.fit_begin, split.fit_size());
  const auto [in_min, in_max] = std::minmax_element(fit_input.begin(), fit_input.end());
  const double lower = options.lower.value_or(*in_min);
  const double upper = options.upper.value_or(*in_max);
  check_range(options.lower, options.upper, lower, upper, "Preisach fit");
  const std::size_t relays = preisach_relay_count(options.levels);
  if (fit_input.size() < relays + 2) {
    throw Error(
        fmt::format("Preisach fit: the fit part has {} samples, fewer than relays + 2 = {} "
                    "(N = {} levels)",
                    fit_input.size(), relays + 2, options.levels));
  }
  const auto [out_min, out_max] = std::minmax_element(fit_output.begin(), fit_output.end());
  if (!(*out_max > *out_min)) {
    throw Error(
        fmt::format("Preisach fit: the output of the fit part is constant (all {} samples "
                    "= {}); there is no hysteresis to fit",
                    fit_output.size(), *out_min));
  }

  // Relay states s_ij[k] of a unit-weight grid.
  Preisach::Params params{.everett = {.levels = options.levels,
                                      .lower = lower,
                                      .upper = upper,
                                      .weights = uniform_relay_weights(options.levels, 1.0),
                                      .layout = options.layout},
                          .offset = 0.0,
                          .initial_state = options.initial_state};
  const PreisachRelayGrid grid(params);
  auto relay_state = grid.initial_state();
  const auto m = static_cast<Eigen::Index>(fit_input.size());
  Eigen::MatrixXd A =
      detail::regressor_matrix(m, static_cast<Eigen::Index>(relays), "Preisach fit");
  for (Eigen::Index k = 0; k < m; ++k) {
    grid.step(relay_state, fit_input[static_cast<std::size_t>(k)]);
    for (std::size_t r = 0; r < relays; ++r)
      A(k, static_cast<Eigen::Index>(r)) = relay_state.relays[r];
  }
  const Eigen::Map<const Eigen::VectorXd> y(fit_output.data(), m);
  const WeightSolution solution = solve_weights(
      std::move(A), y, triangle_neighbours(options.levels), options.smoothness, options.fit_offset);

  params.everett.weights.assign(solution.weights.data(),
                                solution.weights.data() + solution.weights.size());
  params.offset = solution.offset;
  PreisachWeightFit result{Preisach(std::move(params)), {}};

  auto state = result.model.initial_state();
  const auto predicted = simulate(result.model, state, fit_input);
  FitReport& report = result.report;
  report = weight_fit_report("preisach", "relay weights", "relay weights", solution,
                             options.smoothness, options.fit_offset, fit_output, predicted);
  if (split.has_validation()) {
    const auto validation_input = input.subspan(split.validation_begin, split.validation_size());
    const auto validation_output = output.subspan(split.validation_begin, split.validation_size());
    const auto validation_predicted = simulate(result.model, state, validation_input);
    report.validation = error_metrics(validation_output, validation_predicted);
  }
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

// ---------------------------------------------------------------------------------------------
// (b)

PreisachForcFit fit_preisach_forcs(std::span<const ReversalCurve> curves,
                                   const PreisachForcFitOptions& options) {
  const auto start = Clock::now();
  validate_curves(curves);
  check_smoothness(options.smoothness, "FORC fit");
  if (options.intervals == 0) throw Error("FORC fit intervals = 0 must be >= 1", "intervals");
  if (options.saturation == PreisachInitialState::demagnetised) {
    throw Error(
        "FORC fit saturation = demagnetised must be positive_saturation or "
        "negative_saturation (a reversal curve starts at saturation)",
        "saturation");
  }
  std::vector<bool> held(curves.size(), false);
  for (std::size_t index : options.held_out) {
    if (index >= curves.size()) {
      throw Error(fmt::format("FORC fit held_out index {} is out of range ({} curves)", index,
                              curves.size()),
                  "held_out");
    }
    held[index] = true;
  }
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  std::size_t points = 0;
  for (std::size_t n = 0; n < curves.size(); ++n) {
    if (held[n]) continue;
    for (double v : curves[n].input) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    points += curves[n].input.size();
  }
  if (points == 0)
    throw Error("FORC fit: every curve is held out; none is left to fit", "held_out");
  const double lower = options.lower.value_or(lo);
  const double upper = options.upper.value_or(hi);
  check_range(options.lower, options.upper, lower, upper, "FORC fit");
  const std::size_t k = options.intervals;
  const std::size_t cells = k * (k + 1) / 2;
  if (points < cells + 2) {
    throw Error(
        fmt::format("FORC fit: the fitted curves have {} points, fewer than cells + 2 = {} "
                    "(K = {} intervals)",
                    points, cells + 2, k));
  }

  // A probe model on the same levels (unit cell weights) keeps the memory; rows come from it.
  TabulatedEverett::Params table;
  for (std::size_t a = 0; a <= k; ++a) {
    table.levels.push_back(
        a == k ? upper : lower + (upper - lower) * static_cast<double>(a) / static_cast<double>(k));
  }
  table.values = everett_values(k, Eigen::VectorXd::Ones(static_cast<Eigen::Index>(cells)));
  const TabulatedPreisach probe({.everett = table, .offset = 0.0});
  TableRegressors regressors{k, std::vector<double>((k + 1) * (k + 1)), std::vector<double>(k + 1)};

  Eigen::MatrixXd A = detail::regressor_matrix(static_cast<Eigen::Index>(points),
                                               static_cast<Eigen::Index>(cells), "Preisach fit");
  Eigen::VectorXd y(static_cast<Eigen::Index>(points));
  std::vector<double> measured;
  measured.reserve(points);
  std::vector<double> row(cells);
  Eigen::Index next = 0;
  for (std::size_t n = 0; n < curves.size(); ++n) {
    if (held[n]) continue;
    auto state = probe.make_state(options.saturation);
    for (std::size_t i = 0; i < curves[n].input.size(); ++i) {
      probe.step(state, curves[n].input[i]);
      cell_row(probe.everett(), state, regressors, row.data());
      A.row(next) =
          Eigen::Map<const Eigen::RowVectorXd>(row.data(), static_cast<Eigen::Index>(cells));
      y[next++] = curves[n].output[i];
      measured.push_back(curves[n].output[i]);
    }
  }
  const auto [out_min, out_max] = std::minmax_element(measured.begin(), measured.end());
  if (!(*out_max > *out_min)) {
    throw Error(
        fmt::format("FORC fit: the output of the fitted curves is constant (= {}); there "
                    "is no hysteresis to fit",
                    *out_min));
  }
  const WeightSolution solution = solve_weights(std::move(A), std::move(y), triangle_neighbours(k),
                                                options.smoothness, options.fit_offset);

  table.values = everett_values(k, solution.weights);
  PreisachForcFit result{TabulatedPreisach({.everett = std::move(table),
                                            .offset = solution.offset,
                                            .initial_state = options.saturation}),
                         {}};
  std::vector<double> predicted;
  std::vector<double> held_measured;
  std::vector<double> held_predicted;
  for (std::size_t n = 0; n < curves.size(); ++n) {
    const auto curve_prediction =
        predict_reversal_curve(result.model, curves[n].input, options.saturation);
    auto& into = held[n] ? held_predicted : predicted;
    into.insert(into.end(), curve_prediction.begin(), curve_prediction.end());
    if (held[n]) {
      held_measured.insert(held_measured.end(), curves[n].output.begin(), curves[n].output.end());
    }
  }
  FitReport& report = result.report;
  report =
      weight_fit_report("tabulated_preisach", "Everett cell weights from FORCs", "cell weights",
                        solution, options.smoothness, options.fit_offset, measured, predicted);
  if (!held_measured.empty()) report.validation = error_metrics(held_measured, held_predicted);
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace hyst
