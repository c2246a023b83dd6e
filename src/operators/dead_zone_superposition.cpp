#include "hyst/operators/dead_zone_superposition.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

std::size_t validate(const DeadZoneSuperposition::Params& p) {
  const auto& d = p.thresholds;
  const auto& g = p.weights;
  if (d.empty()) throw Error("dead-zone thresholds d are empty", "thresholds");
  require_same_length(d.size(), g.size(), "dead-zone superposition",
                      {"thresholds", "d", "thresholds"}, {"weights", "g", "weights"});
  std::size_t zero = d.size();
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (!std::isfinite(d[i])) {
      throw Error(fmt::format("dead-zone threshold d[{}] = {} is not finite", i, d[i]),
                  fmt::format("thresholds[{}]", i));
    }
    if (!std::isfinite(g[i])) {
      throw Error(fmt::format("dead-zone weight g[{}] = {} is not finite", i, g[i]),
                  fmt::format("weights[{}]", i));
    }
    if (i > 0 && !(d[i] > d[i - 1])) {
      throw Error(fmt::format("dead-zone threshold d[{}] = {} must be > d[{}] = {}", i, d[i], i - 1,
                              d[i - 1]),
                  fmt::format("thresholds[{}]", i));
    }
    if (d[i] == 0.0) zero = i;
  }
  if (zero == d.size()) {
    throw Error("dead-zone thresholds d must contain 0 (the linear part of the map)", "thresholds");
  }
  return zero;
}

}  // namespace

DeadZoneSuperposition::DeadZoneSuperposition(Params params) : params_(std::move(params)) {
  zero_ = validate(params_);
  zones_.reserve(size());
  for (double d : params_.thresholds)
    zones_.emplace_back(d);
}

bool DeadZoneSuperposition::is_invertible() const {
  const auto& g = params_.weights;
  double sum = 0.0;
  for (std::size_t i = zero_; i < size(); ++i) {
    sum += g[i];
    if (!(sum > 0.0)) return false;
  }
  sum = g[zero_];
  for (std::size_t i = zero_; i-- > 0;) {
    sum += g[i];
    if (!(sum > 0.0)) return false;
  }
  return true;
}

DeadZoneSuperposition DeadZoneSuperposition::inverse() const {
  const auto& d = params_.thresholds;
  const auto& g = params_.weights;
  const std::size_t n = size();
  Params inverse{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  const auto check = [&](double sum, std::size_t from, std::size_t to) {
    if (!(sum > 0.0)) {
      throw Error(
          fmt::format("dead-zone partial sum g[{}] + ... + g[{}] = {} must be > 0 for the "
                      "inverse to exist",
                      from, to, sum));
    }
  };
  check(g[zero_], zero_, zero_);
  inverse.weights[zero_] = 1.0 / g[zero_];
  // Outward from d_0: `before` is the slope below (above) d_i, `after` the slope beyond it.
  double before = g[zero_];
  for (std::size_t i = zero_ + 1; i < n; ++i) {
    const double after = before + g[i];
    check(after, zero_, i);
    inverse.weights[i] = -g[i] / (after * before);
    for (std::size_t j = zero_; j <= i; ++j)
      inverse.thresholds[i] += g[j] * (d[i] - d[j]);
    before = after;
  }
  before = g[zero_];
  for (std::size_t i = zero_; i-- > 0;) {
    const double after = before + g[i];
    check(after, i, zero_);
    inverse.weights[i] = -g[i] / (after * before);
    for (std::size_t j = i; j <= zero_; ++j)
      inverse.thresholds[i] += g[j] * (d[i] - d[j]);
    before = after;
  }
  return DeadZoneSuperposition(std::move(inverse));
}

}  // namespace hyst
