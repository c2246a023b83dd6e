#pragma once
//! \file
//! Prandtl-Ishlinskii model with Kuhnen's creep operator: hysteresis plus creep, the drift a piezo
//! shows after a voltage step (logarithmic in time over many decades) and the loop widening at
//! slow rates that follows from it.
//!
//!     y[k]    = y_off + sum_j p_j w_j[k] + sum_i sum_j c_ij z_ij[k]
//!     w_j[k]  = max(v[k] - r_j, min(v[k] + r_j, w_j[k-1]))            (play operators)
//!     z_ij[k] = a_i z_ij[k-1] + (1 - a_i) w_j[k],   a_i = exp(-Ts / tau_i)
//!
//! Each creep element z_ij is a first-order lag tau_i dz/dt = w_j - z with unit static gain,
//! driven by the play w_j. The update is its exact solution when w_j is constant over each sample
//! interval at the value it has at the interval's end (the input of sample k acts from t_{k-1} on):
//! after a step of the input at sample 1, z_ij[k] = w (1 - exp(-k Ts / tau_i)) exactly. So the
//! creep term answers at once (a share (1 - a_i) of c_ij), which keeps the composition invertible
//! sample by sample: y[k] is a PI in v[k] with the effective weights p_j + sum_i c_ij (1 - a_i)
//! plus a term fixed by the past (inverse_prandtl_ishlinskii_creep.hpp).
//!
//! Leakage (optional, 0 by default): a lossy ceramic conducts a current besides its switching
//! one, and a charge integrator (a ferroelectric tester's polarisation) adds that current's charge:
//!
//!     y[k] += L[k],   L[k] = L[k-1] + Ts (g v[k] + i0),   L = 0 in the virgin state,
//!
//! a conduction g [output units / (input units s)] and an offset current i0 [output units / s]
//! (an integrator's input offset), both of either sign, integrated with the input of sample k
//! acting from t_{k-1} on, as the lags. L grows without bound during a hold: a drift, not a
//! hysteresis; the inverse treats it as memory plus the linear weight g Ts of the current input.
//!
//! With every c_ij = 0 it is the PrandtlIshlinskii of the same thresholds and weights. A step of
//! size V from rest settles at sum_j (p_j + sum_i c_ij) P_rj[V]: the creep weights say how much
//! each play's displacement grows after the step, the time constants when. Time constants spaced
//! m per decade with equal weights c give a logarithmic creep law, a growth of m c per decade of
//! time (pi_logarithmic_creep()).
//!
//! Parameters
//! - thresholds r_j [input units]: 0 = r_0 < r_1 < ... < r_{n-1};
//! - weights p_j [output/input units]: finite (as PrandtlIshlinskii);
//! - time_constants tau_i [s]: finite, > 0, strictly increasing; may be empty (no creep);
//! - creep_weights c_ij [output/input units]: finite and >= 0, row i (time constant) by column j
//!   (play), row-major, n_tau * n values;
//! - sample_time Ts [s] > 0; offset y_off [output units];
//! - leakage_conductance g, leakage_current i0: finite, 0 = no leakage.
//! State: the plays w_j and the creep elements z_ij [input units], 0 in the virgin state; the
//! leakage L [output units].
//! Sources: Kuhnen (2001), "Modellbildung und Kompensation von Kriech- und Hystereseeffekten";
//! Krejci & Kuhnen (2001), IEE Proc. Control Theory Appl. 148(3):185-192.

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "hyst/core/assert.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {

class PrandtlIshlinskiiCreep {
 public:
  struct Params {
    std::vector<double> thresholds{};      //!< r_j [input units], 0 = r_0 < r_1 < ...
    std::vector<double> weights{};         //!< p_j [output/input units], one per threshold
    std::vector<double> time_constants{};  //!< tau_i [s], > 0, increasing
    std::vector<double> creep_weights{};   //!< c_ij >= 0, row-major (tau_i by r_j)
    double sample_time = 1.0;              //!< Ts > 0 [s]
    double offset = 0.0;                   //!< y_off [output units]
    double leakage_conductance = 0.0;      //!< g [output units / (input units s)]
    double leakage_current = 0.0;          //!< i0 [output units / s]
  };
  struct State {
    std::vector<double> play;   //!< w_j [input units]
    std::vector<double> creep;  //!< z_ij [input units], row-major like creep_weights
    double leakage = 0.0;       //!< L [output units], the leakage's charge so far
  };

  //! Throws hyst::Error naming the first parameter that breaks a rule.
  explicit PrandtlIshlinskiiCreep(Params params);

  const Params& params() const { return params_; }
  //! Number of plays n.
  std::size_t size() const { return params_.thresholds.size(); }
  //! Number of time constants n_tau.
  std::size_t lags() const { return params_.time_constants.size(); }
  //! The hysteresis part alone: the PI of the same thresholds, weights and offset.
  const PrandtlIshlinskii& hysteresis() const { return hysteresis_; }
  //! a_i = exp(-Ts / tau_i), the lags' decay per sample.
  const std::vector<double>& decay() const { return decay_; }

