#include "hyst/models/backlash_like.hpp"

#include "detail/parameter_rules.hpp"

namespace hyst {

BacklashLike::BacklashLike(Params params) : params_(params) {
  const detail::ParameterRules rules{"backlash-like"};
  rules.greater(params_.a, 0.0, "a", "a");
  rules.greater(params_.c, 0.0, "c", "c");
  rules.below(params_.b1, params_.c, "B1", "b1");
}

BacklashLike::State BacklashLike::state_at(double input, double output) const {
  const detail::ParameterRules rules{"backlash-like state"};
  rules.finite(input, "input", "input");
  rules.finite(output, "output", "output");
  return {input, output};
}

}  // namespace hyst
