#pragma once
//! \file
//! Numerical inverse of any model whose output, from a given state, increases with the next input
//! sample (Bouc-Wen with alpha_k > 0 or z-branches of positive slope, backlash-like with
//! B1 >= c/2, Duhem with g > 0, Jiles-Atherton B(H)), over an input range that may be unbounded:
//! for each desired output a bracket is grown from the previous input by doubling steps, then
//! narrowed by the bracketed search shared with the other numerical inverses
//! (bracketed_search.hpp) down to rounding; the model is advanced with the answer. Inputs are kept
//! within [input_min, input_max] (infinite by default); a target outside what the limits reach
//! gives the limit and a below_range / above_range status.
//!
//! Compared with NumericalInverse (numerical_inverse.hpp), which needs a finite range, this one
//! needs none but only serves increasing maps. Cost: a few dozen model steps per sample; no
//! allocation. Models whose output is not monotone in the next input (the dynamic Bouc-Wen
//! oscillator) are not inverted this way.

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/core/inverse_status.hpp"
#include "hyst/core/model_concept.hpp"
#include "hyst/inverse/bracketed_search.hpp"

namespace hyst {

template <HysteresisModel M>
class MonotoneInverse {
 public:
  struct State {
    typename M::State model;
    double input = 0.0;  //!< the last input returned
  };

  //! Throws hyst::Error unless input_min < input_max (either may be infinite, neither NaN).
  MonotoneInverse(M model, double input_min, double input_max)
      : model_(std::move(model)), input_min_(input_min), input_max_(input_max) {
    if (!(input_min_ < input_max_)) {
      throw Error(fmt::format("monotone inverse input_min = {} must be < input_max = {}",
                              input_min_, input_max_),
                  "input_min");
    }
  }

  const M& model() const { return model_; }

  //! The input that makes the model produce `target` from `state`, which is advanced with it.
  //! Never allocates. Precondition: `target` is finite.
  InverseSample solve(State& state, double target) const {
    const auto output_at = [&](double input) {
      auto probe = state.model;
      return model_.step(probe, input);
    };
    const double start = std::clamp(state.input, input_min_, input_max_);
    const double y_start = output_at(start);
    if (y_start == target) {
      advance(state, start);
      return {start, InverseStatus::ok};
    }
    // Grow a bracket [lo, hi] with y(lo) < target <= y(hi) (or mirrored) from the last input.
    const bool rising = y_start < target;
    double lo = start;
    double hi = start;
    double step = std::max(1e-3, 1e-3 * std::abs(start));
    while (true) {
      const double limit = rising ? input_max_ : input_min_;
      const double trial = rising ? std::min(hi + step, limit) : std::max(lo - step, limit);
      const double y_trial = output_at(trial);
      if (rising ? y_trial >= target : y_trial <= target) {
        (rising ? hi : lo) = trial;
        break;
      }
      if (trial == limit || !std::isfinite(trial) || step > 1e300) {
        advance(state, trial);
        return {trial, rising ? InverseStatus::above_range : InverseStatus::below_range};
      }
      lo = hi = trial;
      step *= 2.0;
    }
    // Narrow it down to rounding: no double is left between the ends before this width.
    BracketedSearch search;
    search.input_min = lo;
    search.input_max = hi;
    search.tolerance =
        4.0 * std::numeric_limits<double>::epsilon() * (std::abs(lo) + std::abs(hi)) +
        std::numeric_limits<double>::denorm_min();
    search.max_iterations = 600;
    const InverseSample sample = bracketed_search(search, output_at, rising ? lo : hi, target);
    advance(state, sample.input);
    return sample;
  }

  //! solve() without the status, so the inverse also runs wherever a model does.
  double step(State& state, double target) const { return solve(state, target).input; }

 private:
  void advance(State& state, double input) const {
    model_.step(state.model, input);
    state.input = input;
  }

  M model_;
  double input_min_;
  double input_max_;
};

}  // namespace hyst
