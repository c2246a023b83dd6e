#pragma once
//! \file
//! Butterfly strain of a piezoceramic: the voltage switches the polarisation, an ordinary
//! hysteresis loop, and the strain follows the polarisation through a static map.
//!
//!     P[k] = Preisach[v](k)                                    polarisation (relay grid, mu >= 0)
//!     y[k] = y_off + d v[k] + sum_{n=1..N} q_n P[k]^n           strain or displacement
//!
//! Electrostriction gives the even terms (S = Q P^2: the strain is the same for +P and -P, so a
//! loop that switches the polarisation draws a butterfly, non-monotone in v); the odd terms and
//! the field term d v carry what a poled sample adds (a linear piezoelectric part, the clamping of
//! the measurement). With measured polarisation the Preisach output is P in its units
//! [uC/cm^2]; with only voltage and displacement the polarisation is a latent signal and the fit
//! normalises it to total weight F0 = 1 (P in [-1, 1], -1 = negative saturation).
//!
//! Parameters: the Preisach model of P(v) (preisach.hpp: levels, input range [lower, upper]
//! [input units], weights mu >= 0 and P offset [P units], its initial state), the field
//! coefficient d [output / input units], the polarisation coefficients q_1 .. q_N (N >= 1,
//! q_n in output units / P units^n) and the strain offset y_off [output units].
//! Properties: rate independent; the polarisation has return-point memory and wiping-out, so a
//! record that repeats one period is periodic after its first period (periodic_state()); the
//! strain is not monotone in v where dy/dP changes sign (the vertex of the butterfly), and there
//! the model has no inverse (inverse_butterfly_strain.hpp).
//! Common mistakes: fitting a butterfly with a PI or a Preisach model alone (both are monotone in
//! v and cannot draw one); a record whose first sample is not in steady state (use the periodic
//! state); reading the latent P of a voltage-only fit as a measured polarisation (its scale is 1).
//! Sources: Devonshire / Haun et al. (1987) electrostriction S = Q P^2; Hughes & Wen (1997),
//! Smith (2005) "Smart Material Systems" ch. 7 for Preisach polarisation models of PZT.

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/models/preisach.hpp"

namespace hyst {

class ButterflyStrain {
 public:
  struct Params {
    Preisach::Params polarisation;   //!< P(v): relay grid, P offset, initial state
    double field_coefficient = 0.0;  //!< d [output / input units]
    std::vector<double> polarisation_coefficients{0.0, 1.0};  //!< q_1 .. q_N, N >= 1
    double offset = 0.0;                                      //!< y_off [output units]
  };
  using State = PreisachState;

  //! Validates; throws hyst::Error naming the field (the Preisach model's, "field_coefficient",
  //! "polarisation_coefficients[n]", "offset").
  explicit ButterflyStrain(Params params);

  const Params& params() const { return params_; }
  const Preisach& polarisation_model() const { return polarisation_; }
  //! N, the degree of the polynomial in P.
  std::size_t degree() const { return params_.polarisation_coefficients.size(); }

  State initial_state() const { return polarisation_.initial_state(); }
  //! The state after `period` applied from the initial state: for an input that repeats
  //! `period` (its last sample next to its first), the state every period starts from in
  //! steady state (wiping-out makes one period enough). Throws hyst::Error for an empty or
  //! non-finite period.
  State periodic_state(std::span<const double> period) const;

  //! The polarisation in `state` [P units].
  double polarisation(const State& state) const { return polarisation_.output(state); }
  //! y_off + d v + sum q_n P^n [output units]: the static map.
  double strain(double input, double polarisation) const noexcept {
    const auto& q = params_.polarisation_coefficients;
    double sum = 0.0;
    for (std::size_t n = q.size(); n-- > 0;)
      sum = (sum + q[n]) * polarisation;
    return params_.offset + params_.field_coefficient * input + sum;
  }
  //! dy/dP at `polarisation` [output / P units].
  double strain_slope(double polarisation) const noexcept {
    const auto& q = params_.polarisation_coefficients;
    double sum = 0.0;
    for (std::size_t n = q.size(); n-- > 0;)
      sum = sum * polarisation + static_cast<double>(n + 1) * q[n];
    return sum;
  }

  //! Advances one sample and returns y. No allocation, no virtual call.
  double step(State& state, double input) const noexcept {
    return strain(input, polarisation_.step(state, input));
  }
  //! The output step(state, input) would return, without changing `state`.
  double preview(const State& state, double input) const noexcept {
    return strain(input, polarisation_.preview(state, input));
  }

 private:
  Params params_;
  Preisach polarisation_;
};

}  // namespace hyst
