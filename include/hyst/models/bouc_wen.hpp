#pragma once
//! \file
//! The Bouc-Wen hysteresis model (Bouc 1967; Wen 1976, J. Eng. Mech. Div. ASCE 102:249-263;
//! survey: Ismail, Ikhouane & Rodellar 2009), displacement x in, restoring force F out:
//!
//!     F = alpha_k k x + (1 - alpha_k) k z
//!     z' = A x' - beta |x'| |z|^(n-1) z - gamma x' |z|^n
//!
//! Standard parameters: A > 0, beta, gamma, n >= 1, stiffness k > 0, alpha_k in [0, 1].
//! Normalised form (Ikhouane & Rodellar 2007, "Systems with Hysteresis"): z = z0 w with
//! z0 = (A / (beta + gamma))^(1/n), rho = A / z0, sigma = beta / (beta + gamma):
//!
//!     F = kx x + kw w,   w' = rho (x' - sigma |x'| |w|^(n-1) w + (sigma - 1) x' |w|^n)
//!
//! with kx = alpha_k k and kw = (1 - alpha_k) k z0. Constraints, checked by the constructor (the
//! bounded, physically consistent class): A > 0, beta + gamma > 0, beta - gamma >= 0
//! (sigma >= 1/2), n >= 1; then a state with |z| <= z0 stays in [-z0, z0]. Identifiability: the
//! standard set is redundant (z can be rescaled); the normalised set (rho, sigma, n, kx, kw) is
//! identifiable, and the fitter works in it. from_normalised() returns the standard set with A = 1.
//!
//! Integration: the model is rate independent, so it is integrated in the input,
//! dz/dx = A - beta s |z|^(n-1) z - gamma |z|^n with s = sign(dx) over a sample.
//! - n = 1: exactly, whatever the sample spacing. While z keeps its sign the equation is linear,
//!   dz/du = s A - c z in u = |x - x_start| with c = beta + s gamma (z >= 0) or beta - s gamma
//!   (z < 0), c >= 0 in the bounded class; z relaxes exponentially to s A / c (linearly when
//!   c = 0). Where z crosses 0 inside the sample the crossing point is computed and the solution
//!   continues with the other coefficient (bouc_wen_exact_advance). `substeps`, `max_input_step`
//!   and `tolerance` do not apply.
//! - n != 1, `tolerance` > 0: adaptively by Boost.Odeint's Dormand-Prince 5(4) with that absolute
//!   and relative error tolerance per step (no allocation: std::array state).
//! - n != 1, `tolerance` = 0: classical RK4 with max(substeps, ceil(|dx| / max_input_step)) steps.
//!   max_input_step = 0 means automatic: z0 / (4 n A), a quarter of the input span over which z
//!   saturates, so that a large jump between two samples is still integrated stably and the output
//!   stays monotone in the input (which the numerical inverse relies on); ordinary sample spacings
//!   stay at `substeps` steps.
//! The fitter (fit_bouc_wen.hpp) integrates with the templated RK4 path (bouc_wen_advance), which
//! differentiates through ceres::Jet, also for the exponent n. State: previous input x and z;
//! initial state x = 0, z = 0.

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "hyst/core/adaptive_integration.hpp"
#include "hyst/core/assert.hpp"
#include "hyst/core/runge_kutta.hpp"

