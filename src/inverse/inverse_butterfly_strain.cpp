#include "hyst/inverse/inverse_butterfly_strain.hpp"

#include <algorithm>
#include <cmath>

namespace hyst {

InverseButterflyStrain::InverseButterflyStrain(ButterflyStrain model,
                                               const NumericalInverseOptions& options)
    : search_(std::move(model), options),
      thresholds_([this] {
        const auto& grid = search_.forward().params().polarisation.everett;
        return preisach_thresholds(grid.levels, grid.lower, grid.upper, grid.layout);
      }()),
      hold_default_(std::clamp(0.0, search_.input_min(), search_.input_max())) {}

bool InverseButterflyStrain::invertible_from(const State& state) const noexcept {
  const double lo = input_min();
  const double hi = input_max();
  double previous = model().preview(state, lo);
  double previous_input = lo;
  int direction = 0;  // +1 rising, -1 falling, 0 flat so far
  const auto consistent = [&](double input) {
    const double y = model().preview(state, input);
    const double change = y - previous;
    const double noise = 1e-12 * (std::abs(y) + std::abs(previous));
    const int sign = change > noise ? 1 : (change < -noise ? -1 : 0);
    if (sign != 0 && direction != 0 && sign != direction) return false;
    if (sign != 0) direction = sign;
    previous = y;
    previous_input = input;
    return true;
  };
  for (double c : thresholds_) {
    if (c <= lo) continue;
    if (c >= hi) break;
    if (!consistent(0.5 * (previous_input + c)) || !consistent(c)) return false;
  }
  if (!consistent(0.5 * (previous_input + hi)) || !consistent(hi)) return false;
  // Between the sampled points y moves with d u: d must go the same way.
  const double d = model().params().field_coefficient;
  return !(d > 0.0 && direction < 0) && !(d < 0.0 && direction > 0);
}

}  // namespace hyst
