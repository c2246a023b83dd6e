#include "hyst/identify/fit_modified_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "dead_zone_slopes.hpp"
#include "detail/regressor_matrix.hpp"
#include "hyst/core/error.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "weight_fit.hpp"

namespace hyst {

using detail::DeadZoneSlopes;

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
  // The inverse map S', linear in its slopes.
  const DeadZoneSlopes inverse_map(
      options.dead_zone_thresholds.empty()
          ? DeadZoneSlopes::default_thresholds(options.dead_zones, y_off - *y_min, *y_max - y_off)
          : options.dead_zone_thresholds,
      options.min_weight);
  const double eps_p =
      options.min_weight * detail::range_of(parts.fit_output) / detail::range_of(parts.fit_input);
  const std::size_t n = r.size();
  const std::size_t slopes = inverse_map.unknowns();
  const auto m = static_cast<Eigen::Index>(parts.fit_input.size());
  Eigen::MatrixXd A =
      detail::regressor_matrix(m, static_cast<Eigen::Index>(n + slopes), "modified PI fit");
  Eigen::VectorXd b(m);
  const bool periodic = options.initial_state == PiFitOptions::InitialState::periodic;
  const auto initial = periodic ? pi_periodic_state(probe, input) : probe.initial_state();
  auto state = initial;
  std::vector<double> slope_terms(slopes);
  for (Eigen::Index k = 0; k < m; ++k) {
    const auto sample = static_cast<std::size_t>(k);
    probe.step(state, parts.fit_input[sample]);
    for (std::size_t j = 0; j < n; ++j)
      A(k, static_cast<Eigen::Index>(j)) = state.play[j];
    b[k] = inverse_map.terms(parts.fit_output[sample] - y_off, slope_terms) - eps_p * state.play[0];
    for (std::size_t i = 0; i < slopes; ++i)
      A(k, static_cast<Eigen::Index>(n + i)) = -slope_terms[i];
  }
  const auto solution = detail::nnls_with_offset(std::move(A), std::move(b), true);

  ModifiedPrandtlIshlinskii::Params params;
  params.pi.thresholds = r;
  params.pi.weights.assign(solution.x.data(), solution.x.data() + static_cast<Eigen::Index>(n));
  params.pi.weights[0] += eps_p;
  params.pi.offset = solution.offset;
  params.dead_zone = inverse_map.map(std::span(solution.x.data() + n, slopes)).inverse().params();
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
      solution, n + slopes + 1, result.model, result.initial_state, parts, start);
  return result;
}

}  // namespace hyst
