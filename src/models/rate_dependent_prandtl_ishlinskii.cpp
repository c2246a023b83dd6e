#include "hyst/models/rate_dependent_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

PrandtlIshlinskii classical_of(const RateDependentPrandtlIshlinskii::Params& p) {
  try {
    return PrandtlIshlinskii({p.thresholds, p.weights, p.offset});
  } catch (const Error& error) {
    throw Error(fmt::format("rate-dependent {}", error.what()), error.field());
  }
}

void require_time(double value, std::string_view field, bool zero_allowed) {
  if (!std::isfinite(value) || value < 0.0 || (!zero_allowed && value == 0.0)) {
    throw Error(fmt::format("rate-dependent PI {} = {} must be finite and {} 0", field, value,
                            zero_allowed ? ">=" : ">"),
                std::string(field));
  }
}

}  // namespace

RateDependentPrandtlIshlinskii::RateDependentPrandtlIshlinskii(Params params)
    : params_(std::move(params)), classical_(classical_of(params_)) {
  require_time(params_.rate_gain, "rate_gain", true);
  require_time(params_.sample_time, "sample_time", false);
  require_time(params_.rate_filter, "rate_filter", true);
  inverse_sample_time_ = 1.0 / params_.sample_time;
  filter_gain_ = params_.sample_time / (params_.rate_filter + params_.sample_time);
}

RateDependentPrandtlIshlinskii::State RateDependentPrandtlIshlinskii::state_at_rest(
    double input) const {
  require_finite(input, "rate-dependent PI rest input v0");
  return State{std::vector<double>(size(), input), input, 0.0};
}

RateDependentPrandtlIshlinskii::State RateDependentPrandtlIshlinskii::make_state(
    std::vector<double> play, double input, double rate) const {
  require_finite(input, "rate-dependent PI state input");
  require_finite(rate, "rate-dependent PI state rate");
  require_same_size(play.size(), "rate-dependent PI state w", size(),
                    "rate-dependent PI thresholds r");
  // After a step every play lies within its current threshold of the input.
  const double widening = params_.rate_gain * std::abs(rate);
  for (std::size_t j = 0; j < play.size(); ++j) {
    require_finite(play[j], fmt::format("rate-dependent PI state w[{}]", j));
    const double limit = params_.thresholds[j] + (j > 0 ? widening : 0.0);
    const double slack = 1e-12 * std::max({1.0, std::abs(input), std::abs(play[j])});
    if (std::abs(play[j] - input) > limit + slack) {
      throw Error(
          fmt::format("rate-dependent PI state w[{}] = {} is more than its threshold {} "
                      "from the input {}: no input history reaches this state",
                      j, play[j], limit, input));
    }
  }
  return State{std::move(play), input, rate};
}

RateDependentPrandtlIshlinskii::Params rate_dependent_pi_exponential(double alpha, double rho,
                                                                     double tau, std::size_t n,
                                                                     double beta,
                                                                     double sample_time) {
  if (!std::isfinite(alpha) || !(alpha > 0.0)) {
    throw Error(fmt::format("rate-dependent PI alpha = {} must be finite and > 0", alpha), "alpha");
  }
  if (!std::isfinite(rho) || !(rho > 0.0)) {
    throw Error(fmt::format("rate-dependent PI rho = {} must be finite and > 0", rho), "rho");
  }
  require_finite(tau, "rate-dependent PI tau");
  RateDependentPrandtlIshlinskii::Params params;
  for (std::size_t j = 0; j <= n; ++j) {
    params.thresholds.push_back(alpha * static_cast<double>(j));
    params.weights.push_back(rho * std::exp(-tau * params.thresholds.back()));
  }
  params.rate_gain = beta;
  params.sample_time = sample_time;
  return params;
}

}  // namespace hyst
