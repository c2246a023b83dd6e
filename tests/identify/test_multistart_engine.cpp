// The multistart engine (src/identify/detail/multistart_driver.hpp, multistart_fit.hpp): which
// runs it continues and keeps, its report, and its global
// stage (global_stage.hpp) on a cost with
// many valleys: cost(q) = ((q - 4)^2 + 9 cos^2(2 q)) / 2 on [-5, 10]. Its valleys lie near the
// zeros of cos(2 q), q = pi/4 + k pi/2, and the deepest is the one closest to 4 (3 pi/4 + pi/2 =
// 3.93). Levenberg-Marquardt from q = 0.7 ends in the valley near pi/4; the global stage finds the
// deepest one. The reference minimum comes from a second algorithm: a grid search with 1e-5 steps.

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "detail/multistart_driver.hpp"
#include "detail/multistart_fit.hpp"

namespace {

struct ManyValleys {
  template <class T>
  bool operator()(const T* q, T* residuals) const {
    using std::cos;
    residuals[0] = q[0] - T(4.0);
    residuals[1] = T(3.0) * cos(T(2.0) * q[0]);
    return true;
  }
  std::size_t residuals() const { return 2; }
};

double cost(double q) {
  return 0.5 * ((q - 4.0) * (q - 4.0) + 9.0 * std::cos(2.0 * q) * std::cos(2.0 * q));
}

double grid_minimum() {
  double best_q = -5.0;
  for (double q = -5.0; q <= 10.0; q += 1e-5) {
    if (cost(q) < cost(best_q)) best_q = q;
  }
  return best_q;
}

hyst::detail::MultistartOptions<1> options(std::size_t global_evaluations) {
  hyst::detail::MultistartOptions<1> o;
  o.lower = {-5.0};
  o.upper = {10.0};
  o.global_evaluations = global_evaluations;
  return o;
}

TEST(GlobalStage, LocalStartEndsInTheNearestValley) {
  const auto result = hyst::detail::multistart_fit(ManyValleys{}, {{0.7}}, options(0), "test");
  EXPECT_NEAR(result.q[0], std::numbers::pi / 4.0, 0.1);
  EXPECT_GT(result.final_cost, cost(grid_minimum()) + 1.0);
}

TEST(GlobalStage, FindsTheDeepestValley) {
  const double reference = grid_minimum();
  ASSERT_NEAR(reference, 3.93, 0.05);
  const auto result = hyst::detail::multistart_fit(ManyValleys{}, {{0.7}}, options(300), "test");
  EXPECT_EQ(result.best_start, 1u);  // the point of the global stage
  EXPECT_NEAR(result.q[0], reference, 1e-4);
  EXPECT_NEAR(result.final_cost, cost(reference), 1e-8);
}

TEST(GlobalStage, RepeatsBitForBit) {
  const auto first = hyst::detail::multistart_fit(ManyValleys{}, {{0.7}}, options(50), "test");
  const auto second = hyst::detail::multistart_fit(ManyValleys{}, {{0.7}}, options(50), "test");
  EXPECT_EQ(first.q[0], second.q[0]);
  EXPECT_EQ(first.final_cost, second.final_cost);
}

TEST(GlobalStage, KeepsFixedParametersAtTheirStart) {
  hyst::detail::MultistartOptions<1> o = options(100);
  o.fixed = {0};
  const auto result = hyst::detail::multistart_fit(ManyValleys{}, {{0.7}}, o, "test");
  EXPECT_EQ(result.q[0], 0.7);
}

// cost(q) = q^2 / 2 on [1, 5]: the minimum is the lower bound, which the report calls degenerate.
struct Square {
  template <class T>
  bool operator()(const T* q, T* residuals) const {
    residuals[0] = q[0];
    return true;
  }
  std::size_t residuals() const { return 1; }
};

TEST(MultistartReport, EveryParameterAtABoundIsDegenerate) {
  hyst::detail::MultistartOptions<1> o;
  o.lower = {1.0};
  o.upper = {5.0};
  const auto result = hyst::detail::multistart_fit(Square{}, {{3.0}}, o, "test");
  EXPECT_DOUBLE_EQ(result.q[0], 1.0);
  EXPECT_TRUE(result.at_bound[0]);
  const auto report = hyst::detail::report_of(result, 1.0, 1, "test", "lm");
  EXPECT_EQ(report.status(), "degenerate");
  EXPECT_NE(report.quality_note.find("ended at a bound"), std::string::npos);
  // A sound simulation does not overrule the fitter's verdict; an unstable one does.
  auto judged = report;
  judged.take_verdict(hyst::FitQuality::sound, "");
  EXPECT_EQ(judged.status(), "degenerate");
  judged.take_verdict(hyst::FitQuality::unstable, "runs away");
  EXPECT_EQ(judged.status(), "unstable");
}

TEST(MultistartReport, AnInteriorMinimumIsNotDegenerate) {
  hyst::detail::MultistartOptions<1> o = options(0);
  const auto result = hyst::detail::multistart_fit(ManyValleys{}, {{0.7}}, o, "test");
  const auto report = hyst::detail::report_of(result, 1.0, 1, "test", "lm");
  EXPECT_EQ(report.status(), "converged");
}

// The driver's rule (multistart_driver.hpp) on scripted runs: start s screens to cost
// screened[s], its continuation ends at continued[s]; the expected choices follow by hand.
struct ScriptedRun {
  std::size_t start = 0;
  double cost = 0.0;
  bool usable = true;
  bool finished = false;
  std::size_t iterations = 0;
};

struct Script {
  std::vector<double> screened;
  std::vector<double> continued;
  std::vector<std::size_t> continued_starts;  // which starts were continued, in order

