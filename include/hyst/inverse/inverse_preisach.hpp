#pragma once
//! \file
//! Numerical inverse of a Preisach model, one sample at a time, by bracketed search on a monotone
//! map.
//!
//! The Preisach model has no analytic inverse (unlike PI). But with a density mu >= 0 the output
//! one step ahead, y(u) = preview(state, u), is a non-decreasing function of the next input u over
//! the whole line, whatever the memory: rising from the current input it follows the ascending
//! branch (y(u) = y_now + 2 E(u, v_now)-type terms), falling the descending one, and both meet at
//! the current input. So the input that produces a desired output y* is found by a bracketed
//! search on this monotone map:
//!
//!     bracket [v_now, v_max] if y* > y_now, else [v_min, v_now];  y(lo) < y* < y(hi)
//!     shrink it by Chandrupatla's method (inverse quadratic interpolation where safe, else
//!     bisection; first trial: the secant root), with a bisection forced whenever three steps have
//!     not halved the bracket, until hi - lo <= tolerance, a trial hits y* (within
//!     output_tolerance) or no double is left between the ends; then apply the end whose output
//!     is nearer y*.
//!
//! The bracket halves at least every four steps, so a sample takes at most
//! 4 ceil(log2((v_max - v_min) / tolerance)) + 4 trials (164 with the default tolerance, never
//! more than 600); typically 5 - 20 (more where the output is nearly flat, as in the tails of a
//! Gaussian density, fewer for a smooth steep branch).
//!
//! Every trial evaluates preview() on the unchanged state (no copy, no allocation); only the
//! chosen input is applied with step(), so the state stays the forward model's state and the
//! inverse can be started from, and handed back to, any model state. The search always
//! terminates. A target below y(v_min) or above y(v_max) is answered with v_min or v_max (which is
//! applied) and the status below_range or above_range - never an exception.
//!
//! Accuracy: for a continuous density |y(u) - y*| <= (dy/du) * tolerance; for the relay grid the
//! output moves in steps, so the result is the input whose output is the reachable value nearest
//! y* (status ok). Where mu = 0 over an input interval, y is flat and any input in it is an answer:
//! the search returns one of them, so inverse(model(v)) need not give back v, but
//! model(inverse(y)) gives back y.
//! Sources: preisach.md sec. 8 (bisection on the monotone map u -> y given the memory); Iyer, Tan
//! & Krishnaprasad (2005), IEEE TAC 50(6), for the closest-match idea; T. R. Chandrupatla (1997),
//! "A new hybrid quadratic/bisection algorithm for finding the zero of a nonlinear function
//! without using derivatives", Adv. Eng. Software 28(3):145.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/core/inverse_status.hpp"
#include "hyst/models/preisach.hpp"

namespace hyst {

struct InversePreisachOptions {
  //! Admissible input range [v_min, v_max] [input units]; not set = the model's [lower, upper]
  //! (inputs beyond it only saturate the model). Finite, v_min < v_max.
  std::optional<double> input_min = std::nullopt;
  std::optional<double> input_max = std::nullopt;
  //! The search stops when the bracket is at most this wide [input units]; not set =
  //! 1e-12 (v_max - v_min). Must be > 0.
  std::optional<double> input_tolerance = std::nullopt;
  //! It also stops as soon as a trial output is within this distance of the target [output
  //! units]; 0 (default) = only the bracket width counts. Must be >= 0.
  double output_tolerance = 0.0;
};

template <EverettFunction Everett>
class BasicInversePreisach {
 public:
  using Model = BasicPreisach<Everett>;
  using State = PreisachState;  //!< the forward model's state
  using Options = InversePreisachOptions;

  //! Throws hyst::Error for invalid options ("inverse Preisach input_min = 2 must be <
  //! input_max = 1").
  explicit BasicInversePreisach(Model model, const Options& options = {})
      : model_(std::move(model)),
        input_min_(options.input_min.value_or(model_.lower())),
        input_max_(options.input_max.value_or(model_.upper())),
        output_tolerance_(options.output_tolerance) {
    if (!std::isfinite(input_min_) || !std::isfinite(input_max_) || !(input_min_ < input_max_)) {
      throw Error(fmt::format("inverse Preisach input_min = {} must be < input_max = {}, both "
                              "finite",
                              input_min_, input_max_),
                  "input_min");
    }
    tolerance_ = options.input_tolerance.value_or(1e-12 * (input_max_ - input_min_));
    if (!std::isfinite(tolerance_) || !(tolerance_ > 0.0)) {
      throw Error(
          fmt::format("inverse Preisach input_tolerance = {} must be > 0 and finite", tolerance_),
          "input_tolerance");
    }
    if (!std::isfinite(output_tolerance_) || output_tolerance_ < 0.0) {
      throw Error(fmt::format("inverse Preisach output_tolerance = {} must be >= 0 and finite",
                              output_tolerance_),
                  "output_tolerance");
    }
    const double halvings = std::ceil(std::log2((input_max_ - input_min_) / tolerance_));
    max_iterations_ = static_cast<std::size_t>(std::clamp(4.0 * halvings + 4.0, 4.0, 600.0));
  }

