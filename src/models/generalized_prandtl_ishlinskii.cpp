#include "hyst/models/generalized_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {
namespace {

// Keeps a mistyped m (e.g. a negative number read into a size) from allocating the machine away.
constexpr std::size_t kMaxOperators = 1'000'000;

void require_finite_field(double value, std::string_view what, std::string_view field) {
  if (!std::isfinite(value)) {
    throw Error(fmt::format("GPI {} = {} is not finite", what, value), std::string(field));
  }
}

void validate_exponential(const GpiParams& params) {
  if (!params.thresholds.empty()) {
    throw Error(fmt::format("GPI thresholds are given ({} values) but density = exponential "
                            "computes them as r_j = alpha j; set density = free to list them",
                            params.thresholds.size()),
                "thresholds");
  }
  if (!params.weights.empty()) {
    throw Error(fmt::format("GPI weights are given ({} values) but density = exponential "
                            "computes them as p_j = rho exp(-tau r_j); set density = free to list "
                            "them",
                            params.weights.size()),
                "weights");
  }
  require_finite_field(params.rho, "density rho", "rho");
  if (!(params.rho > 0.0)) {
    throw Error(fmt::format("GPI density rho = {} must be > 0", params.rho), "rho");
  }
  require_finite_field(params.tau, "density tau", "tau");
  require_finite_field(params.alpha, "threshold spacing alpha", "alpha");
  if (!(params.alpha > 0.0)) {
    throw Error(fmt::format("GPI threshold spacing alpha = {} must be > 0", params.alpha), "alpha");
  }
  if (params.m > kMaxOperators) {
    throw Error(fmt::format("GPI m = {} must be <= {} (m + 1 operators)", params.m, kMaxOperators),
                "m");
  }
}

void validate_free(const GpiParams& params) {
  const auto& r = params.thresholds;
  const auto& p = params.weights;
  if (r.empty()) throw Error("GPI thresholds r is empty (density = free)", "thresholds");
  require_same_length(r.size(), p.size(), "GPI", {"thresholds", "r", "thresholds"},
                      {"weights", "p", "weights"});
  for (std::size_t j = 0; j < r.size(); ++j) {
    require_finite_field(r[j], fmt::format("threshold r[{}]", j), fmt::format("thresholds[{}]", j));
    require_finite_field(p[j], fmt::format("weight p[{}]", j), fmt::format("weights[{}]", j));
  }
  require_increasing_from_zero(r, "GPI threshold", "r", "thresholds",
                               "the r = 0 operator carries the envelope");
  if (!(p[0] > 0.0)) {
    throw Error(fmt::format("GPI weight p[0] = {} must be > 0 (monotone, invertible model)", p[0]),
                "weights[0]");
  }
  double sum = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    sum += p[j];
    if (!(sum > 0.0)) {
      throw Error(fmt::format("GPI partial sum S[{}] = p[0] + ... + p[{}] = {} must be > 0 "
                              "(monotone, invertible model)",
                              j, j, sum),
                  fmt::format("weights[{}]", j));
    }
  }
}

template <Envelope E>
void validate(const GpiParams& params) {
  if (params.envelope != E::kind) {
    throw Error(fmt::format("GPI envelope = {} does not match the model type, whose envelope is {}",
                            to_string(params.envelope), to_string(E::kind)),
                "envelope");
  }
  E::validate(params.ascending, {"GPI", "ascending", 'a'});
  E::validate(params.descending, {"GPI", "descending", 'b'});
  if (params.density == GpiDensity::exponential) {
    validate_exponential(params);
  } else {
    validate_free(params);
  }
  check_envelope_ordering<E>(params.ascending.data(), params.descending.data(), params.input_min,
                             params.input_max, "GPI");
  require_finite_field(params.initial_input, "initial input i0", "initial_input");
  if (params.initial_input < params.input_min || params.initial_input > params.input_max) {
    throw Error(fmt::format("GPI initial input i0 = {} must lie in the operating range [{}, {}]",
                            params.initial_input, params.input_min, params.input_max),
                "initial_input");
  }
}

}  // namespace

GpiDensity gpi_density_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<GpiDensity>, "GPI density", "density");
}

