#pragma once
//! \file
//! The discrete Preisach model evaluated relay by relay: the brute-force reference implementation
//! that the fast Everett form (preisach.hpp) is tested against.
//!
//!     s_ij[k] = +1 if v[k] >= c_i,  else -1 if v[k] <= c_j,  else s_ij[k-1]      (i >= j)
//!     y[k]    = y_off + sum_{i >= j} mu_ij s_ij[k]
//!
//! with the thresholds c_k and weights mu_ij of RelayGridEverett (everett_relay_grid.hpp). Every
//! relay is updated and summed at every sample: O(N^2) per sample (5 us for N = 101, 0.4 ms for
//! N = 1001), so use it only to check the fast form. It shares nothing with the fast form but the
//! threshold formula and the parameter validation; its state is the relay vector itself, so any
//! relay pattern can be set directly (the fast form needs an input history instead).
//! Source: Preisach (1935); the seed paper's 231-relay model (preisach.md sec. 4).

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "hyst/core/assert.hpp"
#include "hyst/models/preisach.hpp"

namespace hyst {

class PreisachRelayGrid {
 public:
  using Params = Preisach::Params;  //!< the same parameters as the fast discrete model
  struct State {
    std::vector<std::int8_t> relays;  //!< s_ij = -1 or +1 at index i(i+1)/2 + j
  };

  //! Validates exactly like Preisach; throws hyst::Error.
  explicit PreisachRelayGrid(Params params);

  const Params& params() const { return params_; }
  std::span<const double> thresholds() const { return thresholds_; }
  std::size_t relay_count() const { return params_.everett.weights.size(); }

  //! The state chosen by params().initial_state.
  State initial_state() const { return make_state(params_.initial_state); }
  //! Every relay -1, every relay +1, or demagnetised: s_ij = +1 iff i + j <= N - 2, i.e.
  //! alpha + beta < lower + upper on the grid.
  State make_state(PreisachInitialState kind) const;
  //! Any relay pattern; throws hyst::Error unless it has N(N+1)/2 entries, each -1 or +1.
  State make_state(std::vector<std::int8_t> relays) const;

  //! y_off + sum mu_ij s_ij.
  double output(const State& state) const;

  //! Updates every relay and returns y. No allocation.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    HYST_ASSERT(state.relays.size() == params_.everett.weights.size(), "state of another model");
    const std::size_t n = params_.everett.levels;
    const double* c = thresholds_.data();
    const double* mu = params_.everett.weights.data();
    std::int8_t* s = state.relays.data();
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const bool up = input >= c[i];
      const std::size_t row = preisach_relay_index(i, 0);
      for (std::size_t j = 0; j <= i; ++j) {
        const std::int8_t next =
            up ? std::int8_t{1} : (input <= c[j] ? std::int8_t{-1} : s[row + j]);
        s[row + j] = next;
        sum += mu[row + j] * static_cast<double>(next);
      }
    }
    return params_.offset + sum;
  }

 private:
  Params params_;
  std::vector<double> thresholds_;
};

}  // namespace hyst