  hyst::detail::MultistartRuns<ScriptedRun> run(const hyst::detail::MultistartBudget& budget) {
    return hyst::detail::run_multistart(
        screened.size(), budget,
        [&](std::size_t s, std::size_t iterations) {
          return ScriptedRun{s, screened[s], std::isfinite(screened[s]), false, iterations};
        },
        [&](const ScriptedRun& run, std::size_t iterations) {
          continued_starts.push_back(run.start);
          return ScriptedRun{run.start, continued[run.start], true, true, iterations};
        });
  }
};

TEST(MultistartDriver, TheBestScreenedRunContinues) {
  Script script{{3.0, 1.0, NAN, 2.0}, {0.5, 0.9, 0.0, 0.1}, {}};
  const auto runs = script.run({.screening_iterations = 4, .max_iterations = 50});
  ASSERT_TRUE(runs.found);
  EXPECT_EQ(runs.best_start, 1U);  // lowest screened cost; the NaN start is not usable
  EXPECT_EQ(runs.best.cost, 0.9);  // its continuation, even though start 3's would be lower
  EXPECT_EQ(script.continued_starts, std::vector<std::size_t>{1});
  EXPECT_EQ(runs.refining_iterations, 50U);
  EXPECT_EQ(runs.iterations, 4U * 4 + 50);
}

TEST(MultistartDriver, SeveralRefinedStartsKeepTheLowestFinalCost) {
  Script script{{3.0, 1.0, 2.5, 2.0}, {0.5, 0.9, 0.0, 0.1}, {}};
  const auto runs =
      script.run({.screening_iterations = 4, .refined_starts = 3, .max_iterations = 50});
  EXPECT_EQ(script.continued_starts, (std::vector<std::size_t>{1, 3, 2}));
  EXPECT_EQ(runs.best_start, 2U);
  EXPECT_EQ(runs.best.cost, 0.0);
  EXPECT_EQ(runs.iterations, 4U * 4 + 3 * 50);
}

TEST(MultistartDriver, WithoutScreeningEveryStartRunsInFullAndNoneContinues) {
  Script script{{3.0, 1.0, 2.5}, {0.5, 0.0, 0.1}, {}};
  const auto runs = script.run({.screen = false, .max_iterations = 50});
  EXPECT_TRUE(script.continued_starts.empty());
  EXPECT_EQ(runs.best_start, 1U);
  EXPECT_EQ(runs.best.cost, 1.0);
  EXPECT_EQ(runs.iterations, 3U * 50);
}

TEST(MultistartDriver, AFinishedRunContinuesOnlyWhenAskedTo) {
  Script script{{3.0, 1.0}, {0.5, 0.2}, {}};
  auto finished_solve = [&](std::size_t s, std::size_t iterations) {
    return ScriptedRun{s, script.screened[s], true, true, iterations};
  };
  auto record = [&](const ScriptedRun& run, std::size_t iterations) {
    script.continued_starts.push_back(run.start);
    return ScriptedRun{run.start, script.continued[run.start], true, true, iterations};
  };
  auto runs = hyst::detail::run_multistart(2, {}, finished_solve, record);
  EXPECT_TRUE(script.continued_starts.empty());
  EXPECT_EQ(runs.best.cost, 1.0);
  runs = hyst::detail::run_multistart(2, {.always_continue = true}, finished_solve, record);
  EXPECT_EQ(script.continued_starts, std::vector<std::size_t>{1});
  EXPECT_EQ(runs.best.cost, 0.2);
}

}  // namespace
