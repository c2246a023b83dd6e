#include "dead_zone_slopes.hpp"

#include <algorithm>
#include <utility>

#include "hyst/operators/dead_zone.hpp"

namespace hyst::detail {

DeadZoneSlopes::DeadZoneSlopes(std::vector<double> thresholds, double min_slope)
    : min_slope_(min_slope) {
  const DeadZoneSuperposition probe({thresholds, std::vector<double>(thresholds.size(), 1.0)});
  thresholds_ = std::move(thresholds);
  zero_ = probe.zero_index();
  above_ = thresholds_.size() - 1 - zero_;
  below_ = zero_;
}

std::vector<double> DeadZoneSlopes::default_thresholds(std::size_t per_side, double below,
                                                       double above) {
  std::vector<double> d;
  for (std::size_t i = per_side; i >= 1; --i)
    d.push_back(-static_cast<double>(i) * below / static_cast<double>(per_side + 1));
  d.push_back(0.0);
  for (std::size_t i = 1; i <= per_side; ++i)
    d.push_back(static_cast<double>(i) * above / static_cast<double>(per_side + 1));
  return d;
}

double DeadZoneSlopes::terms(double x, std::span<double> terms) const {
  const auto zone = [&](std::size_t i) { return DeadZone(thresholds_[i])(x); };
  double known = zone(zero_);
  if (above_ > 0) known -= zone(zero_ + 1);
  if (below_ > 0) known -= zone(zero_ - 1);
  for (std::size_t i = 1; i <= above_; ++i) {
    const double e = zone(zero_ + i) - (i < above_ ? zone(zero_ + i + 1) : 0.0);
    terms[i - 1] = e;
    known += min_slope_ * e;
  }
  for (std::size_t i = 1; i <= below_; ++i) {
    const double f = zone(zero_ - i) - (i < below_ ? zone(zero_ - i - 1) : 0.0);
    terms[above_ + i - 1] = f;
    known += min_slope_ * f;
  }
  return known;
}

double DeadZoneSlopes::slope(double x, std::span<const double> t) const {
  if (x >= 0.0) {
    for (std::size_t i = above_; i >= 1; --i) {
      if (x > thresholds_[zero_ + i]) return min_slope_ + t[i - 1];
    }
    return 1.0;
  }
  for (std::size_t i = below_; i >= 1; --i) {
    if (x < thresholds_[zero_ - i]) return min_slope_ + t[above_ + i - 1];
  }
  return 1.0;
}

DeadZoneSuperposition DeadZoneSlopes::map(std::span<const double> t) const {
  DeadZoneSuperposition::Params map{thresholds_, std::vector<double>(thresholds_.size(), 0.0)};
  map.weights[zero_] = 1.0;
  double previous = 1.0;
  for (std::size_t i = 1; i <= above_; ++i) {
    const double slope = min_slope_ + t[i - 1];
    map.weights[zero_ + i] = slope - previous;
    previous = slope;
  }
  previous = 1.0;
  for (std::size_t i = 1; i <= below_; ++i) {
    const double slope = min_slope_ + t[above_ + i - 1];
    map.weights[zero_ - i] = slope - previous;
    previous = slope;
  }
  return DeadZoneSuperposition(std::move(map));
}

std::vector<double> DeadZoneSlopes::unknowns_of(const DeadZoneSuperposition& map) const {
  const auto& g = map.params().weights;
  std::vector<double> t(unknowns());
  double sum = g[zero_];
  for (std::size_t i = 1; i <= above_; ++i) {
    sum += g[zero_ + i];
    t[i - 1] = std::max(0.0, sum - min_slope_);
  }
  sum = g[zero_];
  for (std::size_t i = 1; i <= below_; ++i) {
    sum += g[zero_ - i];
    t[above_ + i - 1] = std::max(0.0, sum - min_slope_);
  }
  return t;
}

}  // namespace hyst::detail
