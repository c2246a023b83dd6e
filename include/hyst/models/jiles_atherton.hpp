#pragma once
//! \file
//! The Jiles-Atherton model of ferromagnetic hysteresis: field H [A/m] in, flux density
//! B = mu0 (H + M) [T] out (magnetisation M [A/m] and the tangent dB/dH available).
//! Sources: Jiles & Atherton (1986), J. Magn. Magn. Mater. 61:48-60; Jiles, Thoelke & Devine
//! (1992), IEEE Trans. Magn. 28:27-35; corrections reviewed by Zirka et al. (2012), J. Appl. Phys.
//! 112:043916; reference other_models.md section 5.
//!
//! Common to both variants: effective field H_e = H + alpha M, anhysteretic curve
//! M_an = M_s L(H_e / a) with the Langevin function L(x) = coth x - 1/x (series
//! x/3 - x^3/45 + 2 x^5/945 for |x| < 1e-3), direction delta = sign(dH), and the switch delta_M
//! (1 when delta (M_an - M_x) > 0, else 0) that stops the susceptibility from going negative right
//! after a reversal.
//!
//! Variant `original` (Jiles & Atherton 1986; the form of the reference): state M_irr,
//!     M = c M_an + (1 - c) M_irr
//!     dM_irr/dH = delta_M (M_an - M_irr) / (delta k - alpha (M_an - M_irr))
//! (M is solved from M = c M_an(H + alpha M) + (1 - c) M_irr by Newton's method).
//!
//! Variant `venkataraman` (R. Venkataraman, PhD thesis, University of Maryland 1999, eq. (30); the
//! form used by COMSOL and Altair Flux): state M,
//!     N     = c delta k dM_an/dH_e + delta_M (M_an - M)
//!     dM/dH = N / (delta k - alpha N)
//!
//! Corrections against blow-up at high drive (both variants): the denominator is kept on the
//! side of delta with magnitude >= 1e-3 k, and the differential susceptibility dM/dH is clipped
//! to >= 0. Parameters: M_s [A/m] > 0, a [A/m] > 0, k [A/m] > 0, c in [0, 1), alpha >= 0 with
//! alpha M_s / (3 a) < 1 (a single-valued anhysteretic curve).
//!
//! Integration: rate independent, integrated in H; any H(t), minor loops included. By default
//! classical RK4 under step-size control (controlled_runge_kutta.hpp): each sample starts with a
//! trial step of min(|dH|, k / 2), and a step is accepted when its error estimate is at most
//! default_step_error M_s = 1e-7 M_s (the estimate is conservative: loops stay within ~1e-7 M_s of
//! a k / 20000-step reference; where the solution is smooth a whole sample is one step). Until
//! 2026-11 the default was fixed RK4 sub-steps of k / 50 (the reference's advice), 2-3 times the
//! work on a saturating major loop and up to 20 times on loops of small k; `max_field_step` > 0
//! keeps such fixed sub-steps. With `tolerance` > 0: Boost.Odeint's Dormand-Prince 5(4) with that
//! absolute and relative error tolerance per step (in A/m for M; no allocation). The right-hand
//! side has kinks (the switch delta_M, the clipping), which the step control sees as regime
//! changes. The fitter differentiates the same integration in dual numbers.
//! Initial state: demagnetised (H = 0, M = 0, M_irr = 0) or state_at(H, M). Known limitation of
//! the model: minor loops do not close exactly.

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string_view>
#include <type_traits>

#include "hyst/core/adaptive_integration.hpp"
#include "hyst/core/assert.hpp"
#include "hyst/core/controlled_runge_kutta.hpp"
#include "hyst/core/enum_names.hpp"
#include "hyst/core/runge_kutta.hpp"

