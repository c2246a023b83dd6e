#include "hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp"

#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {
namespace {

InversePrandtlIshlinskii instantaneous_inverse_of(
    const PrandtlIshlinskiiCreep& model, const InversePrandtlIshlinskii::Options& options) {
  try {
    return InversePrandtlIshlinskii(
        PrandtlIshlinskii({model.params().thresholds, model.instantaneous_weights(), 0.0}),
        options);
  } catch (const Error& error) {
    throw Error(fmt::format("inverse PI with creep (instantaneous weights p_j + sum_i c_ij "
                            "(1 - a_i)): {}",
                            error.what()),
                error.field());
  }
}

}  // namespace

InversePrandtlIshlinskiiCreep::InversePrandtlIshlinskiiCreep(const PrandtlIshlinskiiCreep& model,
                                                             const Options& options)
    : forward_(model), instantaneous_(instantaneous_inverse_of(model, options)) {}

InversePrandtlIshlinskiiCreep::State InversePrandtlIshlinskiiCreep::state_consistent_with(
    const PrandtlIshlinskiiCreep::State& model_state) const {
  State state{forward_.make_state(model_state.play, model_state.creep), {}};
  state.plays = instantaneous_.state_consistent_with(PrandtlIshlinskii::State{model_state.play});
  return state;
}

void InversePrandtlIshlinskiiCreep::resynchronise(State& state) const noexcept {
  const auto& weights = instantaneous_.forward().params().weights;
  const auto& w = state.model.play;
  auto& wh = state.plays.play;
  // Backwards: the tail sum_{i>j} ph_i w_i and the partial sum S_j = S_n - sum_{i>j} ph_i.
  double total = 0.0;
  for (double p : weights)
    total += p;
  double tail = 0.0;
  double tail_weight = 0.0;
  for (std::size_t j = w.size(); j-- > 0;) {
    wh[j] = (total - tail_weight) * w[j] + tail;
    tail += weights[j] * w[j];
    tail_weight += weights[j];
  }
}

}  // namespace hyst