  const Model& forward() const { return model_; }
  double input_min() const { return input_min_; }
  double input_max() const { return input_max_; }
  double input_tolerance() const { return tolerance_; }
  //! The most bisection steps one sample can take.
  std::size_t max_iterations() const { return max_iterations_; }

  //! The forward model's initial state.
  State initial_state() const { return model_.initial_state(); }

  //! The input that makes the model produce `target` from `state`, which is advanced with it.
  //! Never throws, never allocates. Precondition: `target` is finite.
  InverseSample solve(State& state, double target) const noexcept {
    const double now = std::clamp(state.input, input_min_, input_max_);
    const double y_now = model_.preview(state, now);
    if (y_now == target) return apply(state, now, InverseStatus::ok);
    double lo = input_min_;
    double hi = input_max_;
    double y_lo = 0.0;
    double y_hi = 0.0;
    if (target > y_now) {
      lo = now;
      y_lo = y_now;
      y_hi = model_.preview(state, hi);
      if (y_hi < target) return apply(state, hi, InverseStatus::above_range);
    } else {
      hi = now;
      y_hi = y_now;
      y_lo = model_.preview(state, lo);
      if (y_lo > target) return apply(state, lo, InverseStatus::below_range);
    }
    // Chandrupatla's hybrid of inverse quadratic interpolation and bisection. a is the newest
    // end of the bracket, b the other end (f = y - target has opposite signs there), c the end
    // that was dropped last. The first trial is the secant root of the bracket; a bisection is
    // forced whenever three steps have not halved the bracket, so it halves at least every four
    // steps and the loop ends within max_iterations().
    double a = hi;
    double fa = y_hi - target;  // > 0
    double b = lo;
    double fb = y_lo - target;  // < 0
    double c = a;
    double fc = fa;
    double t = fa / (fa - fb);
    double checkpoint = hi - lo;
    int since_checkpoint = 0;
    for (std::size_t k = 0; k < max_iterations_; ++k) {
      if (since_checkpoint >= 3) t = 0.5;
      const double u = a + t * (b - a);
      if (!(u > std::min(a, b) && u < std::max(a, b))) break;  // no double left between them
      const double fu = model_.preview(state, u) - target;
      if (fu == 0.0 || std::abs(fu) <= output_tolerance_) {
        return apply(state, u, InverseStatus::ok);
      }
      if ((fu < 0.0) == (fa < 0.0)) {
        c = a;
        fc = fa;
      } else {
        c = b;
        fc = fb;
        b = a;
        fb = fa;
      }
      a = u;
      fa = fu;
      const double width = std::abs(b - a);
      if (width <= tolerance_) break;
      if (width <= 0.5 * checkpoint) {
        checkpoint = width;
        since_checkpoint = 0;
      } else {
        ++since_checkpoint;
      }
      // Inverse quadratic interpolation through a, b, c where it is safe (Chandrupatla 1997),
      // kept at least half a tolerance away from the ends.
      t = 0.5;
      const double xi = (a - b) / (c - b);
      const double phi = (fa - fb) / (fc - fb);
      if (phi * phi < xi && (1 - phi) * (1 - phi) < 1 - xi) {
        t = fa / (fb - fa) * fc / (fb - fc) + (c - a) / (b - a) * fa / (fc - fa) * fb / (fc - fb);
      }
      const double margin = 0.5 * tolerance_ / width;
      t = std::clamp(t, margin, 1 - margin);
    }
    lo = std::min(a, b);
    hi = std::max(a, b);
    y_lo = target + (a < b ? fa : fb);
    y_hi = target + (a < b ? fb : fa);
    return apply(state, target - y_lo <= y_hi - target ? lo : hi, InverseStatus::ok);
  }

  //! solve() without the status, so the inverse also runs wherever a model does.
  double step(State& state, double target) const noexcept { return solve(state, target).input; }

 private:
  InverseSample apply(State& state, double input, InverseStatus status) const noexcept {
    model_.step(state, input);
    return {input, status};
  }

  Model model_;
  double input_min_;
  double input_max_;
  double output_tolerance_;
  double tolerance_ = 0.0;
  std::size_t max_iterations_ = 0;
};

using InversePreisach = BasicInversePreisach<RelayGridEverett>;
using InverseGaussianPreisach = BasicInversePreisach<GaussianEverett>;
using InverseLorentzianPreisach = BasicInversePreisach<LorentzianEverett>;
using InverseTabulatedPreisach = BasicInversePreisach<TabulatedEverett>;

extern template class BasicInversePreisach<RelayGridEverett>;
extern template class BasicInversePreisach<GaussianEverett>;
extern template class BasicInversePreisach<LorentzianEverett>;
extern template class BasicInversePreisach<TabulatedEverett>;

}  // namespace hyst
