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
//! dz/dx = A - beta s |z|^(n-1) z - gamma |z|^n with s = sign(dx) over a sample, by classical RK4
//! with max(substeps, ceil(|dx| / max_input_step)) steps (20 RK4 sub-steps and 200 differ by
//! 7e-11 on the reference check). max_input_step = 0 means automatic: z0 / (4 n A), a quarter of
//! the input span over which z saturates, so that a large jump between two samples is still
//! integrated stably and the output stays monotone in the input (which the numerical inverse
//! relies on); ordinary sample spacings stay at `substeps` steps. State: previous input x and z;
//! initial state x = 0, z = 0.

#include <array>
#include <cmath>
#include <cstddef>

#include "hyst/core/runge_kutta.hpp"

namespace hyst {

namespace detail {

//! dz/dx = A - beta s |z|^(n-1) z - gamma |z|^n, advanced over dx with `steps` RK4 steps.
template <class T>
inline T bouc_wen_advance(const T& a, const T& beta, const T& gamma, const T& n, T z, double dx,
                          std::size_t steps) {
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
  rk4_integrate(x, T(dx), steps, rhs);
  return x[0];
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

  //! Advances one sample (input linear between the samples) and returns F. No allocation.
  double step(State& state, double input) const noexcept {
    const double dx = input - state.input;
    if (dx != 0.0) {
      state.hysteretic = detail::bouc_wen_advance(
          params_.a, params_.beta, params_.gamma, params_.n, state.hysteretic, dx,
          detail::substeps_for(dx, params_.substeps, max_input_step_));
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
