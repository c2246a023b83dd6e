#include "hyst/inverse/inverse_generalized_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

template <Envelope E>
InverseGeneralizedPrandtlIshlinskii<E>::InverseGeneralizedPrandtlIshlinskii(const Model& model,
                                                                            const Options& options)
    : forward_(model), inverse_pi_(model.classical()), options_(options) {
  if (std::isnan(options.input_min) || std::isnan(options.input_max) ||
      options.input_min > options.input_max) {
    throw Error(fmt::format("inverse GPI input limits v_min = {} and v_max = {} must satisfy "
                            "v_min <= v_max",
                            options.input_min, options.input_max),
                "input_max");
  }
}

template <Envelope E>
EnvelopeRange InverseGeneralizedPrandtlIshlinskii<E>::reachable_envelope_range() const {
  const EnvelopeRange up = E::range(forward_.params().ascending.data());
  const EnvelopeRange down = E::range(forward_.params().descending.data());
  return {std::max(up.lower, down.lower), std::min(up.upper, down.upper)};
}

template <Envelope E>
typename InverseGeneralizedPrandtlIshlinskii<E>::State
InverseGeneralizedPrandtlIshlinskii<E>::initial_state() const {
  return state_consistent_with(forward_.initial_state(), LoopBranch::ascending);
}

template <Envelope E>
typename InverseGeneralizedPrandtlIshlinskii<E>::State
InverseGeneralizedPrandtlIshlinskii<E>::state_consistent_with(
    const typename Model::State& forward_state, LoopBranch branch) const {
  // The GPI plays are classical plays of u (in u-space), so the classical PI rule applies. The
  // last u equals the r = 0 operator's state z_0; it is taken as the inverse PI's output in the
  // new state, which a repeated target reproduces bit for bit (no spurious direction change).
  const auto checked = forward_.make_state(forward_state.play);
  State state;
  state.pi = inverse_pi_.state_consistent_with(PrandtlIshlinskii::State{checked.play});
  state.u = inverse_pi_.inverse_operator().output(state.pi);
  state.branch = branch;
  return state;
}

template <Envelope E>
typename InverseGeneralizedPrandtlIshlinskii<E>::Model::State
InverseGeneralizedPrandtlIshlinskii<E>::forward_state_consistent_with(
    const State& inverse_state) const {
  return typename Model::State{inverse_pi_.forward_state_consistent_with(inverse_state.pi).play};
}

template <Envelope E>
typename InverseGeneralizedPrandtlIshlinskii<E>::State
InverseGeneralizedPrandtlIshlinskii<E>::state_at_rest(double target) const {
  require_finite(target, "inverse GPI rest output y0");
  State state;
  state.pi = PrandtlIshlinskii::State{std::vector<double>(forward_.size(), target)};
  // The u the inverse PI gives for y0 from this state (the next solve(y0) repeats it exactly,
  // so a constant target keeps the direction).
  state.u = inverse_pi_.inverse_operator().output(state.pi);
  state.branch = LoopBranch::ascending;
  return state;
}

template class InverseGeneralizedPrandtlIshlinskii<LinearEnvelope>;
template class InverseGeneralizedPrandtlIshlinskii<TanhEnvelope>;
template class InverseGeneralizedPrandtlIshlinskii<ArctanEnvelope>;

}  // namespace hyst
