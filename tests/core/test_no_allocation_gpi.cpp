// The generalized play, the GPI model and its inverse must not allocate in step(), solve(),
// simulate() or invert(): this test replaces the global operator new with a counting one and runs
// 100 000 steps of each hot path (its own program, like test_no_allocation).

#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"

#include "../support/gpi_reference.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_generalized_prandtl_ishlinskii.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"
#include "hyst/operators/generalized_play.hpp"

namespace hyst {
namespace {

constexpr std::size_t kGpiSteps = 100'000;

// 0 .. 8 A random walk for the MSMA-like model.
std::vector<double> current(std::uint64_t seed) {
  auto i = test::random_walk(kGpiSteps, seed, 3.9, 0.3);
  for (double& x : i)
    x += 4.0;
  return i;
}

TEST(NoAllocationGpi, CounterSeesAllocations) {
  const long before = test::allocation_count();
  // A direct call: the compiler may elide a new-expression, never a call of operator new.
  void* block = ::operator new(64);
  ::operator delete(block);
  EXPECT_EQ(test::allocation_count() - before, 1);
}

TEST(NoAllocationGpi, GeneralizedPlayStep) {
  const GeneralizedPlay<TanhEnvelope> play({.ascending = {1, 1, -0.3, 0},
                                            .descending = {1, 1, 0.3, 0},
                                            .threshold = 0.1,
                                            .input_min = -2,
                                            .input_max = 2});
  auto state = play.initial_state();
  const auto v = test::random_walk(kGpiSteps, 1);
  double sink = 0;
  const long before = test::allocation_count();
  for (double x : v)
    sink += play.step(state, x);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(NoAllocationGpi, ModelStepAndSimulate) {
  const GeneralizedPrandtlIshlinskii<TanhEnvelope> model(test::msma_params());
  const GeneralizedPrandtlIshlinskii<ArctanEnvelope> arctan([] {
    auto params = test::msma_params();
    params.envelope = EnvelopeKind::arctan;
    params.ascending = {25.0, 0.8, -3.2, 40.0};
    params.descending = {25.0, 0.8, -2.8, 40.0};
    return params;
  }());
  auto state = model.initial_state();
  auto arctan_state = arctan.initial_state();
  const auto i = current(2);
  std::vector<double> y(i.size());
  Stateful<GeneralizedPrandtlIshlinskii<TanhEnvelope>> stateful(model);
  double sink = 0;
  const long before = test::allocation_count();
  for (double x : i)
    sink += model.step(state, x) + arctan.step(arctan_state, x) + stateful.step(x);
  simulate(model, state, i, y);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(NoAllocationGpi, InverseSolveAndBatchInvert) {
  const GeneralizedPrandtlIshlinskii<TanhEnvelope> model(test::msma_params());
  const InverseGeneralizedPrandtlIshlinskii<TanhEnvelope> inverse(
      model, {.input_min = 0.0, .input_max = 8.0});
  auto state = inverse.state_at_rest(40.0);
  auto targets = test::random_walk(kGpiSteps, 3, 30.0, 2.0);
  for (double& y : targets)
    y += 40.0;
  std::vector<double> inputs(targets.size());
  double sink = 0;
  const long before = test::allocation_count();
  for (double y : targets)
    sink += inverse.solve(state, y).input;
  invert(inverse, state, targets, inputs);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace hyst
