// Numerical inverse of monotone differential models: round trip (the model driven by the
// inverse's inputs gives the targets back) and saturation at the input limits.

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/inverse/monotone_inverse.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "hyst/models/jiles_atherton.hpp"

namespace hyst {
namespace {

template <class Model>
void expect_round_trip(const Model& model, const std::vector<double>& input, double tolerance) {
  auto state = model.initial_state();
  std::vector<double> targets;
  for (double v : input)
    targets.push_back(model.step(state, v));
  const MonotoneInverse<Model> inverse(model, -1e9, 1e9);
  typename MonotoneInverse<Model>::State inverse_state{model.initial_state(), 0.0};
  std::vector<double> recovered(targets.size());
  const auto report = invert(inverse, inverse_state, targets, recovered);
  EXPECT_TRUE(report.ok());
  for (std::size_t k = 0; k < input.size(); ++k)
    EXPECT_NEAR(recovered[k], input[k], tolerance) << k;
}

std::vector<double> loops(double amplitude) {
  std::vector<double> v;
  for (int k = 1; k <= 600; ++k)
    v.push_back(amplitude * std::sin(2 * std::numbers::pi * k / 200.0) * (1.0 - k / 900.0));
  return v;
}

TEST(MonotoneInverse, JilesAthertonFieldFromFluxDensity) {
  expect_round_trip(JilesAtherton(JilesAtherton::Params{}), loops(4000.0), 1e-6);
}

TEST(MonotoneInverse, BoucWenDisplacementFromForce) {
  expect_round_trip(BoucWen(BoucWen::Params{}), loops(2.0), 1e-9);
}

TEST(MonotoneInverse, SaturatesAtTheInputLimits) {
  const BoucWen model(BoucWen::Params{});
  const MonotoneInverse<BoucWen> inverse(model, -1.0, 1.0);
  MonotoneInverse<BoucWen>::State state{model.initial_state(), 0.0};
  const auto high = inverse.solve(state, 100.0);
  EXPECT_EQ(high.status, InverseStatus::above_range);
  EXPECT_EQ(high.input, 1.0);
  const auto low = inverse.solve(state, -100.0);
  EXPECT_EQ(low.status, InverseStatus::below_range);
  EXPECT_EQ(low.input, -1.0);
}

TEST(MonotoneInverse, UnboundedRangeByDefaultInRegistryUse) {
  // Infinite limits (the registry's default): the bracket grows until it holds the target.
  const BoucWen model(BoucWen::Params{});
  const MonotoneInverse<BoucWen> inverse(model, -INFINITY, INFINITY);
  MonotoneInverse<BoucWen>::State state{model.initial_state(), 0.0};
  auto probe = model.initial_state();
  const double target = model.step(probe, 250.0);
  const auto sample = inverse.solve(state, target);
  EXPECT_EQ(sample.status, InverseStatus::ok);
  EXPECT_NEAR(sample.input, 250.0, 1e-9);
}

TEST(MonotoneInverse, RejectsAnEmptyOrNanRange) {
  const BoucWen model(BoucWen::Params{});
  EXPECT_HYST_ERROR(static_cast<void>(MonotoneInverse<BoucWen>(model, 1.0, 1.0)),
                    "input_min = 1 must be < input_max");
  EXPECT_HYST_ERROR(static_cast<void>(MonotoneInverse<BoucWen>(model, NAN, 1.0)),
                    "input_min = nan");
}

}  // namespace
}  // namespace hyst
