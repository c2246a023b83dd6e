// The PI paths the conformance suite does not reach through the registry must not allocate: the
// Stateful wrapper and the inverse's per-sample solve(). This test replaces the global operator
// new with a counting one and runs 100 000 steps of each hot path.

#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"

#include "../support/test_signals.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {
namespace {

constexpr std::size_t kSteps = 100'000;

PrandtlIshlinskii model16() {
  return PrandtlIshlinskii(
      {.thresholds = uniform_thresholds(16, 0.1), .weights = std::vector<double>(16, 1.0 / 16)});
}

TEST(NoAllocation, CounterSeesAllocations) {
  const long before = test::allocation_count();
  // A direct call: the compiler may elide a new-expression, never a call of operator new.
  void* block = ::operator new(64);
  ::operator delete(block);
  EXPECT_EQ(test::allocation_count() - before, 1);
}

TEST(NoAllocation, SimulateAndStatefulStep) {
  const auto model = model16();
  auto state = model.initial_state();
  const auto v = test::random_walk(kSteps, 2);
  std::vector<double> y(v.size());
  Stateful<PrandtlIshlinskii> stateful(model);
  double sink = 0;
  const long before = test::allocation_count();
  simulate(model, state, v, y);
  for (double x : v)
    sink += stateful.step(x);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(NoAllocation, InverseSolveAndBatchInvert) {
  const InversePrandtlIshlinskii inverse(model16(), {.input_min = -1.5, .input_max = 1.5});
  auto state = inverse.initial_state();
  const auto targets = test::random_walk(kSteps, 3);
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