namespace hyst {

inline constexpr double kMu0 = 4e-7 * std::numbers::pi;  //!< vacuum permeability [H/m]

enum class JilesAthertonVariant { original, venkataraman };

namespace detail {

//! L(x), L'(x) and, when `second` is not null, L''(x) for a double x, from one exponential:
//! coth|x| = (1 + E) / (1 - E) and 1 / sinh^2 x = 4 E / (1 - E)^2 with E = exp(-2 |x|) (written
//! with e = expm1(-2 |x|) = E - 1 for |x| < 0.35, where 1 - E would cancel). Series near
//! 0 (L for |x| < 1e-3, L' for |x| < 1e-2, L'' for |x| < 0.1, where the closed forms cancel), the
//! limits beyond |x| = 40 (coth x = +-1 to 1e-34; sinh would overflow beyond 710).
inline void langevin_values(double x, double& value, double& derivative, double* second = nullptr) {
  const double ax = std::abs(x);
  const double x2 = x * x;
  if (ax > 40.0) {
    const double inv = 1.0 / x;
    value = (x > 0.0 ? 1.0 : -1.0) - inv;
    derivative = inv * inv;
    if (second) *second = -2.0 * inv * inv * inv;
    return;
  }
  double coth = 0.0;
  double csch2 = 0.0;
  if (ax >= 0.35) {  // exp(-2 |x|) <= 0.5: 1 - exp(-2 |x|) does not cancel
    const double e = std::exp(-2.0 * ax);
    const double inv = 1.0 / (1.0 - e);
    coth = std::copysign((1.0 + e) * inv, x);
    csch2 = 4.0 * e * inv * inv;
  } else if (ax >= 1e-3) {
    const double e = std::expm1(-2.0 * ax);
    coth = std::copysign((2.0 + e) / (-e), x);
    csch2 = 4.0 * (1.0 + e) / (e * e);
  }
  if (ax < 1e-3) {
    value = x * (1.0 / 3.0 - x2 * (1.0 / 45.0 - x2 * (2.0 / 945.0)));
  } else {
    value = coth - 1.0 / x;
  }
  if (ax < 1e-2) {
    derivative = 1.0 / 3.0 - x2 * (1.0 / 15.0 - x2 * (2.0 / 189.0));
  } else {
    derivative = 1.0 / x2 - csch2;
  }
  if (!second) return;
  if (ax < 0.1) {
    *second =
        x * (-2.0 / 15.0 + x2 * (8.0 / 189.0 - x2 * (42.0 / 4725.0 - x2 * (144.0 / 93555.0))));
  } else {
    *second = -2.0 / (x2 * x) + 2.0 * coth * csch2;
  }
}

template <class T>
inline constexpr bool is_plain_scalar = std::is_floating_point_v<T>;

//! L(x) and L'(x) for double or for a ceres::Jet-like type (members a, v): for a Jet the values are
//! those of the double and the derivative parts follow from L' and L'' (one exponential in all).
template <class T>
inline void langevin_pair(const T& x, T& value, T& derivative) {
  if constexpr (is_plain_scalar<T>) {
    langevin_values(x, value, derivative);
  } else {
    double l = 0.0;
    double dl = 0.0;
    double d2l = 0.0;
    langevin_values(x.a, l, dl, &d2l);
    value.a = l;
    value.v = dl * x.v;
    derivative.a = dl;
    derivative.v = d2l * x.v;
  }
}

//! Langevin function L(x) = coth x - 1/x (langevin_values()).
template <class T>
inline T langevin(const T& x) {
  T value(0.0);
  T derivative(0.0);
  langevin_pair(x, value, derivative);
  return value;
}

//! L'(x) = 1/x^2 - 1/sinh^2 x (langevin_values()).
template <class T>
inline T langevin_derivative(const T& x) {
  T value(0.0);
  T derivative(0.0);
  langevin_pair(x, value, derivative);
  return derivative;
}

template <class T>
struct JilesAthertonCoefficients {
  T ms, a, k, c, alpha;
};

//! Denominator delta k - alpha X kept on the side of delta, |.| >= 1e-3 k; `clamped` (when not
//! null) tells whether the bound acted.
template <class T>
inline T ja_denominator(const T& k, const T& alpha, const T& x, double delta,
                        bool* clamped = nullptr) {
  T d = delta * k - alpha * x;
  const bool low = delta * d < 1e-3 * k;
  if (low) d = delta * 1e-3 * k;
  if (clamped) *clamped = low;
  return d;
}

//! Total M for the original variant: the root of M - c M_an(H + alpha M) - (1 - c) M_irr, by
//! Newton's method from `m` (the slope 1 - c alpha dM_an/dH_e >= 1 - alpha M_s / (3 a) > 0).
template <class T>
inline T ja_total_magnetisation(const JilesAthertonCoefficients<T>& p, const T& inv_a, double h,
                                const T& m_irr, T m) {
  const T c_ms = p.c * p.ms;
  const T slope_scale = c_ms * p.alpha * inv_a;
  const T m_rest = (1.0 - p.c) * m_irr;
  for (int i = 0; i < 4; ++i) {
    const T xe = (h + p.alpha * m) * inv_a;
    T l(0.0);
    T dl(0.0);
    langevin_pair(xe, l, dl);
    const T update = (m - c_ms * l - m_rest) / (1.0 - slope_scale * dl);
    m -= update;
  }
  return m;
}

template <class T>
inline T ja_total_magnetisation(const JilesAthertonCoefficients<T>& p, double h, const T& m_irr,
                                T m) {
  return ja_total_magnetisation(p, T(1.0 / p.a), h, m_irr, m);
}

//! How one sample is integrated: Dormand-Prince with `tolerance` when that is > 0 (double only);
//! otherwise fixed RK4 sub-steps of at most `max_step` when that is > 0; otherwise RK4 under error
//! control (controlled_runge_kutta.hpp), error estimate <= `step_error` per step, first trial step
//! <= `first_step`.
struct JaIntegration {
  double max_step = 0.0;    // [A/m]
  double tolerance = 0.0;   // [A/m]
  double step_error = 0.0;  // [A/m]
  double first_step = 0.0;  // [A/m]
};

inline std::size_t field_substeps(double dh, double max_step) {
  const double needed = std::ceil(std::abs(dh) / max_step);
  if (needed < 1.0) return 1;
  return needed > 1e5 ? std::size_t{100000} : static_cast<std::size_t>(needed);
}

//! One sample's integration of x' = f(x, tau, regime) over dh, as `integration` says.
template <class T, class Rhs>
inline void ja_integrate(std::array<T, 1>& x, double dh, const JaIntegration& integration,
                         const Rhs& f) {
  const bool dopri = std::is_same_v<T, double> && integration.tolerance > 0.0;
  if (dopri || integration.max_step > 0.0) {
    int regime = 0;
    auto plain = [&](const std::array<T, 1>& s, double tau) { return f(s, tau, regime); };
    const std::size_t steps = dopri ? 1 : field_substeps(dh, integration.max_step);
    integrate_sample(x, T(dh), steps, dopri ? integration.tolerance : 0.0, plain);
  } else {
    rk4_controlled_integrate(x, dh, integration.step_error, integration.first_step, f);
  }
}

//! Advances (M, M_irr) from field h0 by dh as `integration` says. The right-hand sides report
//! their regime (delta_M on, denominator bounded, slope clipped) for the step control.
template <class T>
inline void ja_advance(const JilesAthertonCoefficients<T>& p, JilesAthertonVariant variant,
                       double h0, double dh, const JaIntegration& integration, T& m, T& m_irr) {
  const double delta = dh > 0.0 ? 1.0 : -1.0;
  const T inv_a = 1.0 / p.a;
  if (variant == JilesAthertonVariant::original) {
    const T m_guess = m;
    auto rhs = [&](const std::array<T, 1>& s, double tau, int& regime) {
      const double h = h0 + tau * dh;
      const T mt = ja_total_magnetisation(p, inv_a, h, s[0], m_guess);
      const T diff = p.ms * langevin((h + p.alpha * mt) * inv_a) - s[0];
      regime = 0;
      if (!(delta * diff > 0.0)) return std::array<T, 1>{T(0.0)};
      bool clamped = false;
      const T slope = diff / ja_denominator(p.k, p.alpha, diff, delta, &clamped);
      regime = clamped ? 2 : 1;
      return std::array<T, 1>{slope};
    };
    std::array<T, 1> x{m_irr};
    ja_integrate(x, dh, integration, rhs);
    m_irr = x[0];
    m = ja_total_magnetisation(p, inv_a, h0 + dh, m_irr, m_guess);
  } else {
    const T c_delta_k_chi = p.c * delta * p.k * p.ms * inv_a;  // c delta k dM_an/dH_e / L'
    auto rhs = [&](const std::array<T, 1>& s, double tau, int& regime) {
      const double h = h0 + tau * dh;
      const T xe = (h + p.alpha * s[0]) * inv_a;
      T l(0.0);
      T dl(0.0);
      langevin_pair(xe, l, dl);
      const T diff = p.ms * l - s[0];
      T n = c_delta_k_chi * dl;
      regime = 0;
      if (delta * diff > 0.0) {
        n += diff;
        regime = 1;
      }
      bool clamped = false;
      T slope = n / ja_denominator(p.k, p.alpha, n, delta, &clamped);
      if (clamped) regime += 2;
      if (slope < 0.0) {
        slope = T(0.0);
        regime += 4;
      }
      return std::array<T, 1>{slope};
    };
    std::array<T, 1> x{m};
    ja_integrate(x, dh, integration, rhs);
    m = x[0];
    m_irr = m;
  }
}

}  // namespace detail

class JilesAtherton {
 public:
  struct Params {
    double ms = 1.6e6;      //!< saturation magnetisation M_s [A/m] > 0
    double a = 1100.0;      //!< anhysteretic shape parameter [A/m] > 0
    double k = 400.0;       //!< pinning [A/m] > 0
    double c = 0.2;         //!< reversibility [-] in [0, 1)
    double alpha = 1.6e-3;  //!< inter-domain coupling [-] >= 0, alpha M_s / (3 a) < 1
    JilesAthertonVariant variant = JilesAthertonVariant::original;
    //! > 0: fixed RK4 steps in H of at most this [A/m]; 0 = RK4 under error control (file
    //! comment)
    double max_field_step = 0.0;
    double tolerance = 0.0;  //!< 0 or [1e-14, 1] [A/m]: adaptive Dormand-Prince
  };
  //! Default integration: the error estimate of an RK4 step at most this times M_s.
  static constexpr double default_step_error = 1e-7;
  //! The integration of one sample for these parameters (file comment).
  static detail::JaIntegration integration_of(const Params& params) {
    return {params.max_field_step, params.tolerance, default_step_error * params.ms,
            0.5 * params.k};
  }
  struct State {
    double field = 0.0;          //!< H of the previous sample [A/m]
    double magnetisation = 0.0;  //!< M [A/m]
    double irreversible = 0.0;   //!< M_irr [A/m] (= M for the Venkataraman variant)
    double direction = 1.0;      //!< sign of the last field change (+1 or -1)
  };

