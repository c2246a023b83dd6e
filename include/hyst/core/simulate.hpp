#pragma once
//! \file
//! Batch simulation of any hyst model, and a stateful convenience wrapper.

#include <span>
#include <utility>
#include <vector>

#include "hyst/core/checks.hpp"
#include "hyst/core/model_concept.hpp"

namespace hyst {

//! Runs `model` over `input` starting from `state` (which is advanced), writing one output per
//! input sample. Throws hyst::Error when the lengths differ or an input sample is not finite;
//! the loop itself neither allocates nor calls virtual functions.
template <HysteresisModel M>
void simulate(const M& model, typename M::State& state, std::span<const double> input,
              std::span<double> output) {
  require_same_size(input.size(), "input", output.size(), "output");
  require_finite(input, "input");
  for (std::size_t k = 0; k < input.size(); ++k)
    output[k] = model.step(state, input[k]);
}

//! Same as above, returning a newly allocated output vector.
template <HysteresisModel M>
std::vector<double> simulate(const M& model, typename M::State& state,
                             std::span<const double> input) {
  std::vector<double> output(input.size());
  simulate(model, state, input, std::span<double>(output));
  return output;
}

//! A model together with its running state: the convenient form when one simulation is all
//! that is needed.
//!
//! \code
//!   hyst::Stateful pi{hyst::PrandtlIshlinskii({.thresholds = {0, 0.5}, .weights = {1, 0.5}})};
//!   double y = pi.step(0.3);
//! \endcode
template <HysteresisModel M>
class Stateful {
 public:
  using Model = M;
  using State = typename M::State;

  explicit Stateful(M model) : model_(std::move(model)), state_(model_.initial_state()) {}
  Stateful(M model, State state) : model_(std::move(model)), state_(std::move(state)) {}

  //! Advances one sample. The caller guarantees a finite input (see simulate() for a checked
  //! batch form).
  double step(double input) { return model_.step(state_, input); }

  void simulate(std::span<const double> input, std::span<double> output) {
    hyst::simulate(model_, state_, input, output);
  }
  std::vector<double> simulate(std::span<const double> input) {
    return hyst::simulate(model_, state_, input);
  }

  //! Back to the model's initial state.
  void reset() { state_ = model_.initial_state(); }

  const M& model() const { return model_; }
  const State& state() const { return state_; }
  void set_state(State state) { state_ = std::move(state); }

 private:
  M model_;
  State state_;
};

}  // namespace hyst
