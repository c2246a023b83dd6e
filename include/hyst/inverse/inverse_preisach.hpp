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
//! The search is bracketed_search.hpp, shared with the generic NumericalInverse
//! (numerical_inverse.hpp). The bracket halves at least every four steps, so a sample takes at most
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

#include <cstddef>
#include <optional>

#include "hyst/inverse/bracketed_search.hpp"
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
class BasicInversePreisach : public BracketedInverseBase<BasicPreisach<Everett>> {
  using Base = BracketedInverseBase<BasicPreisach<Everett>>;
  using Base::model_;
  using Base::search_;

 public:
  using Model = BasicPreisach<Everett>;
  using State = PreisachState;  //!< the forward model's state
  using Options = InversePreisachOptions;

  //! Throws hyst::Error for invalid options ("inverse Preisach input_min = 2 must be <
  //! input_max = 1").
  explicit BasicInversePreisach(Model model, const Options& options = {})
      : Base(model,
             make_bracketed_search("inverse Preisach", options.input_min.value_or(model.lower()),
                                   options.input_max.value_or(model.upper()),
                                   options.input_tolerance, options.output_tolerance)) {}

  //! The input that makes the model produce `target` from `state`, which is advanced with it.
  //! Never throws, never allocates. Precondition: `target` is finite.
  InverseSample solve(State& state, double target) const noexcept {
    const auto preview = [&](double input) { return model_.preview(state, input); };
    const InverseSample sample = bracketed_search(search_, preview, state.input, target);
    model_.step(state, sample.input);
    return sample;
  }

  //! solve() without the status, so the inverse also runs wherever a model does.
  double step(State& state, double target) const noexcept { return solve(state, target).input; }
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