template <Envelope E>
GeneralizedPrandtlIshlinskii<E>::GeneralizedPrandtlIshlinskii(Params params)
    : params_(std::move(params)) {
  validate<E>(params_);
  if (params_.density == GpiDensity::exponential) {
    thresholds_.resize(params_.m + 1);
    weights_.resize(params_.m + 1);
    GpiKernel<E, double>::exponential_density(params_.rho, params_.tau, params_.alpha, params_.m,
                                              thresholds_.data(), weights_.data());
    for (std::size_t j = 0; j < weights_.size(); ++j) {
      if (!(std::isfinite(weights_[j]) && weights_[j] > 0.0)) {
        throw Error(fmt::format("GPI weight p[{}] = rho exp(-tau r_{}) = {} exp({} * {}) = {} is "
                                "not a finite positive number: tau * alpha * m is too large in "
                                "magnitude",
                                j, j, params_.rho, -params_.tau, thresholds_[j], weights_[j]),
                    "tau");
      }
    }
  } else {
    thresholds_ = params_.thresholds;
    weights_ = params_.weights;
  }
}

template <Envelope E>
double GeneralizedPrandtlIshlinskii<E>::weight_sum() const {
  double sum = 0.0;
  for (double p : weights_)
    sum += p;
  return sum;
}

template <Envelope E>
PrandtlIshlinskii GeneralizedPrandtlIshlinskii<E>::classical() const {
  return PrandtlIshlinskii({.thresholds = thresholds_, .weights = weights_, .offset = 0.0});
}

template <Envelope E>
typename GeneralizedPrandtlIshlinskii<E>::State GeneralizedPrandtlIshlinskii<E>::initial_state()
    const {
  return state_at_rest(params_.initial_input, LoopBranch::ascending);
}

template <Envelope E>
typename GeneralizedPrandtlIshlinskii<E>::State GeneralizedPrandtlIshlinskii<E>::state_at_rest(
    double input, LoopBranch branch) const {
  require_finite(input, "GPI rest input v0");
  State state{std::vector<double>(size())};
  GpiKernel<E, double>::rest_state(params_.ascending.data(), params_.descending.data(), input,
                                   branch, size(), state.play.data());
  return state;
}

template <Envelope E>
typename GeneralizedPrandtlIshlinskii<E>::State GeneralizedPrandtlIshlinskii<E>::make_state(
    std::vector<double> play) const {
  // Every step applies the same clamp max(a - r_j, min(b + r_j, .)) to all operators; states
  // breaking the bound are unreachable (and the inverse could not be started from them).
  require_reachable_plays(play, thresholds_, "GPI", "z");
  return State{std::move(play)};
}

template <Envelope E>
double GeneralizedPrandtlIshlinskii<E>::output(const State& state) const {
  require_same_size(state.play.size(), "GPI state z", size(), "GPI thresholds r");
  return GpiKernel<E, double>::output(weights_.data(), state.play.data(), size());
}

GpiParams rescale_density(const GpiParams& params, double factor) {
  if (!(std::isfinite(factor) && factor > 0.0)) {
    throw Error(fmt::format("GPI rescaling factor = {} must be finite and > 0", factor));
  }
  GpiParams scaled = params;
  visit_envelope(params.envelope, [&](auto envelope) {
    using E = decltype(envelope);
    E::validate(params.ascending, {"GPI", "ascending", 'a'});
    E::validate(params.descending, {"GPI", "descending", 'b'});
    E::scale_output(scaled.ascending.data(), 1.0 / factor);
    E::scale_output(scaled.descending.data(), 1.0 / factor);
  });
  if (params.density == GpiDensity::exponential) {
    scaled.rho *= factor;
    scaled.tau *= factor;
    scaled.alpha /= factor;
  } else {
    for (double& r : scaled.thresholds)
      r /= factor;
    for (double& p : scaled.weights)
      p *= factor;
  }
  return scaled;
}

template struct GpiKernel<LinearEnvelope, double>;
template struct GpiKernel<TanhEnvelope, double>;
template struct GpiKernel<ArctanEnvelope, double>;
template class GeneralizedPrandtlIshlinskii<LinearEnvelope>;
template class GeneralizedPrandtlIshlinskii<TanhEnvelope>;
template class GeneralizedPrandtlIshlinskii<ArctanEnvelope>;

}  // namespace hyst
