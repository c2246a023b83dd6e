#pragma once
//! \file
//! What every hysteresis operator and model of hyst looks like to generic code.
//!
//! A model object holds validated, immutable parameters; everything that changes while it runs
//! lives in a separate, copyable `State`. One model can therefore drive many simulations, and a
//! state can be saved and restored (numerical inversion and model-predictive control need this).

#include <concepts>

namespace hyst {

//! A single-input single-output operator with memory, advanced one sample at a time.
template <class M>
concept HysteresisModel = requires(const M& model, typename M::State& state, double input) {
  typename M::State;
  requires std::copyable<typename M::State>;
  { model.initial_state() } -> std::same_as<typename M::State>;
  { model.step(state, input) } -> std::convertible_to<double>;
};

}  // namespace hyst