namespace hyst {

namespace detail {

//! dz/dx = A - beta s |z|^(n-1) z - gamma |z|^n, advanced over dx with `steps` RK4 steps, or
//! adaptively with error tolerance `tolerance` when that is > 0 (double only).
template <class T>
inline T bouc_wen_advance(const T& a, const T& beta, const T& gamma, const T& n, T z, double dx,
                          std::size_t steps, double tolerance = 0.0) {
  using std::abs;
  using std::pow;
  const double s = dx > 0.0 ? 1.0 : -1.0;
  const bool n_is_one = n == 1.0;
  auto rhs = [&](const std::array<T, 1>& state, double) {
    const T abs_z = abs(state[0]);
    if (n_is_one) return std::array<T, 1>{a - s * beta * state[0] - gamma * abs_z};
    if (abs_z == 0.0) return std::array<T, 1>{a};
    const T power = pow(abs_z, n);
    return std::array<T, 1>{a - s * beta * (state[0] < 0.0 ? -power : power) - gamma * power};
  };
  std::array<T, 1> x{z};
  if constexpr (std::is_same_v<T, double>) {
    if (!(tolerance > 0.0)) {
      // RK4 as rk4_integrate, but a sub-step that leaves z unchanged ends the loop: the equation
      // is autonomous and h fixed, so every further sub-step would leave it unchanged too (same
      // result, bit for bit; a large jump after saturation costs a few hundred sub-steps).
      const double h = dx / static_cast<double>(steps);
      for (std::size_t i = 0; i < steps; ++i) {
        const double before = x[0];
        rk4_step(x, h, 0.0, 0.0, rhs);
        if (x[0] == before) break;
      }
      return x[0];
    }
  }
  integrate_sample(x, T(dx), steps, tolerance, rhs);
  return x[0];
}

//! The exact solution of dz/dx = A - beta s z - gamma |z| (n = 1) over dx (file comment).
inline double bouc_wen_exact_advance(double a, double beta, double gamma, double z, double dx) {
  const double s = dx > 0.0 ? 1.0 : -1.0;
  double remaining = std::abs(dx);  // u still to go
  // At most two pieces: z only crosses 0 towards sign s, and then keeps that sign.
  for (int piece = 0; piece < 2 && remaining > 0.0; ++piece) {
    const double z_sign = z > 0.0 ? 1.0 : (z < 0.0 ? -1.0 : s);  // at 0, z moves towards s
    const double c = beta + s * z_sign * gamma;                  // dz/du = s A - c z
    const double slope_at_zero = s * a;
    const bool crosses = z * s < 0.0;  // z moves towards 0 and beyond
    double crossing = remaining;       // u where z reaches 0
    if (crosses) {
      crossing = c > 0.0 ? std::log1p(-z * c / slope_at_zero) / c : -z / slope_at_zero;
    }
    if (!crosses || crossing >= remaining) {
      if (c > 0.0) {
        const double equilibrium = slope_at_zero / c;
        return z - (equilibrium - z) * std::expm1(-c * remaining);
      }
      return z + slope_at_zero * remaining;
    }
    z = 0.0;
    remaining -= crossing;
  }
  return z;
}

inline std::size_t substeps_for(double dx, std::size_t substeps, double max_step) {
  if (!(max_step > 0.0)) return substeps;
  const double needed = std::ceil(std::abs(dx) / max_step);
  return needed > static_cast<double>(substeps)
             ? (needed > 1e6 ? std::size_t{1000000} : static_cast<std::size_t>(needed))
             : substeps;
}

}  // namespace detail

class BoucWen {
 public:
  struct Params {
    double a = 1.0;               //!< A [-] > 0
    double beta = 0.5;            //!< [1/(input units z^(n-1))], beta - gamma >= 0
    double gamma = 0.5;           //!< beta + gamma > 0
    double n = 1.0;               //!< exponent >= 1
    double stiffness = 1.0;       //!< k [output/input units] > 0
    double alpha_k = 0.5;         //!< share of the linear spring, [0, 1]
    std::size_t substeps = 20;    //!< minimum RK4 steps per sample, 1..100000
    double max_input_step = 0.0;  //!< largest RK4 step in x [input units]; 0 = automatic
    double tolerance = 0.0;       //!< n != 1: 0 or [1e-14, 1], adaptive Dormand-Prince
  };
  //! The identifiable normalised parameters (file comment).
  struct Normalised {
    double rho = 1.0;    //!< [1/input units] > 0
    double sigma = 0.5;  //!< [-] >= 1/2
    double n = 1.0;      //!< [-] >= 1
    double kx = 0.5;     //!< linear gain [output/input units]
    double kw = 0.5;     //!< hysteretic gain [output units] >= 0
  };
  struct State {
    double input = 0.0;       //!< x of the previous sample
    double hysteretic = 0.0;  //!< z
  };

  //! Throws hyst::Error naming the parameter and the rule (see the file comment).
  explicit BoucWen(Params params);

  //! Standard parameters with A = 1 and the given substep settings; throws hyst::Error unless
  //! rho > 0, sigma >= 1/2, n >= 1, kw >= 0, kx + kw rho > 0.
  static Params from_normalised(const Normalised& normalised, std::size_t substeps = 20,
                                double max_input_step = 0.0);

  const Params& params() const { return params_; }
  Normalised normalised() const;
  //! z0 = (A / (beta + gamma))^(1/n), the bound of |z|.
  double z_bound() const { return z_bound_; }

  State initial_state() const { return {}; }
  //! A given state; throws hyst::Error unless both are finite and |z| <= z0.
  State make_state(double input, double hysteretic) const;

  double output(const State& state) const {
    return params_.alpha_k * params_.stiffness * state.input +
           (1.0 - params_.alpha_k) * params_.stiffness * state.hysteretic;
  }

  //! The largest input change one step() integrates faithfully: unlimited for n = 1 (exact) and
  //! the adaptive scheme; 10^6 max_input_step for RK4, whose sub-steps are capped at 10^6 and
  //! would grow past the stable length beyond it. The numerical inverse searches within it.
  double max_input_jump() const noexcept {
    return params_.n == 1.0 || params_.tolerance > 0.0 ? std::numeric_limits<double>::infinity()
                                                       : 1e6 * max_input_step_;
  }

  //! Advances one sample (input linear between the samples) and returns F. No allocation.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    const double dx = input - state.input;
    if (dx != 0.0) {
      state.hysteretic =
          params_.n == 1.0
              ? detail::bouc_wen_exact_advance(params_.a, params_.beta, params_.gamma,
                                               state.hysteretic, dx)
              : detail::bouc_wen_advance(
                    params_.a, params_.beta, params_.gamma, params_.n, state.hysteretic, dx,
                    detail::substeps_for(dx, params_.substeps, max_input_step_), params_.tolerance);
      state.input = input;
    }
    return output(state);
  }

 private:
  Params params_;
  double z_bound_;
  double max_input_step_;  //!< params_.max_input_step, or the automatic bound when that is 0
};

}  // namespace hyst
