#include "hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp"

namespace hyst {

InverseModifiedPrandtlIshlinskii::InverseModifiedPrandtlIshlinskii(
    const ModifiedPrandtlIshlinskii& model, const Options& options)
    : dead_zone_inverse_(model.dead_zone().inverse()),
      pi_inverse_(model.hysteresis(), options),
      offset_(model.params().offset) {}

}  // namespace hyst
