// Free-run checks by hand: which simulated samples count as run away, and when a score says that
// its model is unstable (a pole outside the unit circle) or ran away on the data.

#include "hyst/dynamics/free_run_check.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "hyst/dynamics/simulation_score.hpp"
#include "periodic_experiments.hpp"

namespace hyst {
namespace {

TEST(FreeRunCheck, CountsSamplesBeyondTenRangeWidths) {
  // Channel 1 measured in [0, 1]: run away below -10 or above 11; channel 2 in [-2, 2]: beyond
  // +-42.
  const std::vector<ChannelRange> ranges{{0.0, 1.0}, {-2.0, 2.0}};
  Eigen::MatrixXd simulated(5, 2);
  simulated << 11.0, 42.0,  //  on the bounds: not run away
      -10.0, -42.0,         //
      0.5, 42.5,            //  channel 2 beyond: the first one, at sample 3
      11.5, 0.0,            //  channel 1 beyond
      std::numeric_limits<double>::quiet_NaN(), -43.0;  // NaN counts too
  RunawayCount count;
  count_runaway(simulated, ranges, 4, count);
  EXPECT_EQ(count.samples, 4u);
  EXPECT_EQ(count.realisation, 4u);
  EXPECT_EQ(count.sample, 2u);
  EXPECT_EQ(count.channel, 1u);
  // A later realisation adds to the count but keeps the first one.
  count_runaway(simulated, ranges, 5, count);
  EXPECT_EQ(count.samples, 8u);
  EXPECT_EQ(count.realisation, 4u);
}

TEST(FreeRunCheck, ChannelRangesSpanEveryRealisationAndPeriod) {
  const PeriodicSignals signals{.samples = 2,
                                .channels = 2,
                                .realisations = 2,
                                .periods = 1,
                                .values = {1.0, -1.0, 3.0, 0.0, -2.0, 5.0, 0.5, 0.25}};
  const auto ranges = channel_ranges(signals);
  ASSERT_EQ(ranges.size(), 2u);
  EXPECT_EQ(ranges[0].minimum, -2.0);
  EXPECT_EQ(ranges[0].maximum, 3.0);
  EXPECT_EQ(ranges[1].minimum, -1.0);
  EXPECT_EQ(ranges[1].maximum, 5.0);
}

// x[n+1] = pole x[n] + u[n], y[n] = 0.5 gain x[n]: with pole 0.5 and gain 1 the lag below.
StateSpace unstable_candidate(double pole, double gain) {
  StateSpace::Params p;
  p.a = Eigen::MatrixXd::Constant(1, 1, pole);
  p.b = Eigen::MatrixXd::Constant(1, 1, 1.0);
  p.c = Eigen::MatrixXd::Constant(1, 1, 0.5 * gain);
  p.d = Eigen::MatrixXd::Zero(1, 1);
  return StateSpace(p);
}

TEST(FreeRunCheck, APoleOutsideTheUnitCircleIsSaid) {
  const auto warnings = free_run_warnings(unstable_candidate(1.0005, 1.0), RunawayCount{});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("pole of magnitude 1.0005"), std::string::npos) << warnings[0];
  EXPECT_TRUE(free_run_warnings(unstable_candidate(0.9995, 1.0), RunawayCount{}).empty());
  // A pole on the unit circle (an integrator) is not outside it.
  EXPECT_TRUE(free_run_warnings(unstable_candidate(1.0, 1.0), RunawayCount{}).empty());
}

// One input, one output: y[n] = 0.5 y[n-1] + 0.5 u[n-1], by direct recursion.
Eigen::VectorXd half_lag(Eigen::VectorXd& x, const Eigen::VectorXd& u) {
  const Eigen::VectorXd y = x;
  x = 0.5 * x + 0.5 * u;
  return y;
}

TEST(FreeRunCheck, TheScoreCountsTheSamplesOfAModelThatRunsAway) {
  const auto e = test::periodic_experiment(half_lag, 1, 1, 1, 64, 8, 2, 2, 7);
  // The system that made the data stays inside its measured range.
  const auto fitting = score_state_space(unstable_candidate(0.5, 1.0), e.input, e.output);
  EXPECT_EQ(fitting.runaway.samples, 0u);
  // Pole 1.1 from rest: 1.1^n passes 10 range widths within the first period and never returns.
  const auto unstable = score_state_space(unstable_candidate(1.1, 1.0), e.input, e.output);
  EXPECT_GT(unstable.runaway.samples, 0u);
  EXPECT_EQ(unstable.runaway.realisation, 0u);
  EXPECT_LT(unstable.runaway.sample, 64u);
  const auto warnings = free_run_warnings(unstable_candidate(1.1, 1.0), unstable.runaway);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[1].find("simulated samples ran away"), std::string::npos) << warnings[1];
  // A stable model with a gain a thousand times too large runs away without an unstable pole.
  const auto loud = score_state_space(unstable_candidate(0.5, 1000.0), e.input, e.output);
  EXPECT_GT(loud.runaway.samples, 0u);
  EXPECT_EQ(free_run_warnings(unstable_candidate(0.5, 1000.0), loud.runaway).size(), 1u);
}

}  // namespace
}  // namespace hyst
