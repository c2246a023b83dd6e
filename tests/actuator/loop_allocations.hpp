#pragma once
// Runs a closed loop on a sine reference and counts its heap allocations (none expected).

#include <cmath>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"
#include "hyst/actuator/control_loop.hpp"

namespace hyst::test {

//! `steps` samples of PID + feedforward on 0.5 mm +- 0.3 mm; expects no allocation.
template <class H>
void expect_closed_loop_does_not_allocate(const ControlLoop<H>& loop, int steps) {
  auto state = loop.initial_state();
  double current_reference = 0.0;
  double voltage = 0.0;
  double sink = 0.0;
  const long before = allocation_count();
  for (int k = 0; k < steps; ++k) {
    const double r = 5e-4 + 3e-4 * std::sin(1e-3 * k);
    sink +=
        loop.step(state, ControlStrategy::pid_feedforward, r, current_reference, voltage).measured;
  }
  EXPECT_EQ(allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace hyst::test
