#include "hyst/operators/dead_zone.hpp"

#include "hyst/core/checks.hpp"

namespace hyst {

DeadZone::DeadZone(double threshold) : threshold_(threshold) {
  require_finite(threshold, "dead-zone threshold d");
}

}  // namespace hyst
