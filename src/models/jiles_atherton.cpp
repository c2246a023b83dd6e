#include "hyst/models/jiles_atherton.hpp"

#include <algorithm>

#include "../core/detail/enum_names.hpp"
#include "detail/parameter_rules.hpp"

namespace hyst {
JilesAtherton::JilesAtherton(Params params) : params_(params) {
  const detail::ParameterRules rules{"Jiles-Atherton"};
  rules.greater(params_.ms, 0.0, "saturation magnetisation M_s", "ms");
  rules.greater(params_.a, 0.0, "a", "a");
  rules.greater(params_.k, 0.0, "pinning k", "k");
  rules.at_least(params_.c, 0.0, "reversibility c", "c");
  rules.below(params_.c, 1.0, "reversibility c", "c");
  rules.at_least(params_.alpha, 0.0, "coupling alpha", "alpha");
  const double coupling = params_.alpha * params_.ms / (3.0 * params_.a);
  if (!(coupling < 1.0)) {
    throw Error(fmt::format("Jiles-Atherton alpha M_s / (3 a) = {} must be < 1 (otherwise the "
                            "anhysteretic curve is not single valued)",
                            coupling),
                "alpha");
  }
  rules.at_least(params_.max_field_step, 0.0, "max_field_step", "max_field_step");
  rules.integration_tolerance(params_.tolerance);
  coefficients_ = {params_.ms, params_.a, params_.k, params_.c, params_.alpha};
  integration_ = integration_of(params_);
}

JilesAtherton::State JilesAtherton::state_at(double field, double magnetisation) const {
  const detail::ParameterRules rules{"Jiles-Atherton state"};
  rules.finite(field, "field H", "field");
  rules.finite(magnetisation, "magnetisation M", "magnetisation");
  if (!(std::abs(magnetisation) < params_.ms)) {
    rules.fail("|magnetisation M|", "magnetisation", std::abs(magnetisation),
               fmt::format("must be < M_s = {}", params_.ms));
  }
  State state;
  state.field = field;
  state.magnetisation = magnetisation;
  if (params_.variant == JilesAthertonVariant::original) {
    const double m_an = anhysteretic(field + params_.alpha * magnetisation);
    state.irreversible = (magnetisation - params_.c * m_an) / (1.0 - params_.c);
  } else {
    state.irreversible = magnetisation;
  }
  return state;
}

JilesAtherton::State JilesAtherton::state_at(double field, double magnetisation,
                                             double irreversible, double direction) const {
  State state = state_at(field, magnetisation);
  const detail::ParameterRules rules{"Jiles-Atherton state"};
  rules.finite(irreversible, "irreversible magnetisation M_irr", "irreversible");
  if (direction != 1.0 && direction != -1.0) {
    rules.fail("direction", "direction", direction, "must be 1 or -1");
  }
  state.irreversible = irreversible;
  state.direction = direction;
  return state;
}

double JilesAtherton::susceptibility(const State& state, double direction) const {
  const auto& p = coefficients_;
  const double delta = direction >= 0.0 ? 1.0 : -1.0;
  const double xe = (state.field + p.alpha * state.magnetisation) / p.a;
  const double chi_an = p.ms / p.a * detail::langevin_derivative(xe);
  const double m_an = p.ms * detail::langevin(xe);
  double slope = 0.0;
  if (params_.variant == JilesAthertonVariant::original) {
    const double diff = m_an - state.irreversible;
    const double irreversible =
        delta * diff > 0.0 ? diff / detail::ja_denominator(p.k, p.alpha, diff, delta) : 0.0;
    // dM = c chi_an (dH + alpha dM) + (1 - c) dM_irr.
    slope = ((1.0 - p.c) * irreversible + p.c * chi_an) / (1.0 - p.c * p.alpha * chi_an);
  } else {
    const double diff = m_an - state.magnetisation;
    double n = p.c * delta * p.k * chi_an;
    if (delta * diff > 0.0) n += diff;
    slope = n / detail::ja_denominator(p.k, p.alpha, n, delta);
  }
  return std::max(slope, 0.0);
}

JilesAthertonVariant jiles_atherton_variant_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<JilesAthertonVariant>, "Jiles-Atherton variant",
                             "variant");
}

}  // namespace hyst
