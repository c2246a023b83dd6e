#include "hyst/models/preisach_relay_grid.hpp"

#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

PreisachRelayGrid::PreisachRelayGrid(Params params) : params_(std::move(params)) {
  const Preisach validated(params_);  // the same rules and messages as the fast form
  const auto& grid = params_.everett;
  thresholds_ = preisach_thresholds(grid.levels, grid.lower, grid.upper, grid.layout);
}

PreisachRelayGrid::State PreisachRelayGrid::make_state(PreisachInitialState kind) const {
  const std::size_t n = params_.everett.levels;
  State state{std::vector<std::int8_t>(relay_count(), -1)};
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j <= i; ++j) {
      const bool up = kind == PreisachInitialState::positive_saturation ||
                      (kind == PreisachInitialState::demagnetised && i + j + 2 <= n);
      state.relays[preisach_relay_index(i, j)] = up ? 1 : -1;
    }
  }
  return state;
}

PreisachRelayGrid::State PreisachRelayGrid::make_state(std::vector<std::int8_t> relays) const {
  if (relays.size() != relay_count()) {
    throw Error(fmt::format("Preisach relay state has {} relays but the grid has {}", relays.size(),
                            relay_count()));
  }
  for (std::size_t r = 0; r < relays.size(); ++r) {
    if (relays[r] != 1 && relays[r] != -1) {
      throw Error(fmt::format("Preisach relay state s[{}] = {} must be -1 or +1", r,
                              static_cast<int>(relays[r])));
    }
  }
  return State{std::move(relays)};
}

double PreisachRelayGrid::output(const State& state) const {
  double sum = 0.0;
  const auto& mu = params_.everett.weights;
  for (std::size_t r = 0; r < mu.size(); ++r)
    sum += mu[r] * static_cast<double>(state.relays[r]);
  return params_.offset + sum;
}

}  // namespace hyst
