#include "hyst/operators/kp_kernel.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

KpKernel::KpKernel(double down_switch, double up_switch, double ramp)
    : down_(down_switch), up_(up_switch), ramp_(ramp), two_over_ramp_(2.0 / ramp) {
  if (!std::isfinite(down_) || !std::isfinite(up_) || !(down_ <= up_)) {
    throw Error(
        fmt::format("KP kernel switching points s1 = {} and s2 = {} must be finite with "
                    "s1 <= s2",
                    down_, up_));
  }
  if (!std::isfinite(ramp_) || !(ramp_ > 0.0)) {
    throw Error(fmt::format("KP kernel ramp width a = {} must be finite and > 0", ramp_));
  }
}

}  // namespace hyst
