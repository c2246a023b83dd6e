#include "hyst/models/preisach_state.hpp"

#include <cmath>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
PreisachInitialState preisach_initial_state_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<PreisachInitialState>, "Preisach initial state",
                             "initial_state");
}

std::vector<double> preisach_midpoint_staircase(double lower, double upper, std::size_t pairs) {
  if (pairs == 0 || pairs > PreisachState::max_pairs) {
    throw Error(fmt::format("Preisach demagnetising staircase: pairs = {} must be in 1 .. {}",
                            pairs, PreisachState::max_pairs));
  }
  if (!(std::isfinite(lower) && std::isfinite(upper) && lower < upper)) {
    throw Error(
        fmt::format("Preisach demagnetising staircase: lower = {} and upper = {} must be "
                    "finite with lower < upper",
                    lower, upper));
  }
  const double h = (upper - lower) / static_cast<double>(2 * pairs);
  std::vector<double> input;
  input.reserve(2 * pairs);
  for (std::size_t k = 1; k <= pairs; ++k) {
    const auto kd = static_cast<double>(k);
    input.push_back(upper - (kd - 0.5) * h);
    input.push_back(lower + kd * h);
  }
  return input;
}

}  // namespace hyst
