#pragma once
//! \file
//! The Duhem hysteresis model in the Coleman-Hodgdon form (Coleman & Hodgdon 1986, Int. J. Eng.
//! Sci. 24:897-919; Oh & Bernstein 2005, IEEE TAC 50:631):
//!
//!     y' = alpha |v'| (f(v) - y) + g(v) v'          alpha > 0
//!
//! with the material functions (f odd and increasing, g even, lim g = lim f')
//!
//!     f(v) = f_slope v + f_sat tanh(v / v_sat)
//!     g(v) = f_slope + g_peak sech^2(v / v_sat)
//!
//! Rules checked by the constructor: alpha > 0, f_slope >= 0, f_sat >= 0, v_sat > 0 and
//! f' >= g everywhere, i.e. g_peak <= f_sat / v_sat. The remaining Coleman-Hodgdon condition
//! g(v) > alpha e^(alpha v) int_v^inf |f' - g| e^(-alpha zeta) d zeta (properly oriented, monotone
//! loops) is evaluated numerically by coleman_hodgdon_margin() (> 0 when it holds).
//! With f_sat = 0 the model is the backlash-like model (backlash_like.hpp, exact steps).
//!
//! Integration: rate independent, integrated in the input, dy/dv = alpha s (f(v) - y) + g(v),
//! s = sign(dv): with `tolerance` > 0 adaptively by Boost.Odeint's Dormand-Prince 5(4) with that
//! absolute and relative error tolerance per step (accurate whatever the sample spacing; no
//! allocation), otherwise by classical RK4 with max(substeps, ceil(|dv| / max_input_step)) steps
//! (the path the fitter differentiates with ceres::Jet). y relaxes towards f(v) at the rate
//! alpha per unit of input, so RK4 is stable only for steps alpha |dv| below about 2.8: without
//! an explicit max_input_step the step is at most 1 / alpha (a large input step, e.g. a voltage
//! step of one sample, is divided accordingly instead of blowing up).
//! State: the previous input v and y; initial state v = 0, y = 0 (= f(0)).

#include <array>
#include <cmath>
#include <cstddef>

#include "hyst/core/adaptive_integration.hpp"
#include "hyst/core/assert.hpp"
#include "hyst/core/runge_kutta.hpp"
#include "hyst/models/bouc_wen.hpp"  // detail::substeps_for

namespace hyst {

namespace detail {

template <class T>
inline T duhem_advance(const T& alpha, const T& f_slope, const T& f_sat, const T& v_sat,
                       const T& g_peak, double v0, T y, double dv, std::size_t steps,
                       double tolerance = 0.0) {
  using std::cosh;
  using std::tanh;
  const double s = dv > 0.0 ? 1.0 : -1.0;
  auto rhs = [&](const std::array<T, 1>& state, double tau) {
    const double v = v0 + tau * dv;
    const T x = v / v_sat;
    const T sech = 1.0 / cosh(x);
    const T f = f_slope * v + f_sat * tanh(x);
    const T g = f_slope + g_peak * sech * sech;
    return std::array<T, 1>{s * alpha * (f - state[0]) + g};
  };
  std::array<T, 1> x{y};
  integrate_sample(x, T(dv), steps, tolerance, rhs);
  return x[0];
}

}  // namespace detail

class Duhem {
 public:
  struct Params {
    double alpha = 1.0;           //!< [1/input units] > 0
    double f_slope = 0.5;         //!< [output/input units] >= 0
    double f_sat = 1.0;           //!< [output units] >= 0
    double v_sat = 1.0;           //!< [input units] > 0
    double g_peak = 0.5;          //!< [output/input units] <= f_sat / v_sat
    std::size_t substeps = 20;    //!< minimum RK4 steps per sample, 1..100000
    double max_input_step = 0.0;  //!< largest RK4 step in v; 0 = automatic, 1 / alpha
    double tolerance = 0.0;       //!< 0 or [1e-14, 1]: adaptive Dormand-Prince
  };
  struct State {
    double input = 0.0;   //!< v of the previous sample
    double output = 0.0;  //!< y
  };

  //! Throws hyst::Error naming the parameter and the rule (file comment).
  explicit Duhem(Params params);

  const Params& params() const { return params_; }
  State initial_state() const { return {}; }
  //! A given state; throws hyst::Error unless both values are finite.
  State make_state(double input, double output) const;

  double f(double v) const {
    return params_.f_slope * v + params_.f_sat * std::tanh(v / params_.v_sat);
  }
  double g(double v) const {
    const double sech = 1.0 / std::cosh(v / params_.v_sat);
    return params_.f_slope + params_.g_peak * sech * sech;
  }
  //! min over v in [0, 20 v_sat] of g(v) - alpha e^(alpha v) int_v^inf |f' - g| e^(-alpha zeta):
  //! > 0 when the Coleman-Hodgdon condition holds there.
  double coleman_hodgdon_margin() const;
  //! The largest RK4 step in v: params().max_input_step, or 1 / alpha when that is 0.
  double max_input_step() const {
    return params_.max_input_step > 0.0 ? params_.max_input_step : 1.0 / params_.alpha;
  }

  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    const double dv = input - state.input;
    if (dv != 0.0) {
      state.output = detail::duhem_advance(
          params_.alpha, params_.f_slope, params_.f_sat, params_.v_sat, params_.g_peak, state.input,
          state.output, dv, detail::substeps_for(dv, params_.substeps, max_input_step()),
          params_.tolerance);
      state.input = input;
    }
    return state.output;
  }

 private:
  Params params_;
};

}  // namespace hyst
