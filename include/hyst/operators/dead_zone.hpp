#pragma once
//! \file
//! Dead-zone operator S_d (memory-free), the building block of the modified PI model:
//!
//!     S_d(y) = max(y - d, 0)   for d > 0
//!              y               for d = 0
//!              min(y - d, 0)   for d < 0
//!
//! Source: Kuhnen (2003), Eur. J. Control 9:407-418 (d >= 0); the two-sided set with d < 0 follows
//! Al Janaideh et al.

#include <algorithm>

namespace hyst {

class DeadZone {
 public:
  //! Throws hyst::Error unless d is finite.
  explicit DeadZone(double threshold);

  double threshold() const { return threshold_; }

  double operator()(double input) const noexcept {
    if (threshold_ > 0.0) return std::max(input - threshold_, 0.0);
    if (threshold_ < 0.0) return std::min(input - threshold_, 0.0);
    return input;
  }

 private:
  double threshold_;
};

}  // namespace hyst
