#pragma once
//! \file
//! Adaptive integration between two samples with an error tolerance: Boost.Odeint's
//! Dormand-Prince 5(4) stepper (runge_kutta_dopri5) under its step-size controller. The state is a
//! std::array, so nothing is allocated. The right-hand side has the signature of rk4_integrate()
//! (runge_kutta.hpp): `f(state, tau)` with tau in [0, 1] across the interval, returning dx/dt.

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include <boost/numeric/odeint.hpp>

#include "hyst/core/runge_kutta.hpp"

namespace hyst {

//! Integrates x' = f(x, tau) over a length `span` (!= 0; negative for a decreasing input, as the
//! rate-independent models integrate in the input) with absolute and relative error tolerance
//! `tolerance` per step (> 0).
template <std::size_t N, class Rhs>
inline void dopri5_integrate(std::array<double, N>& x, double span, double tolerance,
                             const Rhs& f) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, N>;
  auto stepper = odeint::make_controlled(tolerance, tolerance, odeint::runge_kutta_dopri5<State>());
  // Odeint runs forward over u in [0, |span|]; dx/du = sign(span) f.
  const double length = std::abs(span);
  if (!std::isfinite(length)) {  // a NaN or infinite input: NaN out, as with fixed RK4 steps
    x.fill(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  const double sign = span < 0.0 ? -1.0 : 1.0;
  const double inverse_length = 1.0 / length;
  auto system = [&](const State& s, State& dxdu, double u) {
    dxdu = f(s, u * inverse_length);
    for (double& d : dxdu)
      d *= sign;
  };
  odeint::integrate_adaptive(stepper, system, x, 0.0, length, 0.25 * length);
}

//! One sample of a differential model: adaptive Dormand-Prince when `tolerance` > 0 (double state
//! only), otherwise `substeps` fixed RK4 steps (the path of ceres::Jet states in the fitters).
template <class T, std::size_t N, class Rhs>
inline void integrate_sample(std::array<T, N>& x, const T& span, std::size_t substeps,
                             double tolerance, const Rhs& f) {
  if constexpr (std::is_same_v<T, double>) {
    if (tolerance > 0.0) {
      dopri5_integrate(x, span, tolerance, f);
      return;
    }
  }
  rk4_integrate(x, span, substeps, f);
}

}  // namespace hyst
