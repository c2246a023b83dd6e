#pragma once
//! \file
//! Numerical inverse of any model whose output, from a given state, increases with the next input
//! sample (Bouc-Wen with alpha_k > 0 or z-branches of positive slope, backlash-like with
//! B1 >= c/2, Duhem with g > 0, Jiles-Atherton B(H)): for each desired output the next input is
//! found by bracketing from the previous input (doubling steps) and bisection to rounding, then the
//! model is advanced with it. Inputs are kept within [input_min, input_max]; a target outside
//! what the limits reach gives the limit and a below_range / above_range status.
//!
//! Cost: about 2 x 64 model steps per sample; no allocation. Models whose output is not monotone
//! in the next input (the dynamic Bouc-Wen oscillator) are not inverted this way.

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "hyst/core/inverse_status.hpp"
#include "hyst/core/model_concept.hpp"

namespace hyst {

template <HysteresisModel M>
class MonotoneInverse {
 public:
  struct State {
    typename M::State model;
    double input = 0.0;  //!< the last input returned
  };

  MonotoneInverse(M model, double input_min, double input_max)
      : model_(std::move(model)), input_min_(input_min), input_max_(input_max) {}

  const M& model() const { return model_; }

  InverseSample solve(State& state, double target) const {
    auto output_at = [&](double input) {
      auto probe = state.model;
      return model_.step(probe, input);
    };
    const double start = std::min(std::max(state.input, input_min_), input_max_);
    double lo = start, hi = start;
    const double y_start = output_at(start);
    InverseSample sample;
    double step = std::max(1e-3, 1e-3 * std::abs(start));
    if (y_start < target) {
      // Walk up until the output reaches the target or the limit.
      while (true) {
        hi = std::min(lo + step, input_max_);
        if (output_at(hi) >= target) break;
        if (hi >= input_max_ || !std::isfinite(hi) || step > 1e300) {
          sample = {hi, InverseStatus::above_range};
          advance(state, hi);
          return sample;
        }
        lo = hi;
        step *= 2.0;
      }
    } else if (y_start > target) {
      while (true) {
        lo = std::max(hi - step, input_min_);
        if (output_at(lo) <= target) break;
        if (lo <= input_min_ || !std::isfinite(lo) || step > 1e300) {
          sample = {lo, InverseStatus::below_range};
          advance(state, lo);
          return sample;
        }
        hi = lo;
        step *= 2.0;
      }
    } else {
      advance(state, start);
      return {start, InverseStatus::ok};
    }
    for (int i = 0; i < 200 && hi - lo > 4 * std::numeric_limits<double>::epsilon() *
                                             (std::abs(lo) + std::abs(hi) + 1e-300);
         ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (output_at(mid) < target ? lo : hi) = mid;
    }
    const double input =
        std::abs(output_at(lo) - target) <= std::abs(output_at(hi) - target) ? lo : hi;
    advance(state, input);
    return {input, InverseStatus::ok};
  }

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
