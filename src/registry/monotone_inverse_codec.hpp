#pragma once
// The numerical monotone inverse (inverse/monotone_inverse.hpp) of a scalar differential model as
// a DynamicInverse: shared by the entries of Bouc-Wen, Duhem, backlash-like and Jiles-Atherton.
// Its state is written as {"input": last input, "model": the model's state}.

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
  const auto state_to_json = [model](const typename Inverse::State& s) {
    return nlohmann::json{{"input", s.input}, {"model", Codec::state_to_json(model, s.model)}};
  };
  return std::make_unique<InverseAdapter<Inverse, decltype(state_to_json)>>(
      Inverse(model, limits.input_min, limits.input_max), std::move(inverse_state), state_to_json);
}

// The fit request's held-out record is not supported by the single-record fitters of these
// models: a clear error instead of a silently ignored option.
inline void require_no_validation_record(const FitRequest& request, std::string_view model) {
  if (!request.validation_input.empty()) {
    throw Error(fmt::format("the {} fit validates on the last part of the record only "
                            "(--validate-fraction), not on a separate validation record",
                            model),
                "validation_input");
  }
}

}  // namespace hyst::detail
