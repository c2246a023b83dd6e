#pragma once
//! \file
//! Modified Prandtl-Ishlinskii model (Kuhnen 2003): a classical PI model followed by a
//! memory-free superposition of dead-zone operators, which makes the loops asymmetric and
//! saturating while keeping an analytic inverse.
//!
//!     y = clamp(y_off + S[ Gamma[v] ], y_min, y_max)
//!     Gamma[v] = q + sum_j p_j F_{r_j}[v]        (PI, prandtl_ishlinskii.hpp)
//!     S(x) = sum_{i=-l..l} g_i S_{d_i}(x)        (dead_zone_superposition.hpp)
//!
//! Parameters: the PI part (thresholds r_j [input units], weights p_j, its own offset q [output
//! units]), the dead-zone part (thresholds d_i [output units] around d_0 = 0, weights g_i [-]),
//! the output offset y_off [output units] and optional output limits y_min < y_max [output units]
//! (default -inf, +inf: no clamp). A fit sets them to the output range of its record: where the
//! measured output saturates, the fitted inverse map S' flattens to its minimum slope and S
//! becomes nearly vertical beyond the fitted range, so an unclamped model predicts without bound
//! there. The limits keep the prediction inside the fitted range instead. The model is monotone and
//! invertible iff both parts are (p_0 > 0 and the PI partial sums > 0; g_0 > 0 and the outward
//! dead-zone partial sums > 0): InverseModifiedPrandtlIshlinskii. The pair (Gamma, S) is defined up
//! to a scale c > 0 (Gamma -> c Gamma, S(x) -> S(x/c)); fits fix g_0 = 1. State: the PI part's play
//! outputs (prandtl_ishlinskii.hpp), by default all 0. Kuhnen's creep operators are not included.
//! Source: Kuhnen (2003), Eur. J. Control 9(4):407-418.

#include <algorithm>
#include <cmath>
#include <limits>

#include "hyst/core/assert.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/operators/dead_zone_superposition.hpp"

namespace hyst {

class ModifiedPrandtlIshlinskii {
 public:
  struct Params {
    PrandtlIshlinskii::Params pi{};             //!< Gamma: thresholds, weights, offset q
    DeadZoneSuperposition::Params dead_zone{};  //!< S: thresholds d_i, weights g_i
    double offset = 0.0;                        //!< y_off [output units]
    double output_min = -std::numeric_limits<double>::infinity();  //!< y_min [output units]
    double output_max = std::numeric_limits<double>::infinity();   //!< y_max [output units]
  };
  using State = PrandtlIshlinskii::State;

  //! Validates both parts; hyst::Error::field() is prefixed "pi." or "dead_zone.".
  explicit ModifiedPrandtlIshlinskii(Params params);

  const Params& params() const { return params_; }
  const PrandtlIshlinskii& hysteresis() const { return pi_; }
  const DeadZoneSuperposition& dead_zone() const { return dead_zone_; }
  bool is_invertible() const { return pi_.is_invertible() && dead_zone_.is_invertible(); }

  State initial_state() const { return pi_.initial_state(); }
  State make_state(std::vector<double> play) const { return pi_.make_state(std::move(play)); }
  double output(const State& state) const { return limited(dead_zone_(pi_.output(state))); }

  //! Advances one sample. No allocation.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    return limited(dead_zone_(pi_.step(state, input)));
  }

 private:
  double limited(double shaped) const noexcept {
    return std::clamp(params_.offset + shaped, params_.output_min, params_.output_max);
  }

  Params params_;
  PrandtlIshlinskii pi_;
  DeadZoneSuperposition dead_zone_;
};

}  // namespace hyst
