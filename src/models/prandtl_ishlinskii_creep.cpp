#include "hyst/models/prandtl_ishlinskii_creep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "detail/parameter_rules.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

constexpr std::string_view kCreepModel = "PI with creep";

PrandtlIshlinskii hysteresis_of(const PrandtlIshlinskiiCreep::Params& p) {
  try {
    return PrandtlIshlinskii({p.thresholds, p.weights, p.offset});
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", kCreepModel, error.what()), error.field());
  }
}

void validate_creep(const PrandtlIshlinskiiCreep::Params& p) {
  const detail::ParameterRules rules{kCreepModel};
  rules.greater(p.sample_time, 0.0, "sample time Ts", "sample_time");
  const auto& tau = p.time_constants;
  for (std::size_t i = 0; i < tau.size(); ++i) {
    rules.greater(tau[i], 0.0, fmt::format("time constant tau[{}]", i),
                  fmt::format("time_constants[{}]", i));
    if (i > 0 && !(tau[i] > tau[i - 1])) {
      throw Error(fmt::format("{} time constant tau[{}] = {} must be > tau[{}] = {}", kCreepModel,
                              i, tau[i], i - 1, tau[i - 1]),
                  fmt::format("time_constants[{}]", i));
    }
  }
  rules.finite(p.leakage_conductance, "leakage conductance g", "leakage_conductance");
  rules.finite(p.leakage_current, "leakage current i0", "leakage_current");
  const std::size_t expected = tau.size() * p.thresholds.size();
  if (p.creep_weights.size() != expected) {
    throw Error(
        fmt::format("{} has {} creep weights but needs {} ({} time constants x {} "
                    "thresholds, row-major)",
                    kCreepModel, p.creep_weights.size(), expected, tau.size(), p.thresholds.size()),
        "creep_weights");
  }
  for (std::size_t ij = 0; ij < expected; ++ij) {
    rules.at_least(p.creep_weights[ij], 0.0, fmt::format("creep weight c[{}]", ij),
                   fmt::format("creep_weights[{}]", ij));
  }
}

}  // namespace

PrandtlIshlinskiiCreep::PrandtlIshlinskiiCreep(Params params)
    : params_(std::move(params)), hysteresis_(hysteresis_of(params_)) {
  validate_creep(params_);
  decay_.reserve(lags());
  for (double tau : params_.time_constants)
    decay_.push_back(std::exp(-params_.sample_time / tau));
}

PrandtlIshlinskiiCreep PrandtlIshlinskiiCreep::at_sample_time(double sample_time) const {
  auto params = params_;
  params.sample_time = sample_time;
  return PrandtlIshlinskiiCreep(std::move(params));
}

PrandtlIshlinskiiCreep::State PrandtlIshlinskiiCreep::initial_state() const {
  return state_at_rest(0.0);
}

PrandtlIshlinskiiCreep::State PrandtlIshlinskiiCreep::state_at_rest(double input) const {
  require_finite(input, "PI with creep rest input v0");
  return State{std::vector<double>(size(), input), std::vector<double>(size() * lags(), input)};
}

PrandtlIshlinskiiCreep::State PrandtlIshlinskiiCreep::periodic_state(
    std::span<const double> period) const {
  require_not_empty(period.size(), "PI with creep periodic input");
  require_finite(period, "PI with creep periodic input");
  State state = initial_state();
  for (double v : period)
    step(state, v);  // the plays are periodic from here on
  std::vector<double> play = state.play;
  const std::size_t n = size();
  std::vector<double> weighted(n * lags(), 0.0);  // sum_k a^(N-k) (1 - a) w_j[k]
  for (double v : period) {
    for (std::size_t j = 0; j < n; ++j)
      play[j] = play_step(v, params_.thresholds[j], play[j]);
    for (std::size_t i = 0; i < lags(); ++i) {
      for (std::size_t j = 0; j < n; ++j)
        weighted[i * n + j] = decay_[i] * weighted[i * n + j] + (1.0 - decay_[i]) * play[j];
    }
  }
  const auto samples = static_cast<double>(period.size());
  for (std::size_t i = 0; i < lags(); ++i) {
    // 1 - a^N, accurate also for a slow lag (a close to 1)
    const double settle = -std::expm1(-samples * params_.sample_time / params_.time_constants[i]);
    for (std::size_t j = 0; j < n; ++j)
      state.creep[i * n + j] = weighted[i * n + j] / settle;
  }
  state.leakage = 0.0;  // a drift has no periodic state: its charge counts from the start
  return state;
}

