#pragma once
//! \file
//! Classical RK4 under step-size control, for a right-hand side that is smooth except where it
//! switches between regimes (a kink in the slope, e.g. the Jiles-Atherton switch delta_M).
//!
//! Error estimate of a step of length h (the slope k5 = f(x_new) at its end is the next step's
//! first stage, so a step costs four evaluations): the embedded third-order solution
//! x + h (k1 + 2 k2 + 2 k3 + k5) / 6 differs from the RK4 one by h (k4 - k5) / 6. That estimate
//! only sees the error of the stage values in x; across a regime switch inside the step (the stages
//! do not all report the same regime) the error is of order h^2 times the jump in the slope's
//! derivative, which it misses, and such a step is measured against the trapezoidal rule
//! h (k1 + k5) / 2 instead, whose error is of the same order there. A step is accepted when the
//! estimate (the value part for dual numbers) is at most `tolerance`; the next step follows from
//! the usual rule 0.9 (tolerance / error)^(1/4), within [0.2, 4] times the last one.
//!
//! Every call starts afresh from `first_step` (no memory across calls: the result is a function of
//! the state and the interval alone, so a copied or reloaded state continues exactly). The step
//! sequence is chosen from the values only: with dual numbers the derivatives are those of the
//! discrete map for that sequence.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "hyst/core/scalar_value.hpp"

namespace hyst {

//! Integrates x' = f(x, tau, regime) over a length `span` (negative for a decreasing input), tau
//! running from 0 to 1 across it; f returns dx/d(span) and sets `regime` (an int that changes where
//! f switches form). `tolerance` > 0 is the largest accepted error estimate per step (in x's units,
//! largest component); `first_step` > 0 caps the first trial step (the whole span otherwise).
//! Steps shorter than 1e-9 |span| are accepted as they are (a step can always finish); a
//! non-finite error estimate (an overflowing or NaN state) ends with x NaN.
template <class T, std::size_t N, class Rhs>
inline void rk4_controlled_integrate(std::array<T, N>& x, double span, double tolerance,
                                     double first_step, const Rhs& f) {
  const double length = std::abs(span);
  const double sign = span < 0.0 ? -1.0 : 1.0;
  if (!std::isfinite(length)) {
    x.fill(T(std::numeric_limits<double>::quiet_NaN()));
    return;
  }
  const double shortest = 1e-9 * length;
  double u = 0.0;
  double h = std::min(first_step, length);
  int regime1 = 0;
  std::array<T, N> k1 = f(x, 0.0, regime1);
  while (u < length) {
    const bool last = h >= length - u;
    if (last) h = length - u;
    const double tau_mid = (u + 0.5 * h) / length;
    const double tau1 = last ? 1.0 : (u + h) / length;
    const double hs = sign * h;
    int regime = 0;
    std::array<T, N> xs;
    for (std::size_t i = 0; i < N; ++i)
      xs[i] = x[i] + (0.5 * hs) * k1[i];
    const std::array<T, N> k2 = f(xs, tau_mid, regime);
    bool switched = regime != regime1;
    for (std::size_t i = 0; i < N; ++i)
      xs[i] = x[i] + (0.5 * hs) * k2[i];
    const std::array<T, N> k3 = f(xs, tau_mid, regime);
    switched = switched || regime != regime1;
    for (std::size_t i = 0; i < N; ++i)
      xs[i] = x[i] + hs * k3[i];
    const std::array<T, N> k4 = f(xs, tau1, regime);
    switched = switched || regime != regime1;
    std::array<T, N> next;
    for (std::size_t i = 0; i < N; ++i)
      next[i] = x[i] + (hs / 6.0) * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    int regime5 = 0;
    const std::array<T, N> k5 = f(next, tau1, regime5);
    switched = switched || regime5 != regime1;
    double error = 0.0;
    for (std::size_t i = 0; i < N; ++i) {
      const double k1v = scalar_value(k1[i]);
      const double k5v = scalar_value(k5[i]);
      const double e =
          switched ? std::abs(scalar_value(next[i]) - scalar_value(x[i]) - 0.5 * hs * (k1v + k5v))
                   : std::abs(hs / 6.0 * (scalar_value(k4[i]) - k5v));
      if (!(e <= error)) error = e;  // NaN kept
    }
    if (!std::isfinite(error)) {
      x.fill(T(std::numeric_limits<double>::quiet_NaN()));
      return;
    }
    // 0.9 (tolerance / error)^(1/4), in [0.2, 4].
    const double factor =
        error > 0.0 ? std::clamp(0.9 * std::sqrt(std::sqrt(tolerance / error)), 0.2, 4.0) : 4.0;
    if (error <= tolerance || h <= shortest) {
      x = next;
      k1 = k5;
      regime1 = regime5;
      u = last ? length : u + h;
    }
    h = std::max(h * factor, shortest);
  }
}

}  // namespace hyst
