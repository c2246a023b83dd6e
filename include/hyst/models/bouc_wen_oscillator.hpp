#pragma once
//! \file
//! The Bouc-Wen hysteretic oscillator of the nonlinear system identification benchmark
//! (Noel & Schoukens 2016, nonlinearbenchmark.org): force u [N] in, displacement y [m] out.
//!
//!     m y'' + c y' + k y + z = u
//!     z' = alpha y' - beta (gamma |y'| |z|^(nu-1) z + delta y' |z|^nu)
//!
//! Parameters: mass m [kg] > 0, damping c [N s/m] >= 0, stiffness k [N/m] >= 0, alpha [N/m] > 0,
//! beta >= 0 (beta gamma |z|^(nu-1) in 1/m), gamma and delta [-] any reals, nu >= 1; the sample
//! time Ts [s] > 0.
//! Published values (benchmark()): m = 2, c = 10, k = 5e4, alpha = 5e4, beta = 1e3, gamma = 0.8,
//! delta = -1.1, nu = 1, Ts = 1/750 s.
//!
//! The benchmark's set lies outside the bounded class of the static Bouc-Wen model (bouc_wen.hpp):
//! beta (gamma + delta) = -300 < 0, so z hardens instead of saturating; the mass and the springs
//! keep the oscillator stable for bounded forces. No boundedness rule is therefore imposed here.
//! Only beta gamma and beta delta enter the output (beta is a gauge); the fitter
//! (fit_bouc_wen_oscillator.hpp) identifies m, c, k, alpha, beta gamma, beta delta (and nu).
//!
//! Integration: the state (y, y', z) is advanced over each sample with `substeps` classical RK4
//! steps, or, when `tolerance` > 0, adaptively by Boost.Odeint's Dormand-Prince 5(4) with that
//! absolute and relative error tolerance per step (double only; the fitter uses RK4, which
//! automatic differentiation passes through); the input between two samples is the straight line
//! between them (`linear`, default) or held at the new value (`hold`). The benchmark's data were
//! made from a band-limited input, so to reproduce them drive the model with the input upsampled by
//! a band-limited interpolator (signals/band_limited.hpp) and a sample time Ts / factor; see
//! docs/results.md. State: y [m], y' [m/s], z [N] and the previous input [N]; initial state: at
//! rest, all zero.

#include <array>
#include <cmath>
#include <cstddef>
#include <string_view>

#include "hyst/core/adaptive_integration.hpp"
#include "hyst/core/assert.hpp"
#include "hyst/core/enum_names.hpp"
#include "hyst/core/runge_kutta.hpp"

namespace hyst {

namespace detail {

//! The coefficients that enter the equations, in any scalar type (double or ceres::Jet).
template <class T>
struct BoucWenOscillatorCoefficients {
  T mass, damping, stiffness, alpha, beta_gamma, beta_delta, nu;
};

//! Advances x = (y, y', z) over one sample of length dt, the input going from u0 to u1.
template <class T, class U>
inline void bouc_wen_oscillator_advance(const BoucWenOscillatorCoefficients<T>& p,
                                        std::array<T, 3>& x, const U& u0, const U& u1, double dt,
                                        std::size_t substeps, bool linear_input, bool nu_is_one,
                                        double tolerance = 0.0) {
  using std::abs;
  using std::pow;
  const T inverse_mass = 1.0 / p.mass;
  auto rhs = [&](const std::array<T, 3>& s, double tau) {
    const U u = linear_input ? U(u0 + (u1 - u0) * tau) : u1;
    const T& v = s[1];
    const T& z = s[2];
    const T abs_z = abs(z);
    T hysteretic;
    if (nu_is_one) {
      hysteretic = p.beta_gamma * abs(v) * z + p.beta_delta * v * abs_z;
    } else if (abs_z == 0.0) {
      hysteretic = T(0.0);
    } else {
      const T power = pow(abs_z, p.nu);  // |z|^nu; |z|^(nu-1) z = power * sign(z)
      hysteretic = p.beta_gamma * abs(v) * (z < 0.0 ? -power : power) + p.beta_delta * v * power;
    }
    return std::array<T, 3>{v, (u - p.damping * v - p.stiffness * s[0] - z) * inverse_mass,
                            p.alpha * v - hysteretic};
  };
  integrate_sample(x, T(dt), substeps, tolerance, rhs);
}

}  // namespace detail

class BoucWenOscillator {
 public:
  enum class InputBetweenSamples {
    linear,  //!< straight line between the previous and the new sample
    hold,    //!< the new sample over the whole step (zero-order hold)
  };
  struct Params {
    double mass = 2.0;                 //!< m [kg] > 0
    double damping = 10.0;             //!< c [N s/m] >= 0
    double stiffness = 5e4;            //!< k [N/m] >= 0
    double alpha = 5e4;                //!< [N/m] > 0
    double beta = 1e3;                 //!< >= 0 (beta gamma |z|^(nu-1) in 1/m)
    double gamma = 0.8;                //!< [-]
    double delta = -1.1;               //!< [-]
    double nu = 1.0;                   //!< [-] >= 1
    double sample_time = 1.0 / 750.0;  //!< Ts [s] > 0
    std::size_t substeps = 20;         //!< RK4 steps per sample, 1..100000
    double tolerance = 0.0;            //!< > 0: adaptive Dormand-Prince with this error tolerance
    InputBetweenSamples input_between_samples = InputBetweenSamples::linear;
  };
  struct State {
    double displacement = 0.0;      //!< y [m]
    double velocity = 0.0;          //!< y' [m/s]
    double hysteretic_force = 0.0;  //!< z [N]
    double previous_input = 0.0;    //!< u of the previous sample [N]
  };

  //! Validates; throws hyst::Error naming the field, e.g. "Bouc-Wen oscillator mass m = 0 must be
  //! > 0".
  explicit BoucWenOscillator(Params params);

  //! The published benchmark parameters (file comment).
  static Params benchmark();

  const Params& params() const { return params_; }
  //! At rest: y = y' = z = 0, previous input 0.
  State initial_state() const { return {}; }

  //! Advances one sample with input u [N] and returns y [m]. No allocation, no virtual call.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    std::array<double, 3> x{state.displacement, state.velocity, state.hysteretic_force};
    detail::bouc_wen_oscillator_advance(
        coefficients_, x, state.previous_input, input, params_.sample_time, params_.substeps,
        params_.input_between_samples == InputBetweenSamples::linear, nu_is_one_,
        params_.tolerance);
    state = {x[0], x[1], x[2], input};
    return x[0];
  }

 private:
  Params params_;
  detail::BoucWenOscillatorCoefficients<double> coefficients_;
  bool nu_is_one_;
};

//! "linear" or "hold".
constexpr EnumNames<BoucWenOscillator::InputBetweenSamples, 2> enumerator_names(
    BoucWenOscillator::InputBetweenSamples) {
  return {{
      {BoucWenOscillator::InputBetweenSamples::linear, "linear"},
      {BoucWenOscillator::InputBetweenSamples::hold, "hold"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text.
BoucWenOscillator::InputBetweenSamples input_between_samples_from_string(std::string_view text);

}  // namespace hyst
