#pragma once
//! \file
//! Superposition of dead-zone operators: the memory-free, piecewise-linear output map of the
//! modified Prandtl-Ishlinskii model.
//!
//!     S(x) = sum_{i=-l..l} g_i S_{d_i}(x),   d_{-l} < ... < d_{-1} < d_0 = 0 < d_1 < ... < d_l
//!
//! with S_d the dead zone (dead_zone.hpp). S(0) = 0; the slope of S between thresholds is a
//! partial sum of the weights outward from d_0: sum_{j=0..i} g_j above d_i (i > 0),
//! sum_{j=i..0} g_j below d_i (i < 0). S is strictly increasing, hence invertible, iff g_0 > 0
//! and every such partial sum is > 0; its inverse is again a dead-zone superposition:
//!
//!     g'_0 = 1/g_0,  d'_0 = 0
//!     i > 0:  g'_i = -g_i / ((sum_{j=0..i} g_j)(sum_{j=0..i-1} g_j))
//!             d'_i = sum_{j=0..i} g_j (d_i - d_j)
//!     i < 0:  g'_i = -g_i / ((sum_{j=i..0} g_j)(sum_{j=i+1..0} g_j))
//!             d'_i = sum_{j=i..0} g_j (d_i - d_j)
//!
//! (d'_i = S(d_i): the thresholds move with the map.) Thresholds are listed in increasing order,
//! with exactly one equal to 0; the negative ones may be absent (Kuhnen's original, d_i >= 0).
//! Sources: Kuhnen (2003), Eur. J. Control 9:407-418; reference prandtl_ishlinskii.md sec. 3.

#include <cstddef>
#include <vector>

#include "hyst/operators/dead_zone.hpp"

namespace hyst {

class DeadZoneSuperposition {
 public:
  struct Params {
    std::vector<double> thresholds{};  //!< d_i, strictly increasing, one of them 0
    std::vector<double> weights{};     //!< g_i, one per threshold
  };

  //! Throws hyst::Error naming the field ("dead-zone threshold d[2] = 0.1 must be > d[1] = 0.4").
  explicit DeadZoneSuperposition(Params params);

  const Params& params() const { return params_; }
  std::size_t size() const { return params_.thresholds.size(); }
  //! Index of the threshold d = 0.
  std::size_t zero_index() const { return zero_; }

  //! True iff g_0 > 0 and every outward partial sum is > 0 (strictly increasing map).
  bool is_invertible() const;
  //! The inverse map; throws hyst::Error naming the partial sum that is not > 0.
  DeadZoneSuperposition inverse() const;

  double operator()(double x) const noexcept {
    const double* g = params_.weights.data();
    double y = 0.0;
    for (std::size_t i = 0; i < zones_.size(); ++i)
      y += g[i] * zones_[i](x);
    return y;
  }

 private:
  Params params_;
  std::vector<DeadZone> zones_;
  std::size_t zero_ = 0;
};

}  // namespace hyst
