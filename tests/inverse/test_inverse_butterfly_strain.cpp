// Inverse of the butterfly strain model: exact on a unipolar drive below the coercive voltage,
// not_invertible (never a wrong input) across the vertex, and the exact branch test against a
// dense sweep.

#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_butterfly_strain.hpp"

namespace hyst {
namespace {

// Relays spread along the diagonal (reversible part) and concentrated at the coercive voltage
// +-0.6 of the range [-1, 1]; y = 0.2 v + 0.3 P + P^2 (vertex at P* = -0.15).
ButterflyStrain coercive_butterfly() {
  ButterflyStrain::Params p;
  p.polarisation.everett.levels = 20;
  p.polarisation.everett.lower = -1.0;
  p.polarisation.everett.upper = 1.0;
  const auto c = preisach_thresholds(20, -1.0, 1.0, PreisachGridLayout::cell_centred);
  for (std::size_t i = 0; i < 20; ++i) {
    for (std::size_t j = 0; j <= i; ++j) {
      const double half_width = 0.5 * (c[i] - c[j]) - 0.6;
      const double bias = 0.5 * (c[i] + c[j]);
      p.polarisation.everett.weights.push_back(
          (i == j ? 0.02 : 0.0) + std::exp(-(half_width * half_width + bias * bias) / 0.02));
    }
  }
  p.field_coefficient = 0.2;
  p.polarisation_coefficients = {0.3, 1.0};
  return ButterflyStrain(p);
}

TEST(InverseButterflyStrain, InvertsAUnipolarDriveBelowTheCoerciveVoltage) {
  const ButterflyStrain model = coercive_butterfly();
  // Poled positive (+1 then back to 0), then a unipolar drive in [0, 0.4].
  auto start = model.initial_state();
  model.step(start, 1.0);
  model.step(start, 0.0);
  std::vector<double> drive;
  for (int k = 0; k < 400; ++k)
    drive.push_back(0.2 + 0.18 * std::sin(0.05 * k) * std::cos(0.013 * k));
  auto forward = start;
  const auto targets = simulate(model, forward, std::span<const double>(drive));

  const InverseButterflyStrain inverse(model, {.input_min = 0.0, .input_max = 0.4});
  auto state = start;
  std::vector<double> inputs(targets.size());
  const auto report = invert(inverse, state, targets, inputs);
  EXPECT_TRUE(report.ok());
  auto check = start;
  const auto reproduced = simulate(model, check, std::span<const double>(inputs));
  for (std::size_t k = 0; k < targets.size(); ++k)
    ASSERT_NEAR(reproduced[k], targets[k], 1e-9) << "sample " << k;
}

TEST(InverseButterflyStrain, SaysNotInvertibleAcrossTheVertex) {
  const ButterflyStrain model = coercive_butterfly();
  const InverseButterflyStrain inverse(model, {.input_min = -1.0, .input_max = 1.0});
  auto state = model.initial_state();
  model.step(state, 1.0);
  model.step(state, 0.3);
  // From +P the limits reach negative saturation: P can pass the vertex, so the strain is not
  // monotone in the next input.
  EXPECT_FALSE(inverse.invertible_from(state));
  const auto sample = inverse.solve(state, 0.5);
  EXPECT_EQ(sample.status, InverseStatus::not_invertible);
  EXPECT_EQ(sample.input, 0.3);  // the previous input, held
  std::vector<double> targets(5, 0.5);
  std::vector<double> inputs(5);
  const auto report = invert(inverse, state, targets, inputs);
  EXPECT_EQ(report.not_invertible_samples, 5U);
  EXPECT_EQ(report.first_not_invertible, 0U);
}

// A second algorithm for the branch test: y(u) previewed on a dense grid of [lo, hi] must not
// change direction, and d must not oppose it.
bool monotone_by_sweep(const ButterflyStrain& model, const ButterflyStrain::State& state, double lo,
                       double hi) {
  int direction = 0;
  double previous = model.preview(state, lo);
  for (int k = 1; k <= 20000; ++k) {
    const double y = model.preview(state, lo + (hi - lo) * k / 20000.0);
    const int sign = y > previous + 1e-12 ? 1 : (y < previous - 1e-12 ? -1 : 0);
    if (sign != 0 && direction != 0 && sign != direction) return false;
    if (sign != 0) direction = sign;
    previous = y;
  }
  const double d = model.params().field_coefficient;
  return !(d > 0.0 && direction < 0) && !(d < 0.0 && direction > 0);
}

TEST(InverseButterflyStrain, BranchTestAgreesWithADenseSweep) {
  const ButterflyStrain model = coercive_butterfly();
  int invertible = 0;
  int not_invertible = 0;
  for (double poling : {-1.0, 1.0}) {
    for (double rest : {-0.4, 0.0, 0.5}) {
      auto state = model.initial_state();
      model.step(state, poling);
      model.step(state, rest);
      for (const auto& [lo, hi] :
           {std::pair{0.0, 0.4}, std::pair{-0.4, 0.0}, std::pair{-0.3, 0.3}, std::pair{-1.0, 1.0},
            std::pair{0.2, 0.9}, std::pair{-0.9, -0.2}}) {
        const InverseButterflyStrain inverse(model, {.input_min = lo, .input_max = hi});
        const bool expected = monotone_by_sweep(model, state, lo, hi);
        EXPECT_EQ(inverse.invertible_from(state), expected)
            << "poled " << poling << ", at " << rest << ", limits [" << lo << ", " << hi << "]";
        (expected ? invertible : not_invertible) += 1;
      }
    }
  }
  // Both answers occur, so the agreement means something.
  EXPECT_GT(invertible, 3);
  EXPECT_GT(not_invertible, 3);
}

TEST(InverseButterflyStrain, RejectsInvalidLimits) {
  EXPECT_HYST_ERROR(
      InverseButterflyStrain(coercive_butterfly(), {.input_min = 1.0, .input_max = 0.0}),
      "input_min");
}

}  // namespace
}  // namespace hyst
