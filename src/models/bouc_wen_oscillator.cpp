#include "hyst/models/bouc_wen_oscillator.hpp"

#include "../core/detail/enum_names.hpp"
#include "detail/parameter_rules.hpp"

namespace hyst {
BoucWenOscillator::BoucWenOscillator(Params params) : params_(params) {
  const detail::ParameterRules rules{"Bouc-Wen oscillator"};
  rules.greater(params_.mass, 0.0, "mass m", "mass");
  rules.at_least(params_.damping, 0.0, "damping c", "damping");
  rules.at_least(params_.stiffness, 0.0, "stiffness k", "stiffness");
  rules.greater(params_.alpha, 0.0, "alpha", "alpha");
  rules.at_least(params_.beta, 0.0, "beta", "beta");
  rules.finite(params_.gamma, "gamma", "gamma");
  rules.finite(params_.delta, "delta", "delta");
  rules.at_least(params_.nu, 1.0, "exponent nu", "nu");
  rules.greater(params_.sample_time, 0.0, "sample time Ts", "sample_time");
  rules.count_in(params_.substeps, 1, 100000, "substeps", "substeps");
  rules.integration_tolerance(params_.tolerance);
  coefficients_ = {params_.mass,
                   params_.damping,
                   params_.stiffness,
                   params_.alpha,
                   params_.beta * params_.gamma,
                   params_.beta * params_.delta,
                   params_.nu};
  nu_is_one_ = params_.nu == 1.0;
}

BoucWenOscillator::Params BoucWenOscillator::benchmark() {
  return Params{};
}

BoucWenOscillator::InputBetweenSamples input_between_samples_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<BoucWenOscillator::InputBetweenSamples>,
                             "input_between_samples", "input_between_samples");
}

}  // namespace hyst