  //! The same model discretised at another sample time: the lags are continuous-time elements,
  //! so one fitted model runs records sampled at any rate. Throws hyst::Error unless Ts > 0.
  PrandtlIshlinskiiCreep at_sample_time(double sample_time) const;

  //! Every play and creep element at 0.
  State initial_state() const;
  //! At rest at input v0 for ever: every play and creep element at v0.
  State state_at_rest(double input) const;
  //! The periodic steady state of `period` (one period of a periodic input, its last sample
  //! followed again by its first): the state from which one period returns to the same state.
  //! Exact, not a run-in: the plays reach it after one period (a composition of clamps is
  //! idempotent), and each lag then has the closed form z_ij = sum_k a_i^(N-k) (1 - a_i)
  //! w_j[k] / (1 - a_i^N) over the period's play outputs. Throws hyst::Error for an empty period
  //! or a sample that is not finite.
  State periodic_state(std::span<const double> period) const;
  //! A given state; throws hyst::Error for a wrong size, a value that is not finite, or plays no
  //! input history reaches (as PrandtlIshlinskii::make_state).
  State make_state(std::vector<double> play, std::vector<double> creep, double leakage = 0.0) const;

  //! The output in a given state, without advancing it.
  double output(const State& state) const;

  //! Whether the leakage term is present (g or i0 not 0).
  bool has_leakage() const noexcept {
    return params_.leakage_conductance != 0.0 || params_.leakage_current != 0.0;
  }

  //! p_j + sum_i c_ij (1 - a_i) (and + g Ts for p_0, the play of threshold 0, which is v): the
  //! weights of the plays at the current sample, through which the output depends on the
  //! current input.
  std::vector<double> instantaneous_weights() const;
  //! sum_ij c_ij a_i z_ij + L + Ts i0: the part of the next output fixed by the state before the
  //! sample.
  double creep_memory(const State& state) const noexcept {
    const std::size_t n = size();
    double memory = state.leakage + params_.sample_time * params_.leakage_current;
    for (std::size_t i = 0; i < lags(); ++i) {
      for (std::size_t j = 0; j < n; ++j)
        memory += params_.creep_weights[i * n + j] * decay_[i] * state.creep[i * n + j];
    }
    return memory;
  }

  //! Advances one sample. No allocation, no virtual call.
  //! Precondition: `state` comes from this model and `input` is finite.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    HYST_ASSERT(state.play.size() == size() && state.creep.size() == size() * lags(),
                "state of another model");
    const std::size_t n = size();
    const double* __restrict r = params_.thresholds.data();
    const double* __restrict p = params_.weights.data();
    double* __restrict w = state.play.data();
    double y = params_.offset;
    for (std::size_t j = 0; j < n; ++j) {
      w[j] = play_step(input, r[j], w[j]);
      y += p[j] * w[j];
    }
    const double* __restrict c = params_.creep_weights.data();
    double* __restrict z = state.creep.data();
    for (std::size_t i = 0; i < lags(); ++i) {
      const double a = decay_[i];
      for (std::size_t j = 0; j < n; ++j) {
        const std::size_t ij = i * n + j;
        z[ij] = a * z[ij] + (1.0 - a) * w[j];
        y += c[ij] * z[ij];
      }
    }
    state.leakage +=
        params_.sample_time * (params_.leakage_conductance * input + params_.leakage_current);
    return y + state.leakage;
  }

 private:
  Params params_;
  PrandtlIshlinskii hysteresis_;
  std::vector<double> decay_;
};

//! A logarithmic creep law on a PI: after a step from rest, each play's displacement grows by
//! the share `gamma` of its instantaneous value per decade of time,
//!
//!     y(t) ~ y(0+) (1 + gamma log10(t / t0))   for t0 <= t <= t0 10^decades,
//!
//! as piezo creep is commonly stated (gamma ~ 0.01-0.02). Built from `per_decade` lags per decade,
//! c_ij = gamma p_j / per_decade, time constants from tau_0 = t0 e^euler_gamma 10^(1 / (2
//! per_decade)) over `decades` decades (which places the law's zero at t0). With 2 or more lags per
//! decade it follows the law within 0.05 gamma of the step for 3 t0 <= t <= t0 10^(decades - 1);
//! after the last time constant the growth stops. Throws hyst::Error for gamma < 0, t0 <= 0,
//! decades or per_decade outside [1, 12], or parameters that break a rule (PI weights < 0 give
//! creep weights < 0).
PrandtlIshlinskiiCreep::Params pi_logarithmic_creep(const PrandtlIshlinskii::Params& pi,
                                                    double gamma, double t0, std::size_t decades,
                                                    std::size_t per_decade, double sample_time);

//! `count` time constants spaced evenly in log from `shortest` to `longest` (count = 1: shortest).
//! Throws hyst::Error unless 0 < shortest <= longest (both finite) and count >= 1, with
//! shortest < longest when count > 1.
std::vector<double> log_spaced_time_constants(double shortest, double longest, std::size_t count);

}  // namespace hyst
