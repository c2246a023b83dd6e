#include "hyst/inverse/inverse_modified_prandtl_ishlinskii_creep.hpp"

namespace hyst {

InverseModifiedPrandtlIshlinskiiCreep::InverseModifiedPrandtlIshlinskiiCreep(
    const ModifiedPrandtlIshlinskiiCreep& model, const Options& options)
    : forward_(model),
      dead_zone_inverse_(model.dead_zone().inverse()),
      core_inverse_(model.hysteresis_creep(), options) {}

}  // namespace hyst
