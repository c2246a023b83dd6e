#pragma once
//! \file
//! Krasnosel'skii-Pokrovskii (KP) model: a weighted sum of KP kernels (relays with ramps) on a
//! triangular grid, like the discrete Preisach model but with an output that is continuous in the
//! input.
//!
//!     rho_a(x)    = -1 (x < 0),  -1 + 2x/a (0 <= x <= a),  +1 (x > a)
//!     kappa_ij[k] = max( rho_a(v[k] - s_i), min( rho_a(v[k] - s_j), kappa_ij[k-1] ) ),  i >= j
//!     y[k]        = y_off + sum_{i >= j} mu_ij kappa_ij[k]
//!
//! Kernel (i, j) (kp_kernel.hpp) switches up along a ramp from -1 at v = s_i to +1 at s_i + a and
//! down from +1 at s_j + a to -1 at s_j (s_j <= s_i). Grid: N cells of width D = (upper - lower)/N,
//! thresholds s_k = lower + k D (k = 0..N-1), ramp width a = ramp_cells D (default one cell): with
//! one cell every kernel is +1 for v >= upper and -1 for v <= lower, so the output saturates at
//! y_off +- sum mu there, and a -> 0 gives the Preisach relay grid. N(N+1)/2 kernels, stored at
//! index i(i+1)/2 + j like the Preisach relays.
//!
//! Parameters: levels N >= 1, lower < upper [input units], weights mu_ij >= 0 [output units],
//! ramp_cells > 0 [-], offset y_off [output units]. Initial state: every kernel at -1 (negative
//! saturation). Properties: rate independent; monotone (mu >= 0: the output never moves against
//! the input); return-point memory and closed minor loops (the kernels are max/min compositions
//! like the play operator); Lipschitz continuous in the input with constant sum mu 2/a.
//! Cost: O(N^2) per sample (every kernel is updated).
//! Sources: Krasnosel'skii & Pokrovskii (1989) "Systems with Hysteresis"; Banks, Kurdila & Webb
//! (1997); Hassani et al. (2014), MSSP 49:209; reference operators.md sec. 6, other_models.md sec.
//! 7.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "hyst/core/assert.hpp"
#include "hyst/operators/kp_kernel.hpp"

namespace hyst {

class KrasnoselskiiPokrovskii {
 public:
  struct Params {
    std::size_t levels = 1;         //!< N cells / thresholds, 1 .. 4096
    double lower = -1.0;            //!< [input units]
    double upper = 1.0;             //!< [input units], > lower
    std::vector<double> weights{};  //!< mu_ij >= 0, N(N+1)/2 of them, (i, j) at i(i+1)/2 + j
    double ramp_cells = 1.0;        //!< ramp width a in cells, > 0
    double offset = 0.0;            //!< y_off [output units]
  };
  struct State {
    std::vector<double> kernels;  //!< kappa_ij in [-1, 1]
    std::vector<double> ridge;    //!< work space: rho_a(v - s_k), k = 0..N-1 (no meaning between
                                  //!< samples; kept here so that step() does not allocate)
  };

  //! Throws hyst::Error naming the field ("KP weight mu[3] = -1 must be >= 0", field
  //! "weights[3]").
  explicit KrasnoselskiiPokrovskii(Params params);

  const Params& params() const { return params_; }
  std::size_t kernel_count() const { return params_.weights.size(); }
  //! s_k [input units], k = 0..N-1.
  std::span<const double> thresholds() const { return thresholds_; }
  //! a [input units].
  double ramp_width() const { return ramp_; }
  //! sum mu: the output is y_off +- this at saturation.
  double total_weight() const;

  //! Every kernel at -1.
  State initial_state() const;
  //! Given kernel values; throws hyst::Error unless there are N(N+1)/2, each in [-1, 1].
  State make_state(std::vector<double> kernels) const;

  double output(const State& state) const;

  //! Advances one sample: every kernel, then the weighted sum. No allocation.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    HYST_ASSERT(
        state.ridge.size() == params_.levels && state.kernels.size() == params_.weights.size(),
        "state of another model");
    const std::size_t n = params_.levels;
    double* __restrict rho = state.ridge.data();
    for (std::size_t k = 0; k < n; ++k)
      rho[k] = kp_ridge(input - thresholds_[k], two_over_ramp_);
    double* __restrict kappa = state.kernels.data();
    // Update first (a loop the compiler vectorises), then Eigen's vectorised dot product: a fused
    // loop would keep the written order of the additions and run scalar.
    for (std::size_t i = 0, row = 0; i < n; row += ++i) {
      const double up = rho[i];
      for (std::size_t j = 0; j <= i; ++j)
        kappa[row + j] = kp_kernel_step(up, rho[j], kappa[row + j]);
    }
    const auto count = static_cast<Eigen::Index>(params_.weights.size());
    const double sum = Eigen::Map<const Eigen::VectorXd>(params_.weights.data(), count)
                           .dot(Eigen::Map<const Eigen::VectorXd>(kappa, count));
    return params_.offset + sum;
  }

  //! The output step() would return for `input`, without changing the state (for the numerical
  //! inverse's search). No allocation: the ridge values are computed on the fly.
  double preview(const State& state, double input) const noexcept {
    const std::size_t n = params_.levels;
    const double* kappa = state.kernels.data();
    double sum = 0.0;
    for (std::size_t i = 0, row = 0; i < n; row += ++i) {
      const double up = kp_ridge(input - thresholds_[i], two_over_ramp_);
      for (std::size_t j = 0; j <= i; ++j) {
        const double down = kp_ridge(input - thresholds_[j], two_over_ramp_);
        sum += params_.weights[row + j] * kp_kernel_step(up, down, kappa[row + j]);
      }
    }
    return params_.offset + sum;
  }

 private:
  Params params_;
  std::vector<double> thresholds_;
  double ramp_;
  double two_over_ramp_;
};

}  // namespace hyst
