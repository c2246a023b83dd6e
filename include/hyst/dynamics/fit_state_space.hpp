#pragma once
//! \file
//! A discrete-time MIMO state-space model of chosen order fitted to a best linear approximation
//! (best_linear_approximation.hpp), in two stages:
//!
//! 1. Frequency-domain subspace identification (McKelvey, Akcay & Ljung, "Subspace-based
//!    multivariable system identification from frequency response data", IEEE TAC 41(7), 1996,
//!    algorithm 2): A and C from the range of a block-Hankel-like matrix of z^i G(z), B and D by
//!    linear least squares. Unstable poles are reflected into the unit circle.
//! 2. Weighted nonlinear least squares on the frequency response (Levenberg-Marquardt, Ceres,
//!    analytic Jacobian): sum over lines and entries of |G_model - G_BLA|^2, optionally divided
//!    by the BLA's variance at the line (BlaWeighting). The model is kept
//!    in real modal form (2 x 2 blocks rho [cos t, sin t; -sin t, cos t] for complex pole pairs,
//!    scalars for real poles) with the pole radii bounded below 1: the result is stable by
//!    construction.
//!
//! The report's `fit` error is measured on the real and imaginary parts of the BLA's entries
//! (measured) against the model's (predicted); its costs are the weighted ones.

#include <cstddef>
#include <string_view>

#include "hyst/core/progress.hpp"
#include "hyst/dynamics/best_linear_approximation.hpp"
#include "hyst/dynamics/state_space.hpp"
#include "hyst/identify/fit_report.hpp"

namespace hyst {

//! What weights the frequency-response residuals. With orthogonal multisines of flat spectrum,
//! `none` minimises the periodic steady-state simulation error (Parseval: the output error at a
//! line is the response error times the input spectrum, the same at every line), which is what
//! the benchmarks score; the variances give the statistically efficient estimate of the BLA,
//! which a nonlinear system's errors need not favour (on the FSM benchmark: 6.5 % with none,
//! 8.2 % with the total variance, docs/results.md).
enum class BlaWeighting {
  total_variance,  //!< 1 / the BLA's total variance (noise and distortions); noise or none when
                   //!< the BLA has no total variance
  noise_variance,  //!< 1 / the BLA's noise variance
  none,            //!< every line alike (scaled by the response's RMS)
};

//! "total_variance", "noise_variance", "none".
constexpr EnumNames<BlaWeighting, 3> enumerator_names(BlaWeighting) {
  return {{
      {BlaWeighting::total_variance, "total_variance"},
      {BlaWeighting::noise_variance, "noise_variance"},
      {BlaWeighting::none, "none"},
  }};
}

//! The inverse of to_string(); throws hyst::Error naming the accepted values.
BlaWeighting bla_weighting_from_string(std::string_view text);

//! The highest order a fit takes: 100. Its Jacobian has a row per line, output, input and part
//! (real, imaginary) and about (m + p + 1) n columns, so its memory grows with n and each
//! iteration's time with n^2. Measured on the FSM benchmark's 200 mV training set (3839 lines,
//! 3 x 3 channels; CPU time on this 2-core machine): about 5 MB per state (peak 0.26, 0.50 and
//! 1.05 GB at n = 50, 100 and 200), and 1.7, 6.3 and 31 s per Levenberg-Marquardt iteration. At
//! the default limit of 200 iterations that is at most 21 minutes at n = 100, but 1.7 hours at
//! n = 200 and about 11 hours at n = 500 (which took 2.8 GB); the fits in use have 28 and 44
//! states and converge in 60 to 90 iterations.
inline constexpr std::size_t kMaxStateSpaceFitOrder = 100;

struct StateSpaceFitOptions {
  std::size_t order = 2;                //!< 1 <= n <= kMaxStateSpaceFitOrder states
  std::size_t subspace_block_rows = 0;  //!< q > n of the subspace step; 0: 2n + 2
  BlaWeighting weighting = BlaWeighting::none;
  std::size_t max_iterations = 200;  //!< Levenberg-Marquardt iterations; 0 keeps the subspace model
  double max_pole_radius = 0.99999;  //!< bound on every pole's magnitude, in (0, 1)
  ProgressCallback progress{};       //!< told before each stage
};

struct StateSpaceFit {
  StateSpace model;
  FitReport report;
  //! Weighted cost of the subspace model (stage 1), for comparison with report.final_cost.
  double subspace_cost = 0.0;
};

//! Throws hyst::Error for an order below 1 or above kMaxStateSpaceFitOrder, fewer lines than the
//! order needs, q <= n, or a pole-radius bound outside (0, 1).
StateSpaceFit fit_state_space(const BestLinearApproximation& bla,
                              const StateSpaceFitOptions& options);

}  // namespace hyst
