#pragma once
//! \file
//! Classical fourth-order Runge-Kutta steps on a fixed-size state (std::array), the integrator of
//! the differential hysteresis models between two samples.
//!
//! The state type is a std::array, so a step allocates nothing; the scalar type is a template
//! parameter, so the same code runs with double and with ceres::Jet (automatic derivatives of a
//! simulation with respect to the model parameters). The right-hand side is called as
//! `f(state, tau)`, tau in [0, 1] the position inside the step (0 = start, 1 = end), so that an
//! input that varies within the step (e.g. linearly between two samples) can be evaluated at the
//! Runge-Kutta stages.
//!
//! Rate-independent models integrate in the input instead of in time (dz/dv instead of dz/dt):
//! then the step length `h` is the input increment of the sub-step and the scheme is exactly the
//! same. The global error of RK4 falls as h^4; the models pick their sub-step count from a
//! user-settable bound (see each model's `substeps` / `max_field_step`).

#include <array>
#include <cstddef>

namespace hyst {

//! One RK4 step of length h for x' = f(x, tau), tau running from tau0 to tau0 + dtau over the step.
template <class T, std::size_t N, class Rhs>
inline void rk4_step(std::array<T, N>& x, const T& h, double tau0, double dtau, const Rhs& f) {
  const std::array<T, N> k1 = f(x, tau0);
  std::array<T, N> xs;
  for (std::size_t i = 0; i < N; ++i)
    xs[i] = x[i] + (0.5 * h) * k1[i];
  const std::array<T, N> k2 = f(xs, tau0 + 0.5 * dtau);
  for (std::size_t i = 0; i < N; ++i)
    xs[i] = x[i] + (0.5 * h) * k2[i];
  const std::array<T, N> k3 = f(xs, tau0 + 0.5 * dtau);
  for (std::size_t i = 0; i < N; ++i)
    xs[i] = x[i] + h * k3[i];
  const std::array<T, N> k4 = f(xs, tau0 + dtau);
  for (std::size_t i = 0; i < N; ++i)
    x[i] += (h / 6.0) * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

//! Integrates x' = f(x, tau) over a total length `span` with `substeps` equal RK4 steps
//! (substeps >= 1); tau runs from 0 to 1 across the whole span.
template <class T, std::size_t N, class Rhs>
inline void rk4_integrate(std::array<T, N>& x, const T& span, std::size_t substeps, const Rhs& f) {
  const T h = span / static_cast<double>(substeps);
  const double dtau = 1.0 / static_cast<double>(substeps);
  for (std::size_t i = 0; i < substeps; ++i)
    rk4_step(x, h, static_cast<double>(i) * dtau, dtau, f);
}

}  // namespace hyst
