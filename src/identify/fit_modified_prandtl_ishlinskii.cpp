#include "hyst/identify/fit_modified_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "detail/regressor_matrix.hpp"
#include "hyst/core/error.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/operators/dead_zone.hpp"
#include "hyst/operators/play.hpp"
#include "weight_fit.hpp"

namespace hyst {
namespace {

std::vector<double> default_dead_zones(std::size_t per_side, double below, double above) {
  std::vector<double> d;
  for (std::size_t i = per_side; i >= 1; --i)
    d.push_back(-static_cast<double>(i) * below / static_cast<double>(per_side + 1));
  d.push_back(0.0);
  for (std::size_t i = 1; i <= per_side; ++i)
    d.push_back(static_cast<double>(i) * above / static_cast<double>(per_side + 1));
  return d;
}

}  // namespace

ModifiedPiFit fit_modified_prandtl_ishlinskii(std::span<const double> input,
                                              std::span<const double> output,
                                              const ModifiedPiFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (!std::isfinite(options.min_weight) || !(options.min_weight > 0.0)) {
    throw Error(
        fmt::format("modified PI fit min_weight = {} must be finite and > 0", options.min_weight),
        "min_weight");
  }
  const std::size_t operators =
      options.thresholds.empty() ? options.operators : options.thresholds.size();
  const std::size_t zones = options.dead_zone_thresholds.empty()
                                ? 2 * options.dead_zones + 1
                                : options.dead_zone_thresholds.size();
  if (!std::isfinite(options.output_margin) || options.output_margin < 0.0) {
    throw Error(fmt::format("modified PI fit output_margin = {} must be finite and >= 0",
                            options.output_margin),
                "output_margin");
  }
  const auto parts = detail::split_record(input, output, options.validate_fraction,
                                          "modified PI fit", operators + zones);
  const auto [y_min, y_max] = std::minmax_element(parts.fit_output.begin(), parts.fit_output.end());
  const double y_off = options.output_offset.value_or(0.5 * (*y_min + *y_max));
  if (!std::isfinite(y_off)) {
    throw Error(fmt::format("modified PI fit output_offset = {} is not finite", y_off),
                "output_offset");
  }
  // Validated through the model types: PI thresholds and the inverse dead-zone thresholds.
  const std::vector<double> r = options.thresholds.empty()
                                    ? pi_default_thresholds(parts.fit_input, operators)
                                    : options.thresholds;
  const PrandtlIshlinskii probe({r, std::vector<double>(r.size(), 1.0), 0.0});
  const DeadZoneSuperposition inverse_probe(
      {options.dead_zone_thresholds.empty()
           ? default_dead_zones(options.dead_zones, y_off - *y_min, *y_max - y_off)
           : options.dead_zone_thresholds,
       std::vector<double>(zones, 1.0)});
  const auto& d = inverse_probe.params().thresholds;
  const std::size_t z0 = inverse_probe.zero_index();
  const std::size_t above = d.size() - 1 - z0;  // thresholds d'_1 .. d'_above
  const std::size_t below = z0;                 // thresholds d'_-1 .. d'_-below

  const double eps_p =
      options.min_weight * detail::range_of(parts.fit_output) / detail::range_of(parts.fit_input);
  const double eps_g = options.min_weight;
  const std::size_t n = r.size();
  const auto m = static_cast<Eigen::Index>(parts.fit_input.size());
  Eigen::MatrixXd A =
      detail::regressor_matrix(m, static_cast<Eigen::Index>(n + above + below), "modified PI fit");
  Eigen::VectorXd b(m);
  const bool periodic = options.initial_state == PiFitOptions::InitialState::periodic;
  const auto initial = periodic ? pi_periodic_state(probe, input) : probe.initial_state();
  auto state = initial;
  std::vector<double> zone(d.size());
  for (Eigen::Index k = 0; k < m; ++k) {
    const auto sample = static_cast<std::size_t>(k);
    probe.step(state, parts.fit_input[sample]);
    for (std::size_t j = 0; j < n; ++j)
      A(k, static_cast<Eigen::Index>(j)) = state.play[j];
    const double z = parts.fit_output[sample] - y_off;
    for (std::size_t i = 0; i < d.size(); ++i)
      zone[i] = DeadZone(d[i])(z);
    // S'(z) = z - D_1 - D_-1 + sum_i T_i (D_i - D_{i+1}) + sum_i U_i (D_-i - D_-(i+1)): the
    // partial sums T_i, U_i >= eps_g are the unknowns (T_i = eps_g + t_i).
    double rhs = zone[z0] - eps_p * state.play[0];
    if (above > 0) rhs -= zone[z0 + 1];
    if (below > 0) rhs -= zone[z0 - 1];
    for (std::size_t i = 1; i <= above; ++i) {
      const double e = zone[z0 + i] - (i < above ? zone[z0 + i + 1] : 0.0);
      A(k, static_cast<Eigen::Index>(n + i - 1)) = -e;
      rhs += eps_g * e;
    }
    for (std::size_t i = 1; i <= below; ++i) {
      const double f = zone[z0 - i] - (i < below ? zone[z0 - i - 1] : 0.0);
      A(k, static_cast<Eigen::Index>(n + above + i - 1)) = -f;
      rhs += eps_g * f;
    }
    b[k] = rhs;
  }
  const auto solution = detail::nnls_with_offset(std::move(A), std::move(b), true);

  ModifiedPrandtlIshlinskii::Params params;
  params.pi.thresholds = r;
  params.pi.weights.assign(solution.x.data(), solution.x.data() + static_cast<Eigen::Index>(n));
  params.pi.weights[0] += eps_p;
  params.pi.offset = solution.offset;
  DeadZoneSuperposition::Params inverse_map{d, std::vector<double>(d.size(), 0.0)};
  inverse_map.weights[z0] = 1.0;
  double previous = 1.0;
  for (std::size_t i = 1; i <= above; ++i) {
    const double sum = eps_g + solution.x[static_cast<Eigen::Index>(n + i - 1)];
    inverse_map.weights[z0 + i] = sum - previous;
    previous = sum;
  }
  previous = 1.0;
  for (std::size_t i = 1; i <= below; ++i) {
    const double sum = eps_g + solution.x[static_cast<Eigen::Index>(n + above + i - 1)];
    inverse_map.weights[z0 - i] = sum - previous;
    previous = sum;
  }
  params.dead_zone = DeadZoneSuperposition(std::move(inverse_map)).inverse().params();
  params.offset = y_off;
  if (options.clamp_output) {
    const double margin = options.output_margin * (*y_max - *y_min);
    params.output_min = *y_min - margin;
    params.output_max = *y_max + margin;
  }
  ModifiedPiFit result{ModifiedPrandtlIshlinskii(std::move(params)), {}, {}};
  result.initial_state = result.model.make_state(initial.play);
  result.report = detail::weight_fit_report(
      "modified_pi",
      "constrained least squares (NNLS) on PI weights and inverse dead-zone slopes, equation "
      "error",
      solution, n + above + below + 1, result.model, result.initial_state, parts, start);
  return result;
}

}  // namespace hyst
