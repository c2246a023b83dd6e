#pragma once
// The numerical monotone inverse (inverse/monotone_inverse.hpp) of a scalar differential model as
// a DynamicInverse: shared by the entries of Bouc-Wen, Duhem, backlash-like and Jiles-Atherton.
// Its state is written as {"input": last input, "model": the model's state}.

#include <algorithm>
#include <cmath>
#include <memory>

#include "hyst/inverse/monotone_inverse.hpp"
#include "model_adapter.hpp"

namespace hyst::detail {

template <class Codec>
std::unique_ptr<DynamicInverse> make_monotone_inverse(const typename Codec::Model& model,
                                                      const typename Codec::Model::State& state,
                                                      const InverseLimits& limits,
                                                      double current_input) {
  using Inverse = MonotoneInverse<typename Codec::Model>;
  typename Inverse::State inverse_state{state, current_input};
  // A limit not given is the search span around the input the inverse starts from (about
  // 1.1e12 max(1, |v|)), so that a run of out-of-reach targets cannot walk the input further
  // sample by sample.
  const double reach = 1.125899906842624e12 * std::max(1.0, std::abs(current_input));
  double input_min = limits.input_min;
  double input_max = limits.input_max;
  if (!std::isfinite(input_min)) {
    input_min =
        std::min(current_input, std::isfinite(input_max) ? input_max : current_input) - reach;
  }
  if (!std::isfinite(input_max)) {
    input_max = std::max(current_input,
                         std::isfinite(limits.input_min) ? limits.input_min : current_input) +
                reach;
  }
  const auto state_to_json = [model](const typename Inverse::State& s) {
    return nlohmann::json{{"input", s.input}, {"model", Codec::state_to_json(model, s.model)}};
  };
  return std::make_unique<InverseAdapter<Inverse, decltype(state_to_json)>>(
      Inverse(model, input_min, input_max), std::move(inverse_state), state_to_json);
}

}  // namespace hyst::detail
