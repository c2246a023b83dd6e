#pragma once
//! \file
//! Prandtl-Ishlinskii (PI) model: a weighted sum of play operators.
//!
//!     y[k] = y_off + sum_{j=0..n} p_j w_j[k]
//!     w_j[k] = max(v[k] - r_j, min(v[k] + r_j, w_j[k-1]))
//!
//! Parameters
//! - thresholds r_j [input units]: 0 = r_0 < r_1 < ... < r_n (the r = 0 play is the linear term);
//! - weights p_j [output/input units]: any finite reals. The model is monotone and invertible iff
//!   p_0 > 0 and every partial sum S_j = p_0 + ... + p_j > 0 (see InversePrandtlIshlinskii);
//! - offset y_off [output units].
//! State: the play outputs w_j [input units], by default 0 (the "virgin" state at v = 0).
//! A state reached by some input history satisfies |w_i - w_j| <= |r_i - r_j|; make_state()
//! rejects others, because the inverse cannot be started consistently from them.
//!
//! The model is rate independent (only the sequence of input values matters, no sample time) and
//! cannot saturate: its loops are odd-symmetric about their centre. Use the generalized PI or the
//! modified PI for saturating or asymmetric loops.
//! Sources: Krasnosel'skii & Pokrovskii (1989); Brokate & Sprekels (1996); Kuhnen (2003).

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "hyst/core/assert.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {

class PrandtlIshlinskii {
 public:
  struct Params {
    std::vector<double> thresholds;  //!< r_j [input units], 0 = r_0 < r_1 < ...
    std::vector<double> weights;     //!< p_j [output/input units], one per threshold
    double offset = 0.0;             //!< y_off [output units]
  };
  struct State {
    std::vector<double> play;  //!< w_j [input units], one per threshold
  };

  //! Validates the parameters; throws hyst::Error naming the first one that breaks a rule,
  //! e.g. "PI threshold r[3] = -0.2 must be > r[2] = 0.5".
  explicit PrandtlIshlinskii(Params params);

  const Params& params() const { return params_; }
  //! Number of play operators, n + 1.
  std::size_t size() const { return params_.thresholds.size(); }

  //! All w_j = 0: the virgin state at v = 0.
  State initial_state() const;
  //! All w_j = v0: at rest at input v0, every play centred.
  State state_at_rest(double input) const;
  //! A given state; throws hyst::Error if its size is wrong, a value is not finite, or no input
  //! history can reach it (|w_i - w_j| > r_j - r_i).
  State make_state(std::vector<double> play) const;

  //! True iff p_0 > 0 and all partial sums S_j > 0 (monotone, analytically invertible).
  bool is_invertible() const;

  //! Output of the model in a given state, without advancing it.
  double output(const State& state) const;

  //! Advances one sample: updates every play and returns y. No allocation, no virtual call.
  //! Precondition: `state` comes from this model and `input` is finite.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    HYST_ASSERT(state.play.size() == params_.thresholds.size(), "state of another model");
    const std::size_t n = params_.thresholds.size();
    const double* __restrict r = params_.thresholds.data();
    double* __restrict w = state.play.data();
    for (std::size_t j = 0; j < n; ++j)
      w[j] = play_step(input, r[j], w[j]);
    return params_.offset + weighted_sum(w);
  }

 private:
  // Eigen's vectorised dot product: the weighted sum is as costly as the play updates.
  double weighted_sum(const double* play) const noexcept {
    const auto n = static_cast<Eigen::Index>(params_.weights.size());
    return Eigen::Map<const Eigen::VectorXd>(params_.weights.data(), n)
        .dot(Eigen::Map<const Eigen::VectorXd>(play, n));
  }

  Params params_;
};

//! Thresholds r_j = spacing * j, j = 0..count-1. Throws hyst::Error unless count >= 1 and
//! spacing > 0.
std::vector<double> uniform_thresholds(std::size_t count, double spacing);

}  // namespace hyst
