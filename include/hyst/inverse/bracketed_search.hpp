#pragma once
//! \file
//! The bracketed search shared by the numerical inverses (inverse_preisach.hpp,
//! numerical_inverse.hpp): the input u in [v_min, v_max] at which a non-decreasing map y(u)
//! (the model's output one step ahead from a fixed state) reaches a target y*.
//!
//!     bracket [v_now, v_max] if y* > y(v_now), else [v_min, v_now];  y(lo) < y* < y(hi)
//!     shrink it by Chandrupatla's method (inverse quadratic interpolation where safe, else
//!     bisection; first trial: the secant root), with a bisection forced whenever three steps
//!     have not halved the bracket, until hi - lo <= tolerance, a trial hits y* (within
//!     output_tolerance) or no double is left between the ends; then answer the end whose
//!     output is nearer y*.
//!
//! The bracket halves at least every four steps, so the search ends within
//! bracketed_search_iterations() trials. A target below y(v_min) or above y(v_max) is answered
//! with v_min or v_max and the status below_range or above_range. Never throws, never
//! allocates (the map is called, never stored).
//! Source: T. R. Chandrupatla (1997), "A new hybrid quadratic/bisection algorithm for finding
//! the zero of a nonlinear function without using derivatives", Adv. Eng. Software 28(3):145.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/core/inverse_status.hpp"

namespace hyst {

//! The validated settings of a bracketed search.
struct BracketedSearch {
  double input_min = 0.0;         //!< v_min
  double input_max = 1.0;         //!< v_max > v_min
  double tolerance = 1e-12;       //!< bracket width that ends the search [input units], > 0
  double output_tolerance = 0.0;  //!< |y - y*| that ends it [output units], >= 0
  std::size_t max_iterations = 4;
};

//! The settings for [input_min, input_max], the tolerance (not set: 1e-12 of the range) and the
//! output tolerance; throws hyst::Error naming the field, its messages start with `who`
//! ("inverse Preisach input_min = 2 must be < input_max = 1, both finite").
inline BracketedSearch make_bracketed_search(std::string_view who, double input_min,
                                             double input_max, std::optional<double> tolerance,
                                             double output_tolerance) {
  if (!std::isfinite(input_min) || !std::isfinite(input_max) || !(input_min < input_max)) {
    throw Error(fmt::format("{} input_min = {} must be < input_max = {}, both finite", who,
                            input_min, input_max),
                "input_min");
  }
  BracketedSearch search;
  search.input_min = input_min;
  search.input_max = input_max;
  search.tolerance = tolerance.value_or(1e-12 * (input_max - input_min));
  if (!std::isfinite(search.tolerance) || !(search.tolerance > 0.0)) {
    throw Error(
        fmt::format("{} input_tolerance = {} must be > 0 and finite", who, search.tolerance),
        "input_tolerance");
  }
  if (!std::isfinite(output_tolerance) || output_tolerance < 0.0) {
    throw Error(
        fmt::format("{} output_tolerance = {} must be >= 0 and finite", who, output_tolerance),
        "output_tolerance");
  }
  search.output_tolerance = output_tolerance;
  const double halvings = std::ceil(std::log2((input_max - input_min) / search.tolerance));
  search.max_iterations = static_cast<std::size_t>(std::clamp(4.0 * halvings + 4.0, 4.0, 600.0));
  return search;
}

//! What the bracketed inverses share: the forward model, the search settings and their
//! accessors. The inverse's state is the forward model's state.
template <class M>
class BracketedInverseBase {
 public:
  using Model = M;
  using State = typename M::State;

  const Model& forward() const { return model_; }
  double input_min() const { return search_.input_min; }
  double input_max() const { return search_.input_max; }
  double input_tolerance() const { return search_.tolerance; }
  //! The most search steps one sample can take.
  std::size_t max_iterations() const { return search_.max_iterations; }

  //! The forward model's initial state.
  State initial_state() const { return model_.initial_state(); }

 protected:
  BracketedInverseBase(Model model, const BracketedSearch& search)
      : model_(std::move(model)), search_(search) {}

  Model model_;
  BracketedSearch search_;
};

//! The input in [v_min, v_max] where the non-decreasing map `y` reaches `target`, starting from
//! the bracket split at `now` (clamped into the range; the output there is y(now)). A NaN target
//! has no input: `now` is held (status not_invertible); +-inf is out of reach at the limit.
template <class Map>
InverseSample bracketed_search(const BracketedSearch& search, Map&& y, double now,
                               double target) noexcept {
  now = std::clamp(now, search.input_min, search.input_max);
  if (std::isnan(target)) return {now, InverseStatus::not_invertible};
  const double y_now = y(now);
  if (y_now == target) return {now, InverseStatus::ok};
  double lo = search.input_min;
  double hi = search.input_max;
  double y_lo = 0.0;
  double y_hi = 0.0;
  if (target > y_now) {
    lo = now;
    y_lo = y_now;
    y_hi = y(hi);
    if (y_hi < target) return {hi, InverseStatus::above_range};
  } else {
    hi = now;
    y_hi = y_now;
    y_lo = y(lo);
    if (y_lo > target) return {lo, InverseStatus::below_range};
  }
  // Chandrupatla's hybrid of inverse quadratic interpolation and bisection. a is the newest
  // end of the bracket, b the other end (f = y - target has opposite signs there), c the end
  // that was dropped last. The first trial is the secant root of the bracket; a bisection is
  // forced whenever three steps have not halved the bracket, so it halves at least every four
  // steps and the loop ends within max_iterations.
  double a = hi;
  double fa = y_hi - target;  // >= 0
  double b = lo;
  double fb = y_lo - target;  // <= 0
  double c = a;
  double fc = fa;
  double t = fa / (fa - fb);
  double checkpoint = hi - lo;
  int since_checkpoint = 0;
  for (std::size_t k = 0; k < search.max_iterations; ++k) {
    if (since_checkpoint >= 3) t = 0.5;
    const double u = a + t * (b - a);
    if (!(u > std::min(a, b) && u < std::max(a, b))) break;  // no double left between them
    const double fu = y(u) - target;
    if (fu == 0.0 || std::abs(fu) <= search.output_tolerance) return {u, InverseStatus::ok};
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
    if (width <= search.tolerance) break;
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
    const double margin = 0.5 * search.tolerance / width;
    t = std::clamp(t, margin, 1 - margin);
  }
  lo = std::min(a, b);
  hi = std::max(a, b);
  y_lo = target + (a < b ? fa : fb);
  y_hi = target + (a < b ? fb : fa);
  return {target - y_lo <= y_hi - target ? lo : hi, InverseStatus::ok};
}

}  // namespace hyst
