#include "hyst/identify/fit_rate_dependent_prandtl_ishlinskii.hpp"

#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "detail/regressor_matrix.hpp"
#include "hyst/core/error.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "weight_fit.hpp"

namespace hyst {

RateDependentPiFit fit_rate_dependent_prandtl_ishlinskii(std::span<const double> input,
                                                         std::span<const double> output,
                                                         const RateDependentPiFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (!std::isfinite(options.min_linear_weight) || !(options.min_linear_weight > 0.0)) {
    throw Error(fmt::format("rate-dependent PI fit min_linear_weight = {} must be finite and > 0",
                            options.min_linear_weight),
                "min_linear_weight");
  }
  const std::size_t operators =
      options.thresholds.empty() ? options.operators : options.thresholds.size();
  const auto parts = detail::split_record(input, output, options.validate_fraction,
                                          "rate-dependent PI fit", operators + 1);
  RateDependentPrandtlIshlinskii::Params params;
  params.thresholds = options.thresholds.empty() ? pi_default_thresholds(parts.fit_input, operators)
                                                 : options.thresholds;
  params.weights.assign(params.thresholds.size(), 1.0);
  params.rate_gain = options.rate_gain;
  params.sample_time = options.sample_time;
  params.rate_filter = options.rate_filter;
  const RateDependentPrandtlIshlinskii probe(params);  // validates the options

  // Columns w_j[k]; p_0 = eps + q so that every unknown is >= 0.
  const double eps = options.min_linear_weight * detail::range_of(parts.fit_output) /
                     detail::range_of(parts.fit_input);
  const auto m = static_cast<Eigen::Index>(parts.fit_input.size());
  const auto n = static_cast<Eigen::Index>(probe.size());
  Eigen::MatrixXd A = detail::regressor_matrix(m, n, "rate-dependent PI fit");
  Eigen::VectorXd b(m);
  auto state = probe.initial_state();
  for (Eigen::Index k = 0; k < m; ++k) {
    const auto sample = static_cast<std::size_t>(k);
    probe.step(state, parts.fit_input[sample]);
    A.row(k) = Eigen::Map<const Eigen::RowVectorXd>(state.play.data(), n);
    b[k] = parts.fit_output[sample] - eps * state.play[0];
  }
  const auto solution = detail::nnls_with_offset(std::move(A), std::move(b), options.fit_offset);
  params.weights.assign(solution.x.data(), solution.x.data() + n);
  params.weights[0] += eps;
  params.offset = solution.offset;
  RateDependentPiFit result{RateDependentPrandtlIshlinskii(std::move(params)), {}};
  result.report =
      detail::weight_fit_report("rate_dependent_pi", "nnls (Lawson-Hanson)", solution,
                                static_cast<std::size_t>(n) + (options.fit_offset ? 1 : 0),
                                result.model, result.model.initial_state(), parts, start);
  return result;
}

}  // namespace hyst
