#pragma once
//! \file
//! Modified Prandtl-Ishlinskii model with creep (Kuhnen 2001, 2003): hysteresis and creep
//! superposed, then a memory-free dead-zone superposition that makes the loops asymmetric and
//! saturating,
//!
//!     y = clamp(y_off + S( Gamma_c[v] ), y_min, y_max)
//!     Gamma_c[v] = q + sum_j p_j w_j + sum_ij c_ij z_ij   (PI with creep,
//!     prandtl_ishlinskii_creep.hpp) S(x) = sum_i g_i S_{d_i}(x) (dead_zone_superposition.hpp)
//!
//! It is to the PI with creep what the modified PI (modified_prandtl_ishlinskii.hpp) is to the
//! PI: with S the identity (one dead zone d_0 = 0, g_0 = 1) it is the PI with creep, with no
//! creep weights the modified PI. Monotone and invertible sample by sample when the instantaneous
//! PI (weights p_j + sum_i c_ij (1 - a_i)) and S are invertible:
//! InverseModifiedPrandtlIshlinskiiCreep.
//!
//! Parameters: the PI with creep (thresholds r_j [input units], weights p_j, time constants tau_i
//! [s], creep weights c_ij >= 0, sample time Ts [s], its offset q [output units]); the dead zones
//! (thresholds d_i [output units], weights g_i [-]); the output offset y_off and the optional
//! output limits y_min < y_max [output units] (default: none). State: the plays and the creep
//! elements of the PI with creep, 0 in the virgin state.
//! Sources: Kuhnen (2001), "Modellbildung und Kompensation von Kriech- und Hystereseeffekten";
//! Kuhnen (2003), Eur. J. Control 9(4):407-418.

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "hyst/core/assert.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"
#include "hyst/operators/dead_zone_superposition.hpp"

namespace hyst {

class ModifiedPrandtlIshlinskiiCreep {
 public:
  struct Params {
    PrandtlIshlinskiiCreep::Params pi_creep{};  //!< Gamma_c, its offset q
    DeadZoneSuperposition::Params dead_zone{};  //!< S: thresholds d_i, weights g_i
    double offset = 0.0;                        //!< y_off [output units]
    double output_min = -std::numeric_limits<double>::infinity();  //!< y_min [output units]
    double output_max = std::numeric_limits<double>::infinity();   //!< y_max [output units]
  };
  using State = PrandtlIshlinskiiCreep::State;

  //! Validates both parts; hyst::Error::field() is prefixed "pi_creep." or "dead_zone.".
  explicit ModifiedPrandtlIshlinskiiCreep(Params params);

  const Params& params() const { return params_; }
  //! Gamma_c, the PI with creep ahead of the dead zones.
  const PrandtlIshlinskiiCreep& hysteresis_creep() const { return core_; }
  const DeadZoneSuperposition& dead_zone() const { return dead_zone_; }
  //! True when the instantaneous PI and the dead-zone map are both invertible.
  bool is_invertible() const;

  //! The same model discretised at another sample time (PrandtlIshlinskiiCreep::at_sample_time).
  ModifiedPrandtlIshlinskiiCreep at_sample_time(double sample_time) const;

  State initial_state() const { return core_.initial_state(); }
  State state_at_rest(double input) const { return core_.state_at_rest(input); }
  //! The periodic steady state of `period` (PrandtlIshlinskiiCreep::periodic_state(): the dead
  //! zones have no memory).
  State periodic_state(std::span<const double> period) const {
    return core_.periodic_state(period);
  }
  State make_state(std::vector<double> play, std::vector<double> creep) const {
    return core_.make_state(std::move(play), std::move(creep));
  }
  double output(const State& state) const { return shaped(core_.output(state)); }

  //! Advances one sample. No allocation, no virtual call.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    return shaped(core_.step(state, input));
  }

 private:
  double shaped(double hysteresis_and_creep) const noexcept {
    return std::clamp(params_.offset + dead_zone_(hysteresis_and_creep), params_.output_min,
                      params_.output_max);
  }

  Params params_;
  PrandtlIshlinskiiCreep core_;
  DeadZoneSuperposition dead_zone_;
};

}  // namespace hyst
