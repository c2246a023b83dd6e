// The Preisach models' step(), preview() and the numerical inverse must not allocate: this test
// replaces the global operator new with a counting one (its own program, so the replacement does
// not leak into other tests) and runs 100 000 samples of each hot path, including the path that
// drops a pair from a full memory.

#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"

#include "../support/test_signals.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/inverse/inverse_preisach.hpp"
#include "hyst/models/preisach.hpp"

namespace hyst {
namespace {

constexpr std::size_t kPreisachSteps = 100'000;

Preisach grid101() {
  std::vector<double> mu(preisach_relay_count(101));
  for (std::size_t r = 0; r < mu.size(); ++r)
    mu[r] = 1.0 + static_cast<double>(r % 7);
  return Preisach({.everett = {.levels = 101, .lower = -1, .upper = 1, .weights = mu}});
}

GaussianPreisach gaussian() {
  return GaussianPreisach({.everett = {.lower = -1,
                                       .upper = 1,
                                       .saturation = 1,
                                       .alpha_centre = 0.2,
                                       .alpha_width = 0.2,
                                       .beta_centre = -0.2,
                                       .beta_width = 0.2}});
}

template <class Model>
long allocations_of_steps(const Model& model, std::uint64_t seed) {
  auto state = model.initial_state();
  const auto v = test::random_walk(kPreisachSteps, seed, 1.1, 0.2);
  double sink = 0;
  const long before = test::allocation_count();
  for (double x : v) {
    sink += model.preview(state, -x);
    sink += model.step(state, x);
  }
  const long counted = test::allocation_count() - before;
  EXPECT_TRUE(std::isfinite(sink));
  return counted;
}

TEST(PreisachNoAllocation, CounterSeesAllocations) {
  const long before = test::allocation_count();
  // A direct call: the compiler may elide a new-expression, never a call of operator new.
  void* block = ::operator new(64);
  ::operator delete(block);
  EXPECT_EQ(test::allocation_count() - before, 1);
}

TEST(PreisachNoAllocation, StepAndPreviewOfEveryEverettForm) {
  EXPECT_EQ(allocations_of_steps(grid101(), 1), 0);
  EXPECT_EQ(allocations_of_steps(gaussian(), 2), 0);
  EXPECT_EQ(allocations_of_steps(LorentzianPreisach({.everett = {.lower = -1,
                                                                 .upper = 1,
                                                                 .saturation = 1,
                                                                 .alpha_centre = 0.2,
                                                                 .alpha_width = 0.1,
                                                                 .beta_centre = -0.2,
                                                                 .beta_width = 0.1}}),
                                 3),
            0);
  EXPECT_EQ(allocations_of_steps(
                TabulatedPreisach({.everett = {.levels = {-1, 0, 1}, .values = {1, 3, 1}}}), 4),
            0);
}

TEST(PreisachNoAllocation, FullMemoryTruncation) {
  const auto model = grid101();
  auto state = model.initial_state();
  std::vector<double> v;
  for (int k = 1; k <= 2000; ++k) {
    const double a = 0.9 * std::pow(0.999, k);
    v.push_back(a);
    v.push_back(-a);
  }
  double sink = 0;
  const long before = test::allocation_count();
  for (double x : v)
    sink += model.step(state, x);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_GT(state.truncations, 0U);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(PreisachNoAllocation, SimulateStatefulAndCopies) {
  const auto model = grid101();
  auto state = model.initial_state();
  const auto v = test::random_walk(kPreisachSteps, 5);
  std::vector<double> y(v.size());
  Stateful<Preisach> stateful(model);
  double sink = 0;
  const long before = test::allocation_count();
  simulate(model, state, v, y);
  for (double x : v)
    sink += stateful.step(x);
  auto copy = state;  // the state is a fixed-size value: copying it does not allocate
  sink += model.step(copy, 0.5) + model.output(model.initial_state());
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(PreisachNoAllocation, InverseSolveAndBatchInvert) {
  const InverseGaussianPreisach inverse(gaussian());
  const InversePreisach grid_inverse(grid101());
  auto state = inverse.initial_state();
  auto grid_state = grid_inverse.initial_state();
  const auto targets = test::random_walk(kPreisachSteps / 10, 6, 1.2, 0.2);
  std::vector<double> inputs(targets.size());
  double sink = 0;
  const long before = test::allocation_count();
  for (double y : targets) {
    sink += inverse.solve(state, y).input;
    sink += grid_inverse.solve(grid_state, 50 * y).input;
  }
  invert(inverse, state, targets, inputs);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace hyst
