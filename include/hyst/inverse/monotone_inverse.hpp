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
//! Every search is bounded, so a target the model cannot reach (a saturating Bouc-Wen asked for
//! 1e300) costs a bounded number of steps and is answered with the reachable extreme and a status:
//! - the bracket grows from the first step 1e-3 max(1, |v_now|) by doubling, at most 64 steps, and
//!   no further than the search span 2^50 first steps (about 1.1e12 max(1, |v_now|)) or the
//!   model's `max_input_jump()` where it has one (Bouc-Wen's RK4: the jump it integrates stably);
//! - three doubling steps in a row that leave the output unchanged (within 8 eps) mean
//!   saturation; an output that is not finite ends the search at the last finite one;
//! - the answer is checked by re-simulating: an output further than 1e-9 max(|y*|, |y_now|) +
//!   1e-6 |y* - y_now| from the target is reported as out of reach (below_range / above_range).
//!
//! Compared with NumericalInverse (numerical_inverse.hpp), which needs a finite range, this one
//! needs none but only serves increasing maps. Cost: a few dozen model steps per sample, at most
//! max_expansions() + 604; no allocation. Models whose output is not monotone in the next input
//! (the dynamic Bouc-Wen oscillator) are not inverted this way.

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
  //! Never allocates; at most max_expansions() + 604 model steps. A NaN target holds the last
  //! input (status not_invertible); +-inf is out of reach in its direction.
  InverseSample solve(State& state, double target) const {
    const auto output_at = [&](double input) {
      auto probe = state.model;
      return model_.step(probe, input);
    };
    const double start = std::clamp(state.input, input_min_, input_max_);
    if (std::isnan(target)) {
      advance(state, start);
      return {start, InverseStatus::not_invertible};
    }
    const double y_start = output_at(start);
    if (y_start == target) {
      advance(state, start);
      return {start, InverseStatus::ok};
    }
    // Grow a bracket [lo, hi] with y(lo) < target <= y(hi) (or mirrored) from the last input,
    // by doubling steps within the limits and the search span.
    const bool rising = y_start < target;
    const InverseStatus short_of = rising ? InverseStatus::above_range : InverseStatus::below_range;
    const double first_step = kFirstStep * std::max(1.0, std::abs(start));
    double span = first_step * kSpanSteps;
    if constexpr (requires { model_.max_input_jump(); })
      span = std::min(span, model_.max_input_jump());
    const double limit =
        rising ? std::min(input_max_, start + span) : std::max(input_min_, start - span);
    double lo = start;
    double hi = start;
    double y_previous = y_start;
    double step = first_step;
    int flat = 0;
    for (std::size_t expansion = 0;; ++expansion) {
      const double trial = rising ? std::min(hi + step, limit) : std::max(lo - step, limit);
      const double y_trial = output_at(trial);
      if (rising ? y_trial >= target : y_trial <= target) {
        (rising ? hi : lo) = trial;
        break;
      }
      // Out of reach: the limit (given or the search span) is met, the search is out of
      // expansions, or the output has stopped moving over growing steps (saturated).
      flat = std::abs(y_trial - y_previous) <=
                     8.0 * std::numeric_limits<double>::epsilon() * std::abs(y_trial)
                 ? flat + 1
                 : 0;
      if (!std::isfinite(y_trial)) {  // beyond what the model computes: the last good input
        const double last = rising ? hi : lo;
        advance(state, last);
        return {last, short_of};
      }
      if (trial == limit || expansion + 1 >= kMaxExpansions || flat >= kFlatExpansions) {
        advance(state, trial);
        return {trial, short_of};
      }
      lo = hi = trial;
      y_previous = y_trial;
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
    InverseSample sample = bracketed_search(search, output_at, rising ? lo : hi, target);
    // Check by re-simulating: the answer's output must be the target up to the rounding of the
    // bracket; else (a map that is not monotone after all) the target counts as out of reach.
    const double y = advance(state, sample.input);
    const double slack = 1e-9 * std::max({std::abs(target), std::abs(y_start), 1e-300}) +
                         1e-6 * std::abs(target - y_start);
    if (sample.status == InverseStatus::ok && !(std::abs(y - target) <= slack)) {
      sample.status = y < target ? InverseStatus::above_range : InverseStatus::below_range;
    }
    return sample;
  }

  //! The most doubling steps one sample takes to bracket its target.
  static constexpr std::size_t max_expansions() { return kMaxExpansions; }

  //! solve() without the status, so the inverse also runs wherever a model does.
  double step(State& state, double target) const { return solve(state, target).input; }

 private:
  double advance(State& state, double input) const {
    state.input = input;
    return model_.step(state.model, input);
  }

  // Bracket growth: the first step is kFirstStep max(1, |v_now|) and doubles; the search span
  // is kSpanSteps first steps (2^50, about 1.1e12 max(1, |v_now|)) on either side of v_now.
  static constexpr double kFirstStep = 1e-3;
  static constexpr double kSpanSteps = 1125899906842624.0;  // 2^50
  static constexpr std::size_t kMaxExpansions = 64;
  // Doubling steps in a row without any change of the output: saturated, out of reach.
  static constexpr int kFlatExpansions = 3;

  M model_;
  double input_min_;
  double input_max_;
};

}  // namespace hyst
