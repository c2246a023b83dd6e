#include "hyst/models/modified_prandtl_ishlinskii.hpp"

#include <utility>

#include "detail/parameter_rules.hpp"

namespace hyst {

ModifiedPrandtlIshlinskii::ModifiedPrandtlIshlinskii(Params params)
    : params_(std::move(params)),
      pi_(detail::ParameterRules{"modified PI"}.part<PrandtlIshlinskii>(params_.pi, "pi")),
      dead_zone_(detail::ParameterRules{"modified PI"}.part<DeadZoneSuperposition>(
          params_.dead_zone, "dead_zone")) {
  const detail::ParameterRules rules{"modified PI"};
  rules.finite(params_.offset, "offset", "offset");
  rules.output_limits(params_.output_min, params_.output_max);
}

}  // namespace hyst
