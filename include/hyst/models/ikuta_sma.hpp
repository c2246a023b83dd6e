#pragma once
//! \file
//! Ikuta-type model of shape memory alloy (SMA) hysteresis: a martensite fraction that follows
//! cosine-shaped transformation branches, a model with LOCAL memory (it cannot produce internal
//! loops: no return-point memory, minor loops do not close).
//!
//!     heating (v rising),  A_s <= v <= A_f:  xi = xi_M h(v)
//!     cooling (v falling), M_f <= v <= M_s:  xi = 1 - (1 - xi_A) g(v)
//!     h(v) = (cos(pi (v - A_s)/(A_f - A_s)) + 1)/2
//!     g(v) = (1 - cos(pi (v - M_f)/(M_s - M_f)))/2
//!     outside these windows xi is held;  y = y_A + (y_M - y_A) xi
//!
//! (g is the reference's ((1 - xi_A)/2) cos(...) + (1 + xi_A)/2 rewritten; h(A_s) = 1, h(A_f) = 0,
//! g(M_f) = 0, g(M_s) = 1.) Input v: temperature [degC] or a monotone proxy (heating current);
//! xi in [0, 1] (1 = martensite, cold); output y [output units, e.g. strain or length].
//!
//! Behaviour at reversals. xi_M and xi_A are fixed when a branch starts (at the reversal):
//! - A reversal outside the window of the new branch (the usual case: cooling stopped below A_s,
//!   heating stopped above M_s) starts the reference's branch with xi_M (xi_A) = the fraction at
//!   the reversal; the branch is continuous there by construction.
//! - A reversal INSIDE the window of the new branch (e.g. heating to v1 in [A_s, A_f], cooling a
//!   little to v_r > M_s, heating again) would make the reference's branch jump by xi_r (1 -
//!   h(v_r)). Here the whole branch is re-scaled so that it starts at the current point and still
//!   ends at full transformation: xi = xi_r h(v)/h(v_r) (heating), 1 - xi = (1 - xi_r) g(v)/g(v_r)
//!   (cooling). At v_r = A_f (M_f) there is nothing left to transform and xi is held.
//! Either way each branch runs to the END of the transformation (xi = 0 at A_f, 1 at M_f),
//! whatever the history; this is why the model has local memory only: after a reversal at v2 the
//! fraction at a previous reversal input v1 is not reached again (no return-point memory), a
//! periodic input between two inner reversals drifts over several cycles towards a limit cycle
//! instead of closing its first loop, and there is no wiping-out. Stress dependence (A_s +
//! sigma/C_A) is omitted.
//!
//! Initial state: at rest at input v0 = initial_input with xi = initial_fraction (default 1, cold
//! martensite); the first input that differs from v0 starts the first branch.
//! Sources: Ikuta, Tsukamoto & Hirose (1991), Proc. IEEE MEMS'91 (named by the seed paper; the
//! form used is the trigonometric phase-fraction law of Liang & Rogers (1990), J. Intell. Mater.
//! Syst. Struct. 1:207, an assumed reading of the seed's "based on sinus function").

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>

#include "hyst/core/assert.hpp"
#include "hyst/core/enum_names.hpp"

namespace hyst {

class IkutaSma {
 public:
  struct Params {
    double martensite_finish = 0.0;  //!< M_f [input units], < M_s
    double martensite_start = 1.0;   //!< M_s [input units]
    double austenite_start = 0.0;    //!< A_s [input units], < A_f, >= M_f
    double austenite_finish = 1.0;   //!< A_f [input units], >= M_s
    double output_austenite = 0.0;   //!< y_A: output at xi = 0 [output units]
    double output_martensite = 1.0;  //!< y_M: output at xi = 1 [output units]
    double initial_fraction = 1.0;   //!< xi at rest before the first sample, in [0, 1]
    double initial_input = 0.0;      //!< v0 [input units]: the input of the initial state
  };
  //! Direction of the current branch.
  enum class Branch : std::int8_t { rest = 0, heating = 1, cooling = -1 };
  struct State {
    double fraction = 1.0;  //!< xi [-]
    double input = 0.0;     //!< v[k-1] [input units]
    Branch branch = Branch::rest;
    //! xi_r / h(v_r) on a heating branch, (1 - xi_r) / g(v_r) on a cooling branch; < 0 = hold
    double scale = -1.0;
  };

  //! Throws hyst::Error naming the field that breaks a rule ("Ikuta martensite_start M_s = 1
  //! must be > martensite_finish M_f = 2").
  explicit IkutaSma(const Params& params);

  const Params& params() const { return params_; }

  //! At rest at initial_input with xi = initial_fraction.
  State initial_state() const;
  //! A given state at rest (the next input starts a new branch); throws hyst::Error unless the
  //! fraction is in [0, 1] and the input finite.
  State make_state(double fraction, double input) const;
  //! A given state on a branch with its scale (a stored state); throws hyst::Error as above and
  //! unless the scale is finite (< 0 = hold).
  State make_state(double fraction, double input, Branch branch, double scale) const;

  double output(const State& state) const {
    return params_.output_austenite +
           (params_.output_martensite - params_.output_austenite) * state.fraction;
  }
  //! The transformation laws h(v) (heating, 1 at A_s, 0 at A_f) and g(v) (cooling, 0 at M_f, 1
  //! at M_s), constant outside their windows.
  double heating_law(double input) const noexcept {
    const double x = std::clamp((input - params_.austenite_start) * heating_scale_, 0.0, 1.0);
    return 0.5 * (std::cos(std::numbers::pi * x) + 1.0);
  }
  double cooling_law(double input) const noexcept {
    const double x = std::clamp((input - params_.martensite_finish) * cooling_scale_, 0.0, 1.0);
    return 0.5 * (1.0 - std::cos(std::numbers::pi * x));
  }

  //! Advances one sample and returns y. No allocation, no virtual call.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    if (input > state.input) {
      if (state.branch != Branch::heating) {
        const double start = heating_law(state.input);
        state.branch = Branch::heating;
        state.scale = start > 0.0 ? state.fraction / start : -1.0;
      }
      // min/max only guard against rounding: within a branch the law is monotone.
      if (state.scale >= 0.0) {
        state.fraction = std::min(state.fraction, state.scale * heating_law(input));
      }
    } else if (input < state.input) {
      if (state.branch != Branch::cooling) {
        const double start = cooling_law(state.input);
        state.branch = Branch::cooling;
        state.scale = start > 0.0 ? (1.0 - state.fraction) / start : -1.0;
      }
      if (state.scale >= 0.0) {
        state.fraction = std::max(state.fraction, 1.0 - state.scale * cooling_law(input));
      }
    }
    state.input = input;
    return output(state);
  }

 private:
  Params params_;
  double heating_scale_;  // 1 / (A_f - A_s)
  double cooling_scale_;  // 1 / (M_s - M_f)
};

//! "rest", "heating", "cooling"; and back (hyst::Error for other text).
constexpr EnumNames<IkutaSma::Branch, 3> enumerator_names(IkutaSma::Branch) {
  return {{
      {IkutaSma::Branch::rest, "rest"},
      {IkutaSma::Branch::heating, "heating"},
      {IkutaSma::Branch::cooling, "cooling"},
  }};
}
IkutaSma::Branch ikuta_branch_from_string(std::string_view text);

}  // namespace hyst