  //! Throws hyst::Error naming the parameter and the rule (file comment).
  explicit JilesAtherton(Params params);

  const Params& params() const { return params_; }
  const detail::JaIntegration& integration() const { return integration_; }
  //! Demagnetised: H = 0, M = M_irr = 0.
  State initial_state() const { return {}; }
  //! At field H with magnetisation M, M_irr from M = c M_an + (1 - c) M_irr; throws hyst::Error
  //! unless both are finite and |M| < M_s.
  State state_at(double field, double magnetisation) const;
  //! A whole state as a running model holds it (M_irr drifts from that relation by the rounding
  //! of the integration, so a copy that must continue exactly keeps it); throws hyst::Error unless
  //! M_irr is finite and the direction is +1 or -1, and as above.
  State state_at(double field, double magnetisation, double irreversible, double direction) const;

  //! M_an(H_e) = M_s L(H_e / a) [A/m].
  double anhysteretic(double effective_field) const {
    return params_.ms * detail::langevin(effective_field / params_.a);
  }
  double flux_density(const State& state) const {
    return kMu0 * (state.field + state.magnetisation);
  }
  //! dM/dH [-] at the state, for a field change in direction `direction` (+1 / -1).
  double susceptibility(const State& state, double direction) const;
  //! Tangent dB/dH = mu0 (1 + dM/dH) [H/m] for finite-element and circuit solvers.
  double tangent(const State& state, double direction) const {
    return kMu0 * (1.0 + susceptibility(state, direction));
  }
  double tangent(const State& state) const { return tangent(state, state.direction); }

  //! Advances to field H [A/m] (linear between samples) and returns B [T]. No allocation.
  double step(State& state, double field) const noexcept {
    HYST_ASSERT(std::isfinite(field), "step() needs a finite field");
    const double dh = field - state.field;
    if (dh != 0.0) {
      detail::ja_advance(coefficients_, params_.variant, state.field, dh, integration_,
                         state.magnetisation, state.irreversible);
      state.field = field;
      state.direction = dh > 0.0 ? 1.0 : -1.0;
    }
    return flux_density(state);
  }

 private:
  Params params_;
  detail::JilesAthertonCoefficients<double> coefficients_;
  detail::JaIntegration integration_;
};

//! "original" or "venkataraman".
constexpr EnumNames<JilesAthertonVariant, 2> enumerator_names(JilesAthertonVariant) {
  return {{
      {JilesAthertonVariant::original, "original"},
      {JilesAthertonVariant::venkataraman, "venkataraman"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text.
JilesAthertonVariant jiles_atherton_variant_from_string(std::string_view text);

}  // namespace hyst
