#pragma once
// A dead-zone superposition with fixed thresholds written through its slopes, the form in which
// the modified PI fits find it by linear or bounded nonlinear least squares:
//
//     S(x) = sum_i g_i S_{d_i}(x),   g_0 = 1   (d_0 = 0)
//          = x - D_1 - D_-1 + sum_i T_i (D_i - D_{i+1}) + sum_i U_i (D_-i - D_-(i+1)),
//
// D_i = S_{d_i}(x), T_i (U_i) the slope of S between d_i and d_{i+1} above 0 (below 0), the
// outward partial sums of the weights. With T_i, U_i >= eps as the unknowns t_i = T_i - eps >= 0,
// S is linear in them, and monotone and invertible for every feasible value. The equation-error
// fits use it for the inverse map S' (Kuhnen), the output-error refinement for S itself.

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/operators/dead_zone_superposition.hpp"

namespace hyst::detail {

class DeadZoneSlopes {
 public:
  // `thresholds` d_i, increasing, containing 0 (validated as a DeadZoneSuperposition);
  // `min_slope` eps > 0.
  DeadZoneSlopes(std::vector<double> thresholds, double min_slope);

  // l thresholds per side, evenly spaced over (-below, 0) and (0, above).
  static std::vector<double> default_thresholds(std::size_t per_side, double below, double above);

  // Number of unknowns t_i (thresholds other than 0): those above 0 first, outwards, then those
  // below 0, outwards.
  std::size_t unknowns() const { return above_ + below_; }

  // S(x) = known + sum_i e_i t_i: writes the e_i (unknowns() of them) into `terms` and returns
  // the known part.
  double terms(double x, std::span<double> terms) const;
  // dS/dx at x for the unknowns t: the slope of the segment x lies in (1 around 0).
  double slope(double x, std::span<const double> t) const;

  // S for the unknowns t.
  DeadZoneSuperposition map(std::span<const double> t) const;
  // The unknowns of `map` (with these thresholds and g_0 = 1), slopes below eps raised to it.
  std::vector<double> unknowns_of(const DeadZoneSuperposition& map) const;

 private:
  std::vector<double> thresholds_;
  double min_slope_;
  std::size_t zero_ = 0;   // index of d_0 = 0
  std::size_t above_ = 0;  // thresholds d_1 .. d_above
  std::size_t below_ = 0;  // thresholds d_-1 .. d_-below
};

}  // namespace hyst::detail
