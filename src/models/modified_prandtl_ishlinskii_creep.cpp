#include "hyst/models/modified_prandtl_ishlinskii_creep.hpp"

#include <utility>

#include "detail/parameter_rules.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

ModifiedPrandtlIshlinskiiCreep::ModifiedPrandtlIshlinskiiCreep(Params params)
    : params_(std::move(params)),
      core_(detail::ParameterRules{"modified PI with creep"}.part<PrandtlIshlinskiiCreep>(
          params_.pi_creep, "pi_creep")),
      dead_zone_(detail::ParameterRules{"modified PI with creep"}.part<DeadZoneSuperposition>(
          params_.dead_zone, "dead_zone")) {
  const detail::ParameterRules rules{"modified PI with creep"};
  rules.finite(params_.offset, "offset", "offset");
  if (core_.has_leakage()) {
    throw Error(
        "modified PI with creep: pi_creep.leakage_conductance and pi_creep.leakage_current must "
        "be 0 (a leakage drift adds to the output after the dead zones: use pi_creep)",
        "pi_creep.leakage_conductance");
  }
  rules.output_limits(params_.output_min, params_.output_max);
}

bool ModifiedPrandtlIshlinskiiCreep::is_invertible() const {
  const PrandtlIshlinskii instantaneous(
      {core_.params().thresholds, core_.instantaneous_weights(), 0.0});
  return instantaneous.is_invertible() && dead_zone_.is_invertible();
}

ModifiedPrandtlIshlinskiiCreep ModifiedPrandtlIshlinskiiCreep::at_sample_time(
    double sample_time) const {
  auto params = params_;
  params.pi_creep.sample_time = sample_time;
  return ModifiedPrandtlIshlinskiiCreep(std::move(params));
}

}  // namespace hyst
