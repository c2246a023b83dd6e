// step() of the Ikuta, KP, Maxwell-slip, modified PI and rate-dependent PI models, and the
// modified PI inverse, allocate nothing: the global operator new is replaced by a counting one in
// this program.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"
#include "../support/test_signals.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp"
#include "hyst/models/ikuta_sma.hpp"
#include "hyst/models/krasnoselskii_pokrovskii.hpp"
#include "hyst/models/maxwell_slip.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"
#include "hyst/models/rate_dependent_prandtl_ishlinskii.hpp"

namespace hyst {
namespace {

template <class Model>
long allocations_of_steps(const Model& model) {
  auto state = model.initial_state();
  const auto v = test::random_walk(100'000, 37, 1.2, 0.1);
  double sink = 0.0;
  const long before = test::allocation_count();
  for (double x : v)
    sink += model.step(state, x);
  const long counted = test::allocation_count() - before;
  EXPECT_TRUE(std::isfinite(sink));
  return counted;
}

TEST(OperatorModelsNoAllocation, StepsAllocateNothing) {
  EXPECT_EQ(allocations_of_steps(IkutaSma({.martensite_finish = -0.8,
                                           .martensite_start = 0.2,
                                           .austenite_start = -0.2,
                                           .austenite_finish = 0.8})),
            0);
  EXPECT_EQ(allocations_of_steps(
                KrasnoselskiiPokrovskii({.levels = 21, .weights = std::vector<double>(231, 1.0)})),
            0);
  EXPECT_EQ(allocations_of_steps(MaxwellSlip(
                {.stiffness = {3, 2, 1}, .break_away = {0.3, 0.4, 0.5}, .linear_stiffness = 1})),
            0);
  const ModifiedPrandtlIshlinskii mpi(
      {.pi = {.thresholds = {0, 0.3, 0.7}, .weights = {0.8, 0.5, 0.3}},
       .dead_zone = {{-0.3, 0, 0.4}, {0.2, 1.0, -0.15}}});
  EXPECT_EQ(allocations_of_steps(mpi), 0);
  EXPECT_EQ(allocations_of_steps(InverseModifiedPrandtlIshlinskii(mpi)), 0);
  EXPECT_EQ(allocations_of_steps(RateDependentPrandtlIshlinskii(
                rate_dependent_pi_exponential(0.1, 1, 0.5, 8, 0.01, 1e-3))),
            0);
}

}  // namespace
}  // namespace hyst
