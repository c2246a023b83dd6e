// step() of the differential models must not allocate (fixed-size RK4 and Dormand-Prince
// std::array states, the exact Bouc-Wen path): counted with the replacing operator new over
// 100 000 steps of each. The conformance suite covers every model with its example parameters;
// these are the other integration paths.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/models/backlash_like.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "hyst/models/bouc_wen_oscillator.hpp"
#include "hyst/models/duhem.hpp"
#include "hyst/models/jiles_atherton.hpp"

namespace hyst {
namespace {

template <class Model>
void expect_no_allocation(const Model& model, double input_scale) {
  auto state = model.initial_state();
  auto v = test::random_walk(100'000, 5);
  for (double& x : v)
    x *= input_scale;
  std::vector<double> y(v.size());
  const long before = test::allocation_count();
  simulate(model, state, v, y);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(y.back()));
}

TEST(NoAllocationDifferential, EveryModelStep) {
  expect_no_allocation(BoucWen(BoucWen::Params{}), 1.0);
  auto adaptive = BoucWenOscillator::benchmark();
  adaptive.tolerance = 1e-8;  // Boost.Odeint Dormand-Prince on std::array
  expect_no_allocation(BoucWenOscillator(adaptive), 10.0);
  BoucWen::Params bouc_wen_adaptive;
  bouc_wen_adaptive.n = 1.5;
  bouc_wen_adaptive.tolerance = 1e-8;
  expect_no_allocation(BoucWen(bouc_wen_adaptive), 1.0);
  Duhem::Params duhem_adaptive;
  duhem_adaptive.tolerance = 1e-8;
  expect_no_allocation(Duhem(duhem_adaptive), 1.0);
  expect_no_allocation(BacklashLike(BacklashLike::Params{}), 1.0);
  expect_no_allocation(JilesAtherton(JilesAtherton::Params{}), 100.0);
  JilesAtherton::Params jiles_atherton_adaptive;
  jiles_atherton_adaptive.tolerance = 1e-8;
  expect_no_allocation(JilesAtherton(jiles_atherton_adaptive), 100.0);
}

}  // namespace
}  // namespace hyst
