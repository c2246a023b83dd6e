#pragma once
//! \file
//! Adaptive integration between two samples with an error tolerance: Boost.Odeint's
//! Dormand-Prince 5(4) stepper (runge_kutta_dopri5) under its step-size controller. The state is a
//! std::array, so nothing is allocated. The right-hand side has the signature of rk4_integrate()
//! (runge_kutta.hpp): `f(state, tau)` with tau in [0, 1] across the interval, returning dx/dt.

#include <array>
#include <cstddef>

#include <boost/numeric/odeint.hpp>

namespace hyst {

//! Integrates x' = f(x, tau) over a length `span` (> 0) with absolute and relative error
//! tolerance `tolerance` per step (> 0).
template <std::size_t N, class Rhs>
inline void dopri5_integrate(std::array<double, N>& x, double span, double tolerance,
                             const Rhs& f) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, N>;
  auto stepper = odeint::make_controlled(tolerance, tolerance, odeint::runge_kutta_dopri5<State>());
  const double inverse_span = 1.0 / span;
  auto system = [&](const State& s, State& dxdt, double t) { dxdt = f(s, t * inverse_span); };
  odeint::integrate_adaptive(stepper, system, x, 0.0, span, 0.25 * span);
}

}  // namespace hyst
