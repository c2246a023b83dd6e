#include "hyst/models/prandtl_ishlinskii.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {
namespace {

void validate(const PrandtlIshlinskii::Params& params) {
  const auto& r = params.thresholds;
  const auto& p = params.weights;
  if (r.empty()) throw Error("PI thresholds r is empty", "thresholds");
  require_same_length(r.size(), p.size(), "PI", {"thresholds", "r", "thresholds"},
                      {"weights", "p", "weights"});
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!std::isfinite(r[j])) {
      throw Error(fmt::format("PI threshold r[{}] = {} is not finite", j, r[j]),
                  fmt::format("thresholds[{}]", j));
    }
    if (!std::isfinite(p[j])) {
      throw Error(fmt::format("PI weight p[{}] = {} is not finite", j, p[j]),
                  fmt::format("weights[{}]", j));
    }
  }
  require_increasing_from_zero(r, "PI threshold", "r", "thresholds",
                               "the r = 0 play carries the linear term");
  if (!std::isfinite(params.offset)) {
    throw Error(fmt::format("PI offset = {} is not finite", params.offset), "offset");
  }
}

}  // namespace

PrandtlIshlinskii::PrandtlIshlinskii(Params params) : params_(std::move(params)) {
  validate(params_);
}

PrandtlIshlinskii::State PrandtlIshlinskii::initial_state() const {
  return State{std::vector<double>(size(), 0.0)};
}

PrandtlIshlinskii::State PrandtlIshlinskii::state_at_rest(double input) const {
  require_finite(input, "PI rest input v0");
  return State{std::vector<double>(size(), input)};
}

PrandtlIshlinskii::State PrandtlIshlinskii::make_state(std::vector<double> play) const {
  require_reachable_plays(play, params_.thresholds, "PI", "w");
  return State{std::move(play)};
}

bool PrandtlIshlinskii::is_invertible() const {
  const auto& p = params_.weights;
  if (!(p[0] > 0.0)) return false;
  double partial_sum = 0.0;
  for (double pj : p) {
    partial_sum += pj;
    if (!(partial_sum > 0.0)) return false;
  }
  return true;
}

double PrandtlIshlinskii::output(const State& state) const {
  require_same_size(state.play.size(), "PI state w", size(), "PI thresholds r");
  return params_.offset + weighted_sum(state.play.data());
}

std::vector<double> uniform_thresholds(std::size_t count, double spacing) {
  if (count == 0) throw Error("uniform thresholds: count = 0 must be >= 1");
  require_finite(spacing, "uniform threshold spacing");
  if (!(spacing > 0.0)) {
    throw Error(fmt::format("uniform threshold spacing = {} must be > 0", spacing));
  }
  std::vector<double> thresholds(count);
  for (std::size_t j = 0; j < count; ++j)
    thresholds[j] = spacing * static_cast<double>(j);
  return thresholds;
}

}  // namespace hyst
