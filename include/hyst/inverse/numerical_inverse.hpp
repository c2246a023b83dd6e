#pragma once
//! \file
//! Numerical inverse of any monotone hysteresis model, one sample at a time: the bracketed
//! search (bracketed_search.hpp) on the one-step map u -> y(u), the model's output one step
//! ahead from the current, unchanged state.
//!
//! The map is evaluated by the model's `preview(const State&, double) const` where it has one
//! (no copy), otherwise on a copy of the state; a copy is only allowed when it cannot allocate
//! (a trivially copyable State: IkutaSma), so a model with a vector state needs a preview
//! (KrasnoselskiiPokrovskii, Preisach). Only the chosen input is applied with step(), so the
//! state stays the forward model's state. The search starts from the last input where the state
//! has one (`state.input`), else from the middle of the range.
//!
//! The model must be monotone in this sense: from every state, y(u) is non-decreasing over
//! [v_min, v_max], or non-increasing (IkutaSma with y_M > y_A). Each sample compares y(v_min)
//! and y(v_max) and searches -y for a non-increasing map, so both work; a target beyond the
//! outputs reachable from the state gives the input of the nearest reachable output, v_min or
//! v_max (applied), with the status below_range or above_range (the input was limited to v_min
//! or v_max, inverse_status.hpp) - never an exception.
//! Accuracy: where y is continuous, |y(u) - y*| <= |dy/du| input_tolerance; where y is flat any
//! input of the flat part is an answer (model(inverse(y)) gives back y, inverse(model(v)) need
//! not give back v). Cost per sample: at most max_iterations() + 3 evaluations of the map.

#include <concepts>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "hyst/inverse/bracketed_search.hpp"

namespace hyst {

struct NumericalInverseOptions {
  //! Admissible input range [v_min, v_max] [input units], finite, v_min < v_max (required: the
  //! defaults are NaN, which the constructor rejects).
  double input_min = std::numeric_limits<double>::quiet_NaN();
  double input_max = std::numeric_limits<double>::quiet_NaN();
  //! Bracket width that ends the search [input units]; not set = 1e-12 (v_max - v_min); > 0.
  std::optional<double> input_tolerance = std::nullopt;
  //! A trial output this close to the target ends it [output units]; 0 = off; >= 0.
  double output_tolerance = 0.0;
};

//! A model whose one-step map can be evaluated without changing its state.
template <class Model>
concept Previewable = requires(const Model& model, const typename Model::State& state) {
  { model.preview(state, 0.0) } -> std::convertible_to<double>;
};

template <class M>
class NumericalInverse : public BracketedInverseBase<M> {
  static_assert(Previewable<M> || std::is_trivially_copyable_v<typename M::State>,
                "NumericalInverse needs the model's preview(const State&, double) const, or a "
                "State that copies without allocating (trivially copyable)");

  using Base = BracketedInverseBase<M>;
  using Base::model_;
  using Base::search_;

 public:
  using Model = M;
  using State = typename M::State;  //!< the forward model's state
  using Options = NumericalInverseOptions;

  //! Throws hyst::Error for invalid options ("numerical inverse input_min = 2 must be <
  //! input_max = 1, both finite").
  NumericalInverse(Model model, const Options& options)
      : Base(std::move(model),
             make_bracketed_search("numerical inverse", options.input_min, options.input_max,
                                   options.input_tolerance, options.output_tolerance)) {}

  //! The input that makes the model produce `target` from `state`, which is advanced with it.
  //! Never throws, never allocates. Precondition: `target` is finite.
  InverseSample solve(State& state, double target) const noexcept {
    const double y_min = output_after(state, search_.input_min);
    const double y_max = output_after(state, search_.input_max);
    const double sign = y_max < y_min ? -1.0 : 1.0;
    const auto map = [&](double input) { return sign * output_after(state, input); };
    const InverseSample sample = bracketed_search(search_, map, start_of(state), sign * target);
    model_.step(state, sample.input);
    return sample;
  }

  //! solve() without the status, so the inverse also runs wherever a model does.
  double step(State& state, double target) const noexcept { return solve(state, target).input; }

 private:
  double output_after(const State& state, double input) const noexcept {
    if constexpr (Previewable<Model>) {
      return model_.preview(state, input);
    } else {
      State copy = state;
      return model_.step(copy, input);
    }
  }
  double start_of(const State& state) const noexcept {
    if constexpr (requires { state.input; }) {
      return state.input;
    } else {
      return 0.5 * (search_.input_min + search_.input_max);
    }
  }
};

}  // namespace hyst
