#include "hyst/models/krasnoselskii_pokrovskii.hpp"

#include <cmath>
#include <numeric>
#include <string>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {
namespace {

void validate(const KrasnoselskiiPokrovskii::Params& p) {
  if (p.levels == 0) throw Error("KP levels N = 0 must be >= 1", "levels");
  // Before N(N+1)/2 is computed: beyond 2^32 levels it would overflow (and could match a short
  // weight list). 4096 levels are 8 390 656 kernels, as many as the Preisach model allows.
  if (p.levels > 4096) {
    throw Error(
        fmt::format("KP levels N = {} must be in 1 .. 4096 (the model has N(N+1)/2 kernels)",
                    p.levels),
        "levels");
  }
  if (!std::isfinite(p.lower)) {
    throw Error(fmt::format("KP lower = {} is not finite", p.lower), "lower");
  }
  if (!std::isfinite(p.upper) || !(p.upper > p.lower)) {
    throw Error(fmt::format("KP upper = {} must be finite and > lower = {}", p.upper, p.lower),
                "upper");
  }
  const std::size_t count = p.levels * (p.levels + 1) / 2;
  if (p.weights.size() != count) {
    throw Error(fmt::format("KP has {} weights but N = {} levels need N(N+1)/2 = {}",
                            p.weights.size(), p.levels, count),
                "weights");
  }
  for (std::size_t r = 0; r < count; ++r) {
    if (!std::isfinite(p.weights[r]) || p.weights[r] < 0.0) {
      throw Error(fmt::format("KP weight mu[{}] = {} must be finite and >= 0", r, p.weights[r]),
                  fmt::format("weights[{}]", r));
    }
  }
  if (!std::isfinite(p.ramp_cells) || !(p.ramp_cells > 0.0)) {
    throw Error(fmt::format("KP ramp_cells = {} must be finite and > 0", p.ramp_cells),
                "ramp_cells");
  }
  if (!std::isfinite(p.offset)) {
    throw Error(fmt::format("KP offset = {} is not finite", p.offset), "offset");
  }
}

}  // namespace

KrasnoselskiiPokrovskii::KrasnoselskiiPokrovskii(Params params) : params_(std::move(params)) {
  validate(params_);
  const double cell = (params_.upper - params_.lower) / static_cast<double>(params_.levels);
  thresholds_.resize(params_.levels);
  for (std::size_t k = 0; k < params_.levels; ++k)
    thresholds_[k] = params_.lower + cell * static_cast<double>(k);
  ramp_ = params_.ramp_cells * cell;
  two_over_ramp_ = 2.0 / ramp_;
}

double KrasnoselskiiPokrovskii::total_weight() const {
  return std::accumulate(params_.weights.begin(), params_.weights.end(), 0.0);
}

KrasnoselskiiPokrovskii::State KrasnoselskiiPokrovskii::initial_state() const {
  return State{std::vector<double>(kernel_count(), -1.0), std::vector<double>(params_.levels)};
}

KrasnoselskiiPokrovskii::State KrasnoselskiiPokrovskii::make_state(
    std::vector<double> kernels) const {
  if (kernels.size() != kernel_count()) {
    throw Error(
        fmt::format("KP state has {} kernels but the grid has {}", kernels.size(), kernel_count()));
  }
  for (std::size_t r = 0; r < kernels.size(); ++r) {
    if (!(kernels[r] >= -1.0 && kernels[r] <= 1.0)) {
      throw Error(fmt::format("KP state kernel[{}] = {} must be in [-1, 1]", r, kernels[r]));
    }
  }
  return State{std::move(kernels), std::vector<double>(params_.levels)};
}

double KrasnoselskiiPokrovskii::output(const State& state) const {
  double sum = 0.0;
  for (std::size_t r = 0; r < kernel_count(); ++r)
    sum += params_.weights[r] * state.kernels[r];
  return params_.offset + sum;
}

}  // namespace hyst
