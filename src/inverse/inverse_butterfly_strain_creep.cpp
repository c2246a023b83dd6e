#include "hyst/inverse/inverse_butterfly_strain_creep.hpp"

#include <algorithm>
#include <cmath>

namespace hyst {
namespace {

constexpr int kSlopeSamples = 64;  // intervals of the polarisation range checked

}  // namespace

InverseButterflyStrainCreep::InverseButterflyStrainCreep(ButterflyStrainCreep model,
                                                         const NumericalInverseOptions& options)
    : search_(std::move(model), options),
      hold_default_(std::clamp(0.0, search_.input_min(), search_.input_max())) {}

bool InverseButterflyStrainCreep::invertible_from(const State& state) const noexcept {
  const double low = model().preview_polarisation(state, input_min());
  const double high = model().preview_polarisation(state, input_max());
  const double d = model().params().butterfly.field_coefficient;
  int direction = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
  if (!(high > low)) return true;  // P fixed over the range: y moves with d u alone
  const auto& butterfly = model().butterfly();
  for (int s = 0; s <= kSlopeSamples; ++s) {
    const double P = low + (high - low) * static_cast<double>(s) / kSlopeSamples;
    const double slope = butterfly.strain_slope(P);
    const int sign = slope > 0.0 ? 1 : (slope < 0.0 ? -1 : 0);
    if (sign == 0) continue;
    if (direction != 0 && sign != direction) return false;
    direction = sign;
  }
  return true;
}

}  // namespace hyst
