#pragma once
//! \file
//! Butterfly strain with creep: the polarisation of a switching ceramic switches (a Preisach
//! loop), then creeps after each voltage step (Kuhnen's creep operator), and the strain follows
//! the polarisation through the static map, so that the displacement after a step relaxes as the
//! polarisation does. A leakage charge adds to the measured polarisation but strains nothing.
//!
//!     P_s[k]  = Preisach[v](k)                                       switching
//!     C[k]    = sum_i sum_j c_ij z_ij[k]                             creep
//!     z_ij[k] = a_i z_ij[k-1] + (1 - a_i) w_j[k],  w_j = play_rj[v],  a_i = exp(-Ts / tau_i)
//!     L[k]    = L[k-1] + Ts (g v[k] + i0)                            leakage charge
//!     P[k]    = P_s[k] + C[k]                                        polarisation (strains)
//!     P_m[k]  = P[k] + L[k]                                          as a charge integrator sees
//!     it y[k]    = y_off + d v[k] + sum_n q_n P[k]^n                    strain or displacement
//!
//! The creep part is the creep operator of prandtl_ishlinskii_creep.hpp with no static play
//! weights (the Preisach already carries the static loop): a step of size V from rest settles
//! with a polarisation sum_ij c_ij P_rj[V] above its switching one, approached by the lags; time
//! constants spaced m per decade with equal weights give a logarithmic creep law. The lags are
//! continuous-time elements discretised exactly (at_sample_time() for other records' sample
//! times). With every c_ij = 0 and no leakage it is the ButterflyStrain of the same parameters.
//!
//! Parameters: the butterfly strain model's (butterfly_strain.hpp: the Preisach P_s(v), d, q_n,
//! y_off), the creep thresholds r_j [input units] (0 = r_0 < r_1 < ...), the time constants
//! tau_i [s] (> 0, increasing; may be empty), the creep weights c_ij >= 0 [P units / input
//! units] (row-major, tau_i by r_j), the sample time Ts > 0 [s], the leakage conductance g
//! [P units / (input units s)] and current i0 [P units / s] (finite; 0 = none).
//! State: the Preisach memory, the plays and lags (0 in the virgin state) and the leakage charge.
//! Properties: P never moves against the input at the current sample (the Preisach and the
//! creep's instantaneous share c_ij (1 - a_i) are monotone in v), so the inverse exists on the
//! branches where dy/dP keeps its sign (inverse_butterfly_strain_creep.hpp).
//! Common mistakes: reading the leakage as creep (a leakage grows without bound during a hold and
//! is proportional to the voltage; a creep saturates or grows by decades); fitting the leakage
//! from a displacement alone (it strains nothing: it needs the measured polarisation).
//! Sources: butterfly_strain.hpp; Kuhnen (2001); Krejci & Kuhnen (2001) for the creep operator.

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/models/butterfly_strain.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"

namespace hyst {

class ButterflyStrainCreep {
 public:
  struct Params {
    ButterflyStrain::Params butterfly;          //!< P_s(v) and the strain map
    std::vector<double> creep_thresholds{0.0};  //!< r_j [input units], 0 = r_0 < r_1 < ...
    std::vector<double> time_constants{};       //!< tau_i [s], > 0, increasing
    std::vector<double> creep_weights{};        //!< c_ij >= 0, row-major (tau_i by r_j)
    double sample_time = 1.0;                   //!< Ts > 0 [s]
    double leakage_conductance = 0.0;           //!< g [P units / (input units s)]
    double leakage_current = 0.0;               //!< i0 [P units / s]
  };
  struct State {
    PreisachState switching;              //!< the Preisach memory
    PrandtlIshlinskiiCreep::State creep;  //!< plays, lags and the leakage charge L
  };

  //! Validates; throws hyst::Error naming the field (the butterfly model's, "creep_thresholds",
  //! "time_constants", "creep_weights[n]", "sample_time", "leakage_conductance", ...).
  explicit ButterflyStrainCreep(Params params);

  const Params& params() const { return params_; }
  //! The model without creep and leakage: switching and map.
  const ButterflyStrain& butterfly() const { return butterfly_; }
  //! The creep and leakage part as a PI with creep of zero static weights (output C + L).
  const PrandtlIshlinskiiCreep& creep() const { return creep_; }
  //! The same model discretised at another sample time. Throws hyst::Error unless Ts > 0.
  ButterflyStrainCreep at_sample_time(double sample_time) const;

  //! The Preisach initial state, plays and lags at 0, no leakage charge.
  State initial_state() const;
  //! The state after `period` applied from the initial state, with the creep's exact periodic
  //! steady state (PrandtlIshlinskiiCreep::periodic_state()) and no leakage charge: the state
  //! every period of a periodic drive starts from. Throws hyst::Error for an empty or non-finite
  //! period.
  State periodic_state(std::span<const double> period) const;

  //! P = P_s + C in `state` [P units]: the polarisation that strains.
  double polarisation(const State& state) const {
    return butterfly_.polarisation(state.switching) + creep_.output(state.creep) -
           state.creep.leakage;
  }
  //! P + L: the polarisation a charge integrator measures [P units].
  double measured_polarisation(const State& state) const {
    return butterfly_.polarisation(state.switching) + creep_.output(state.creep);
  }

  //! Advances one sample and returns y. No allocation, no virtual call.
  double step(State& state, double input) const noexcept {
    const double switching = butterfly_.polarisation_model().step(state.switching, input);
    const double creep = creep_.step(state.creep, input) - state.creep.leakage;
    return butterfly_.strain(input, switching + creep);
  }
  //! The polarisation P (without leakage) step(state, input) would reach, without changing
  //! `state`. No allocation.
  double preview_polarisation(const State& state, double input) const noexcept {
    const double switching = butterfly_.polarisation_model().preview(state.switching, input);
    const auto& p = creep_.params();
    // The lags' memory sum c_ij a_i z_ij, then their share of the current plays.
    double creep =
        creep_.creep_memory(state.creep) - state.creep.leakage - p.sample_time * p.leakage_current;
    for (std::size_t j = 0; j < current_share_.size(); ++j)
      creep += current_share_[j] * play_step(input, p.thresholds[j], state.creep.play[j]);
    return switching + creep;
  }
  //! The output step(state, input) would return, without changing `state`. No allocation.
  double preview(const State& state, double input) const noexcept {
    return butterfly_.strain(input, preview_polarisation(state, input));
  }

 private:
  Params params_;
  ButterflyStrain butterfly_;
  PrandtlIshlinskiiCreep creep_;
  std::vector<double> current_share_;  // sum_i c_ij (1 - a_i): the lags' share of play j now
};

}  // namespace hyst
