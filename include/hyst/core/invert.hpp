#pragma once
//! \file
//! Batch inversion with any hyst inverse model (a type with `State`, `initial_state()` and
//! `solve(State&, double target) -> InverseSample`).

#include <span>

#include "hyst/core/checks.hpp"
#include "hyst/core/inverse_status.hpp"

namespace hyst {

template <class Inverse>
concept InverseModel = requires(const Inverse& inverse, typename Inverse::State& state,
                                double target) {
  { inverse.solve(state, target) } -> std::same_as<InverseSample>;
};

//! Computes the input for every desired output in `targets`, starting from `state` (advanced).
//! Throws hyst::Error for mismatched lengths or non-finite targets; saturation is reported in the
//! returned InverseReport, not thrown.
template <InverseModel Inverse>
InverseReport invert(const Inverse& inverse, typename Inverse::State& state,
                     std::span<const double> targets, std::span<double> inputs) {
  require_same_size(targets.size(), "targets", inputs.size(), "inputs");
  require_finite(targets, "targets");
  InverseReport report;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const InverseSample sample = inverse.solve(state, targets[k]);
    inputs[k] = sample.input;
    report.record(k, sample.status);
  }
  return report;
}

}  // namespace hyst
