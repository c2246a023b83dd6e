#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

std::vector<double> checked_partial_sums(const std::vector<double>& p) {
  if (!(p[0] > 0.0)) {
    throw Error(fmt::format("PI weight p[0] = {} must be > 0 for the inverse to exist", p[0]));
  }
  std::vector<double> sums(p.size());
  double sum = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    sum += p[j];
    if (!(sum > 0.0)) {
      throw Error(fmt::format(
          "PI partial sum S[{}] = p[0] + ... + p[{}] = {} must be > 0 for the inverse to exist", j,
          j, sum));
    }
    sums[j] = sum;
  }
  return sums;
}

// rh_j = sum_{i<=j} p_i (r_j - r_i) by the recurrence rh_j = rh_{j-1} + S_{j-1} (r_j - r_{j-1})
// (linear in the number of operators; every term is >= 0 as S_j > 0). A parameter set whose
// inverse over- or underflows (e.g. a subnormal p_0, whose 1/p_0 is inf) is refused with the
// forward values as the model holds them.
PrandtlIshlinskii::Params inverse_params(const PrandtlIshlinskii::Params& forward,
                                         const std::vector<double>& sums) {
  const auto& r = forward.thresholds;
  const auto& p = forward.weights;
  const std::size_t n = r.size();
  PrandtlIshlinskii::Params inverse{std::vector<double>(n), std::vector<double>(n), 0.0};
  double threshold = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    if (j > 0) threshold += sums[j - 1] * (r[j] - r[j - 1]);
    if (!std::isfinite(threshold)) {
      throw Error(fmt::format("PI inverse threshold rh[{}] = sum_{{i<={}}} p[i] (r[{}] - r[i]) "
                              "overflows (r[{}] = {}, S[{}] = {}): the inverse cannot be "
                              "represented in double",
                              j, j, j, j, r[j], j, sums[j]),
                  fmt::format("weights[{}]", j));
    }
    inverse.thresholds[j] = threshold;
    const double weight = j == 0 ? 1.0 / p[0] : -(p[j] / sums[j]) / sums[j - 1];
    if (!std::isfinite(weight) || (p[j] != 0.0 && weight == 0.0)) {
      if (j == 0) {
        throw Error(fmt::format("PI weight p[0] = {} is too small for the inverse: its inverse "
                                "weight 1/p[0] overflows (p[0] must be >= {})",
                                p[0], 1.0 / std::numeric_limits<double>::max()),
                    "weights[0]");
      }
      throw Error(fmt::format("PI weight p[{}] = {} gives the inverse weight -p[{}] / (S[{}] "
                              "S[{}]) = {} with S[{}] = {} and S[{}] = {}: the inverse cannot be "
                              "represented in double",
                              j, p[j], j, j, j - 1, weight, j, sums[j], j - 1, sums[j - 1]),
                  fmt::format("weights[{}]", j));
    }
    inverse.weights[j] = weight;
  }
  return inverse;
}

}  // namespace

InversePrandtlIshlinskii::InversePrandtlIshlinskii(const PrandtlIshlinskii& model,
                                                   const Options& options)
    : forward_(model),
      partial_sums_(checked_partial_sums(model.params().weights)),
      inverse_(inverse_params(model.params(), partial_sums_)),
      target_bound_([this] {
        double weight_sum = 0.0;
        for (const double weight : inverse_.params().weights)
          weight_sum += std::abs(weight);
        return 0.25 * std::numeric_limits<double>::max() / std::max(1.0, weight_sum);
      }()),
      options_(options) {
  if (std::isnan(options.input_min) || std::isnan(options.input_max) ||
      options.input_min > options.input_max) {
    throw Error(
        fmt::format("inverse PI input limits v_min = {} and v_max = {} must satisfy "
                    "v_min <= v_max",
                    options.input_min, options.input_max));
  }
}

InversePrandtlIshlinskii::State InversePrandtlIshlinskii::state_consistent_with(
    const PrandtlIshlinskii::State& forward_state) const {
  const auto& z = forward_.make_state(forward_state.play).play;
  const auto& p = forward_.params().weights;
  const std::size_t n = z.size();
  std::vector<double> state(n);
  double tail = 0.0;  // sum_{i>j} p_i z_i
  for (std::size_t j = n; j-- > 0;) {
    state[j] = partial_sums_[j] * z[j] + tail;
    tail += p[j] * z[j];
  }
  return State{std::move(state)};
}

PrandtlIshlinskii::State InversePrandtlIshlinskii::forward_state_consistent_with(
    const State& inverse_state) const {
  const auto& zh = inverse_.make_state(inverse_state.play).play;
  const std::size_t n = zh.size();
  // zh_j - zh_{j+1} = S_j (z_j - z_{j+1}) and zh_n = S_n z_n.
  std::vector<double> z(n);
  z[n - 1] = zh[n - 1] / partial_sums_[n - 1];
  for (std::size_t j = n - 1; j-- > 0;)
    z[j] = z[j + 1] + (zh[j] - zh[j + 1]) / partial_sums_[j];
  return PrandtlIshlinskii::State{std::move(z)};
}

}  // namespace hyst
