#include "hyst/models/butterfly_strain_creep.hpp"

#include <cmath>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {
namespace {

constexpr std::string_view kModel = "butterfly strain model with creep";

// The creep part as a PI with creep of zero static weights; its errors name this model's fields
// (its "thresholds" are the "creep_thresholds").
PrandtlIshlinskiiCreep creep_of(const ButterflyStrainCreep::Params& p) {
  const auto& r = p.creep_thresholds;
  if (r.empty() || r[0] != 0.0) {
    throw Error(fmt::format("{}: creep_thresholds[0] = {} must be 0 (the play of v itself)", kModel,
                            r.empty() ? std::string("(none)") : fmt::format("{}", r[0])),
                "creep_thresholds[0]");
  }
  for (std::size_t j = 1; j < r.size(); ++j) {
    if (!(std::isfinite(r[j]) && r[j] > r[j - 1])) {
      throw Error(fmt::format("{}: creep_thresholds[{}] = {} must be finite and > "
                              "creep_thresholds[{}] = {}",
                              kModel, j, r[j], j - 1, r[j - 1]),
                  fmt::format("creep_thresholds[{}]", j));
    }
  }
  PrandtlIshlinskiiCreep::Params creep;
  creep.thresholds = p.creep_thresholds;
  creep.weights.assign(p.creep_thresholds.size(), 0.0);
  creep.time_constants = p.time_constants;
  creep.creep_weights = p.creep_weights;
  creep.sample_time = p.sample_time;
  creep.leakage_conductance = p.leakage_conductance;
  creep.leakage_current = p.leakage_current;
  try {
    return PrandtlIshlinskiiCreep(std::move(creep));
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", kModel, error.what()), error.field());
  }
}

ButterflyStrain butterfly_of(const ButterflyStrainCreep::Params& p) {
  try {
    return ButterflyStrain(p.butterfly);
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", kModel, error.what()), error.field());
  }
}

}  // namespace

ButterflyStrainCreep::ButterflyStrainCreep(Params params)
    : params_(std::move(params)), butterfly_(butterfly_of(params_)), creep_(creep_of(params_)) {
  const std::size_t n = creep_.size();
  current_share_.assign(n, 0.0);
  for (std::size_t i = 0; i < creep_.lags(); ++i) {
    for (std::size_t j = 0; j < n; ++j)
      current_share_[j] += params_.creep_weights[i * n + j] * (1.0 - creep_.decay()[i]);
  }
}

ButterflyStrainCreep ButterflyStrainCreep::at_sample_time(double sample_time) const {
  auto params = params_;
  params.sample_time = sample_time;
  return ButterflyStrainCreep(std::move(params));
}

ButterflyStrainCreep::State ButterflyStrainCreep::initial_state() const {
  return {butterfly_.initial_state(), creep_.initial_state()};
}

ButterflyStrainCreep::State ButterflyStrainCreep::periodic_state(
    std::span<const double> period) const {
  return {butterfly_.periodic_state(period), creep_.periodic_state(period)};
}

}  // namespace hyst