PrandtlIshlinskiiCreep::State PrandtlIshlinskiiCreep::make_state(std::vector<double> play,
                                                                 std::vector<double> creep,
                                                                 double leakage) const {
  require_reachable_plays(play, params_.thresholds, "PI with creep", "w");
  require_same_size(creep.size(), "PI with creep state z", size() * lags(),
                    "time constants x thresholds");
  require_finite(creep, "PI with creep state z");
  require_finite(leakage, "PI with creep state L");
  return State{std::move(play), std::move(creep), leakage};
}

double PrandtlIshlinskiiCreep::output(const State& state) const {
  require_same_size(state.play.size(), "PI with creep state w", size(), "thresholds r");
  require_same_size(state.creep.size(), "PI with creep state z", size() * lags(),
                    "time constants x thresholds");
  double y = hysteresis_.output(PrandtlIshlinskii::State{state.play});
  for (std::size_t ij = 0; ij < state.creep.size(); ++ij)
    y += params_.creep_weights[ij] * state.creep[ij];
  return y + state.leakage;
}

std::vector<double> PrandtlIshlinskiiCreep::instantaneous_weights() const {
  std::vector<double> weights = params_.weights;
  for (std::size_t i = 0; i < lags(); ++i) {
    for (std::size_t j = 0; j < size(); ++j)
      weights[j] += params_.creep_weights[i * size() + j] * (1.0 - decay_[i]);
  }
  weights[0] += params_.leakage_conductance * params_.sample_time;
  return weights;
}

std::vector<double> log_spaced_time_constants(double shortest, double longest, std::size_t count) {
  if (!(std::isfinite(shortest) && std::isfinite(longest) && shortest > 0.0 &&
        longest >= shortest)) {
    throw Error(
        fmt::format("log-spaced time constants: shortest = {} and longest = {} must be "
                    "finite with 0 < shortest <= longest",
                    shortest, longest));
  }
  if (count == 0 || (count > 1 && !(longest > shortest))) {
    throw Error(
        fmt::format("log-spaced time constants: count = {} must be >= 1, and 1 when "
                    "shortest = longest = {}",
                    count, shortest));
  }
  std::vector<double> tau(count, shortest);
  for (std::size_t i = 1; i < count; ++i) {
    const double share = static_cast<double>(i) / static_cast<double>(count - 1);
    tau[i] = shortest * std::pow(longest / shortest, share);
  }
  tau.back() = std::max(tau.back(), longest);
  return tau;
}

PrandtlIshlinskiiCreep::Params pi_logarithmic_creep(const PrandtlIshlinskii::Params& pi,
                                                    double gamma, double t0, std::size_t decades,
                                                    std::size_t per_decade, double sample_time) {
  const detail::ParameterRules rules{"logarithmic creep"};
  rules.at_least(gamma, 0.0, "gamma", "gamma");
  rules.greater(t0, 0.0, "t0", "t0");
  rules.count_in(decades, 1, 12, "decades", "decades");
  rules.count_in(per_decade, 1, 12, "lags per decade", "per_decade");
  // S(t) = sum_i (1 - exp(-t / tau_i)) over tau_i = tau_0 10^(i / m), i = 0, 1, ... grows by m
  // per decade of t: S(t) = m (log10(t / tau_0) + euler_gamma / ln 10) + 1/2 inside the covered
  // range (the integral of 1 - exp(-10^-x) minus a unit step is euler_gamma / ln 10, the 1/2 is the
  // sum's end correction). tau_0 = t0 e^euler_gamma 10^(1 / (2 m)) puts its zero at t0.
  const double tau0 =
      t0 * std::exp(std::numbers::egamma) * std::pow(10.0, 0.5 / static_cast<double>(per_decade));
  const std::size_t count = decades * per_decade + 1;
  PrandtlIshlinskiiCreep::Params params{pi.thresholds, pi.weights, {}, {}, sample_time, pi.offset};
  params.time_constants =
      log_spaced_time_constants(tau0, tau0 * std::pow(10.0, static_cast<double>(decades)), count);
  for (std::size_t i = 0; i < count; ++i) {
    for (double p : pi.weights)
      params.creep_weights.push_back(gamma * p / static_cast<double>(per_decade));
  }
  return params;
}

}  // namespace hyst
