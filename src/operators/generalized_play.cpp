#include "hyst/operators/generalized_play.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

template <Envelope E>
GeneralizedPlay<E>::GeneralizedPlay(Params params) : params_(std::move(params)) {
  constexpr std::string_view model = "generalized play";
  E::validate(params_.ascending, {model, "ascending", 'a'});
  E::validate(params_.descending, {model, "descending", 'b'});
  if (!std::isfinite(params_.threshold)) {
    throw Error(fmt::format("generalized play threshold r = {} is not finite", params_.threshold),
                "threshold");
  }
  if (params_.threshold < 0.0) {
    throw Error(fmt::format("generalized play threshold r = {} must be >= 0", params_.threshold),
                "threshold");
  }
  check_envelope_ordering<E>(params_.ascending.data(), params_.descending.data(), params_.input_min,
                             params_.input_max, model);
}

template <Envelope E>
typename GeneralizedPlay<E>::State GeneralizedPlay<E>::make_state(double output) const {
  require_finite(output, "generalized play state z");
  return State{output};
}

template class GeneralizedPlay<LinearEnvelope>;
template class GeneralizedPlay<TanhEnvelope>;
template class GeneralizedPlay<ArctanEnvelope>;

}  // namespace hyst
