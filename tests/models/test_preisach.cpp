// The discrete Preisach model: the fast Everett form against the brute-force relay grid and the
// reference's Python checks (preisach_check.py, preisach_props.py), its memory, and bad input.

#include "hyst/models/preisach.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/python_random.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/models/preisach_relay_grid.hpp"

namespace hyst {
namespace {

Preisach::Params grid_params(
    std::size_t levels, std::vector<double> weights,
    PreisachGridLayout layout = PreisachGridLayout::cell_centred,
    PreisachInitialState initial = PreisachInitialState::negative_saturation, double offset = 0.0) {
  return {.everett = {.levels = levels,
                      .lower = -1.0,
                      .upper = 1.0,
                      .weights = std::move(weights),
                      .layout = layout},
          .offset = offset,
          .initial_state = initial};
}

std::vector<double> random_weights(std::size_t levels, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> mu(preisach_relay_count(levels));
  for (double& m : mu)
    m = unit(rng);
  return mu;
}

// The weights of the reference checks: random.seed(3), then one random() per relay (i, j), i >= j,
// in the order i = 0..N-1, j = 0..i - which is also hyst's storage order.
std::vector<double> python_weights(test::PythonRandom& rng, std::size_t levels) {
  std::vector<double> mu(preisach_relay_count(levels));
  for (double& m : mu)
    m = rng.random();
  return mu;
}

std::vector<double> run(const Preisach& model, std::vector<double> input) {
  auto state = model.initial_state();
  return simulate(model, state, input);
}

std::vector<double> run(const PreisachRelayGrid& model, const std::vector<double>& input) {
  auto state = model.initial_state();
  std::vector<double> y;
  for (double v : input)
    y.push_back(model.step(state, v));
  return y;
}

// ---------------------------------------------------------------------------------------------
// Independent reference values

TEST(Preisach, RelayCountOfTheSeedGrid) {
  EXPECT_EQ(preisach_relay_count(21), 231U);
  EXPECT_EQ(preisach_relay_index(20, 20), 230U);
  const Preisach model(grid_params(21, uniform_relay_weights(21, 1.0)));
  EXPECT_EQ(model.total_weight(), 231.0);
}

// preisach_props.py: unweighted (mu = 1) cell-centred 231-relay model from negative saturation.
// The 101 needs the tie rule: 0 is exactly the middle threshold, whose diagonal relay stays +1.
TEST(Preisach, UnweightedSeedModelMatchesPreisachProps) {
  const auto params = grid_params(21, uniform_relay_weights(21, 1.0));
  const std::vector<double> input{-1.0, 1.0, 0.0, 0.5, -0.5, 1.0};
  const std::vector<double> expected{-231, 231, 101, 141, -41, 231};
  EXPECT_EQ(run(Preisach(params), input), expected);
  EXPECT_EQ(run(PreisachRelayGrid(params), input), expected);
  ASSERT_EQ(Preisach(params).everett().thresholds()[10], 0.0);
}

// preisach.md sec. 4: with endpoint levels the relay (x_0, x_0) ties at v = lower.
TEST(Preisach, EndpointLayoutTiesAtTheLowerLevel) {
  const auto params =
      grid_params(21, uniform_relay_weights(21, 1.0), PreisachGridLayout::endpoints);
  EXPECT_EQ(run(Preisach(params), {1.0, -1.0}).back(), -229.0);
  EXPECT_EQ(run(PreisachRelayGrid(params), {1.0, -1.0}).back(), -229.0);
  EXPECT_EQ(run(Preisach(params), {1.0, -1.0 - 1e-9}).back(), -231.0);
}

// preisach_check.py: endpoint grid N = 21 on [-1, 1], random weights (seed 3), a 400-sample
// random walk in [-1.3, 1.3]; the script finds staircase = brute force to 5.7e-14.
TEST(Preisach, FastFormMatchesBruteForceOnPreisachCheckData) {
  test::PythonRandom rng(3);
  const auto params = grid_params(21, python_weights(rng, 21), PreisachGridLayout::endpoints);
  std::vector<double> input;
  double u = 0.0;
  for (int k = 0; k < 400; ++k) {
    u = std::clamp(u + rng.uniform(-0.15, 0.15), -1.3, 1.3);
    input.push_back(u);
  }
  const auto fast = run(Preisach(params), input);
  const auto brute = run(PreisachRelayGrid(params), input);
  double worst = 0;
  for (std::size_t k = 0; k < input.size(); ++k)
    worst = std::max(worst, std::abs(fast[k] - brute[k]));
  EXPECT_LE(worst, 1e-12);
  // Values printed by the script's own brute force (repr, 17 digits).
  EXPECT_NEAR(input[399], -1.2281655743389615, 1e-15);
  EXPECT_NEAR(Preisach(params).total_weight(), 120.13841533113289, 1e-12);
  EXPECT_NEAR(fast[0], -46.262282824261135, 1e-12);
  EXPECT_NEAR(fast[99], -108.41905712479965, 1e-12);
  EXPECT_NEAR(fast[199], -106.40784057160998, 1e-12);
  EXPECT_NEAR(fast[399], -120.13841533113289, 1e-12);
}

// preisach_props.py, wiping-out and congruency with its random weights (cell-centred, seed 3).
TEST(Preisach, WipingOutAndCongruencyMatchPreisachProps) {
  test::PythonRandom rng(3);
  const Preisach model(grid_params(21, python_weights(rng, 21)));
  const std::vector<double> cont{0.2, -0.5, 0.4};
  auto a = run(model, {0.6, -0.2, 0.3, 0.1, 0.6, 0.2, -0.5, 0.4});
  auto b = run(model, {0.6, 0.2, -0.5, 0.4});
  const std::vector<double> printed{28.902782, -39.316536, 18.460487};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(a[5 + k], printed[k], 5e-7) << k;
    EXPECT_EQ(a[5 + k], b[1 + k]) << k;
  }
  const auto y1 = run(model, {0.9, -0.8, 0.8, -0.33, 0.47, -0.33});
  const auto y2 = run(model, {0.2, -0.9, 0.6, -0.7, 0.75, -0.33, 0.47, -0.33});
  EXPECT_NEAR(y1[4] - y1[3], 35.016809062, 5e-10);
  EXPECT_NEAR(y2[6] - y2[5], 35.016809062, 5e-10);
  EXPECT_NEAR(y1[5] - y1[3], 0.0, 1e-12);
  EXPECT_NEAR(y2[7] - y2[5], 0.0, 1e-12);
  EXPECT_NEAR(y1[3], 2.250669, 5e-7);
  EXPECT_NEAR(y2[5], -6.60856, 5e-6);
  // Rise over a minor loop = 2 E(u2, u1).
  EXPECT_NEAR(y1[4] - y1[3], 2 * model.everett()(0.47, -0.33), 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Fast form = brute force on seeded random inputs with many internal loops

struct BruteCase {
  std::size_t levels;
  PreisachGridLayout layout;
  PreisachInitialState initial;
};

void expect_fast_equals_brute(const BruteCase& c, std::uint64_t seed, std::size_t samples) {
  SCOPED_TRACE(testing::Message() << "seed " << seed << ", N = " << c.levels << ", "
                                  << to_string(c.layout) << ", " << to_string(c.initial));
  const auto params =
      grid_params(c.levels, random_weights(c.levels, seed), c.layout, c.initial, 0.25);
  const Preisach fast(params);
  const PreisachRelayGrid brute(params);
  auto fast_state = fast.initial_state();
  auto brute_state = brute.initial_state();
  ASSERT_NEAR(fast.output(fast_state), brute.output(brute_state), 1e-12 * fast.total_weight());

  // A random walk slightly wider than the grid, with every tenth sample snapped to a threshold or
  // a cell boundary so that exact ties with the relay thresholds are exercised too.
  std::mt19937_64 rng(seed);
  const auto walk = test::random_walk(samples, seed, 1.1, 0.3);
  const auto c_k = fast.everett().thresholds();
  double worst = 0;
  for (std::size_t k = 0; k < walk.size(); ++k) {
    double v = walk[k];
    if (k % 10 == 5) {
      const std::size_t level = rng() % c.levels;
      v = rng() % 2 == 0 ? c_k[level] : -1.0 + 2.0 * static_cast<double>(level) / c.levels;
    }
    const double y_fast = fast.step(fast_state, v);
    const double y_brute = brute.step(brute_state, v);
    worst = std::max(worst, std::abs(y_fast - y_brute));
    ASSERT_NEAR(y_fast, y_brute, 1e-12 * fast.total_weight()) << "k = " << k << ", v = " << v;
  }
  testing::Test::RecordProperty("worst_relative_difference",
                                fmt::format("{:.2e}", worst / fast.total_weight()));
}

TEST(Preisach, FastFormEqualsBruteForceN21) {
  std::mt19937_64 seeds(21);
  for (auto layout : {PreisachGridLayout::cell_centred, PreisachGridLayout::endpoints}) {
    for (auto initial :
         {PreisachInitialState::negative_saturation, PreisachInitialState::positive_saturation,
          PreisachInitialState::demagnetised}) {
      for (int trial = 0; trial < 4; ++trial)
        expect_fast_equals_brute({21, layout, initial}, seeds(), 4000);
    }
  }
}

TEST(Preisach, FastFormEqualsBruteForceN101) {
  std::mt19937_64 seeds(101);
  for (auto initial :
       {PreisachInitialState::negative_saturation, PreisachInitialState::demagnetised}) {
    for (int trial = 0; trial < 2; ++trial)
      expect_fast_equals_brute({101, PreisachGridLayout::cell_centred, initial}, seeds(), 3000);
  }
  expect_fast_equals_brute(
      {101, PreisachGridLayout::endpoints, PreisachInitialState::positive_saturation}, seeds(),
      3000);
}

TEST(Preisach, FastFormEqualsBruteForceForSmallGrids) {
  for (std::size_t levels = 1; levels <= 6; ++levels) {
    expect_fast_equals_brute(
        {levels, PreisachGridLayout::cell_centred, PreisachInitialState::demagnetised}, levels,
        2000);
    if (levels >= 2) {
      expect_fast_equals_brute(
          {levels, PreisachGridLayout::endpoints, PreisachInitialState::demagnetised}, levels,
          2000);
    }
  }
}

// The demagnetised staircase is exactly the relay pattern alpha + beta < lower + upper.
TEST(Preisach, DemagnetisedStateIsTheAntiDiagonalPattern) {
  for (std::size_t levels : {1U, 2U, 3U, 4U, 21U, 22U}) {
    SCOPED_TRACE(testing::Message() << "N = " << levels);
    const auto params =
        grid_params(levels, uniform_relay_weights(levels, 1.0), PreisachGridLayout::cell_centred,
                    PreisachInitialState::demagnetised);
    const Preisach fast(params);
    const PreisachRelayGrid brute(params);
    // Symmetric pattern: as many relays up as down off the anti-diagonal.
    EXPECT_EQ(fast.output(fast.initial_state()), brute.output(brute.initial_state()));
    std::size_t on_anti_diagonal = 0;
    for (std::size_t i = 0; i < levels; ++i)
      on_anti_diagonal += (i >= levels - 1 - i) ? 1 : 0;
    EXPECT_EQ(brute.output(brute.initial_state()), -static_cast<double>(on_anti_diagonal));
  }
}

// ---------------------------------------------------------------------------------------------
// Properties

TEST(Preisach, RateIndependentUnderUpsampling) {
  const Preisach model(grid_params(21, random_weights(21, 5)));
  const auto v = test::random_walk(3000, 5, 1.2, 0.25);
  auto coarse = model.initial_state();
  auto fine = model.initial_state();
  const auto y = simulate(model, coarse, v);
  const auto y_fine = simulate(model, fine, test::upsample_linear(v, 4));
  for (std::size_t k = 0; k < v.size(); ++k)
    ASSERT_NEAR(y[k], y_fine[4 * k], 1e-12 * model.total_weight()) << "k = " << k;
}

TEST(Preisach, OutputIsBoundedMonotoneAndSaturates) {
  for (std::uint64_t seed : {11U, 12U, 13U}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const Preisach model(grid_params(31, random_weights(31, seed), PreisachGridLayout::cell_centred,
                                     PreisachInitialState::demagnetised, -0.5));
    const auto v = test::random_walk(5000, seed, 1.5, 0.3);
    auto state = model.initial_state();
    double previous_y = model.output(state);
    double previous_v = v.front();
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double y = model.step(state, v[k]);
      ASSERT_GE(y, model.output_min() - 1e-12);
      ASSERT_LE(y, model.output_max() + 1e-12);
      if (k > 0) {
        ASSERT_GE((y - previous_y) * (v[k] - previous_v), -1e-12) << "k = " << k;
      }
      if (v[k] < -1.0) {
        ASSERT_EQ(y, model.output_min());
      }
      if (v[k] > 1.0) {
        ASSERT_EQ(y, model.output_max());
      }
      previous_y = y;
      previous_v = v[k];
    }
  }
}

// Return-point memory: after any excursion that stays between the last reversal and the one
// before it, returning to the last reversal point restores the output and the memory.
TEST(Preisach, ReturnPointMemory) {
  const Preisach model(grid_params(41, random_weights(41, 17)));
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto state = model.initial_state();
  // Falling from 0.6 to the reversal point -0.1.
  const double y_before = simulate(model, state, std::vector<double>{0.9, -0.7, 0.6, -0.1}).back();
  const auto before = state;
  // Excursions inside (-0.1, 0.6): rise, fall, nested loops, then back to -0.1.
  for (int trial = 0; trial < 50; ++trial) {
    for (int k = 0; k < 20; ++k)
      model.step(state, -0.1 + 0.7 * unit(rng) * 0.999);
    EXPECT_EQ(model.step(state, -0.1), y_before);
    ASSERT_EQ(state.size, before.size);  // the excursion's extrema are wiped out
    for (std::size_t t = 0; t < state.size; ++t)
      ASSERT_EQ(state.extrema[t], before.extrema[t]);
    model.step(state, 0.0);
  }
}

TEST(Preisach, CongruentMinorLoopsForRandomHistories) {
  const Preisach model(grid_params(25, random_weights(25, 23)));
  const double u1 = -0.37;
  const double u2 = 0.29;
  const double rise = 2 * model.everett()(u2, u1);
  for (std::uint64_t seed : {1U, 2U, 3U, 4U, 5U}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    auto state = model.initial_state();
    simulate(model, state, test::random_walk(500, seed, 1.0, 0.2));
    // Go beyond both ends once so that the loop u1 <-> u2 nests inside the memory.
    simulate(model, state, std::vector<double>{0.95, -0.95, 0.9});
    const double bottom = model.step(state, u1);
    std::vector<double> branch_up;
    for (double v : {-0.2, 0.0, 0.1, u2})
      branch_up.push_back(model.step(state, v) - bottom);
    EXPECT_NEAR(branch_up.back(), rise, 1e-12);
    EXPECT_NEAR(model.step(state, u1), bottom, 1e-12);
    // The same branch from another history is the same up to a vertical offset.
    auto other = model.make_state(PreisachInitialState::positive_saturation);
    simulate(model, other, std::vector<double>{-0.9, 0.8, -0.6, 0.5});
    const double other_bottom = model.step(other, u1);
    std::size_t k = 0;
    for (double v : {-0.2, 0.0, 0.1, u2})
      EXPECT_NEAR(model.step(other, v) - other_bottom, branch_up[k++], 1e-12);
  }
}

// ---------------------------------------------------------------------------------------------
// The running sums: no drift, recomputed formula agrees after a million samples

TEST(Preisach, RunningSumsAgreeWithTheRecomputedFormulaAfterAMillionSamples) {
  for (std::size_t levels : {21U, 101U}) {
    SCOPED_TRACE(testing::Message() << "N = " << levels);
    const Preisach model(grid_params(levels, random_weights(levels, levels),
                                     PreisachGridLayout::cell_centred,
                                     PreisachInitialState::demagnetised, 3.0));
    auto state = model.initial_state();
    const auto v = test::random_walk(1'000'000, levels, 1.0, 0.05);
    double worst = 0;
    std::size_t deepest = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double y = model.step(state, v[k]);
      deepest = std::max(deepest, state.size);
      if (k % 997 == 0 || k + 1 == v.size()) {
        worst = std::max(worst, std::abs(y - model.output(state)));
        ASSERT_NEAR(y, model.output(state), 1e-12 * model.total_weight()) << "k = " << k;
      }
    }
    EXPECT_EQ(state.truncations, 0U);
    RecordProperty("worst_difference", fmt::format("{:.2e}", worst));
    RecordProperty("deepest_memory", fmt::format("{}", deepest));
  }
}

// ---------------------------------------------------------------------------------------------
// The fixed-capacity memory

TEST(Preisach, FullMemoryDropsTheInnermostPair) {
  const Preisach model(grid_params(21, random_weights(21, 31)));
  auto state = model.initial_state();
  // Ever-shrinking oscillations: 400 nested loops around 0.
  std::vector<double> v;
  for (int k = 1; k <= 400; ++k) {
    const double a = 0.9 * std::pow(0.99, k);
    v.push_back(a);
    v.push_back(-a);
  }
  for (double x : v) {
    const double y = model.step(state, x);
    ASSERT_LE(state.size, PreisachState::capacity);
    ASSERT_NEAR(y, model.output(state), 1e-12 * model.total_weight());
  }
  EXPECT_GE(state.size, PreisachState::capacity - 1);
  EXPECT_GT(state.truncations, 0U);
  // The memory stays nested and alternating: it round-trips through make_state().
  const auto copy =
      model.make_state(PreisachInitialState::negative_saturation, state.memory(), state.input);
  EXPECT_EQ(model.output(copy), model.output(state));
  // A large input wipes the whole memory, as ever.
  model.step(state, 0.95);
  model.step(state, -0.95);
  EXPECT_EQ(state.size, 2U);
}

// ---------------------------------------------------------------------------------------------
// State handling

TEST(Preisach, PreviewEqualsAStepOnACopy) {
  const Preisach model(grid_params(21, random_weights(21, 41)));
  auto state = model.initial_state();
  const auto v = test::random_walk(2000, 41, 1.2, 0.3);
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> trial(-1.3, 1.3);
  for (double x : v) {
    for (int k = 0; k < 3; ++k) {
      const double u = trial(rng);
      auto copy = state;
      ASSERT_EQ(model.preview(state, u), model.step(copy, u)) << "u = " << u;
    }
    model.step(state, x);
  }
}

TEST(Preisach, StatesRoundTripThroughTheirStoredForm) {
  const Preisach model(grid_params(21, random_weights(21, 43)));
  for (auto start :
       {PreisachInitialState::negative_saturation, PreisachInitialState::positive_saturation}) {
    auto state = model.make_state(start);
    for (double x : test::random_walk(777, 43, 0.99, 0.3)) {
      model.step(state, x);
      const auto copy = model.make_state(start, state.memory(), state.input);
      ASSERT_EQ(copy.size, state.size);
      for (std::size_t t = 0; t < state.size; ++t)
        ASSERT_EQ(copy.partial[t], state.partial[t]);
    }
  }
  const auto fresh = model.make_state(PreisachInitialState::negative_saturation, {},
                                      -std::numeric_limits<double>::infinity());
  EXPECT_EQ(model.output(fresh), -model.total_weight());
}

TEST(Preisach, InitialStatesAndSaturationReset) {
  const Preisach model(grid_params(21, uniform_relay_weights(21, 1.0),
                                   PreisachGridLayout::cell_centred,
                                   PreisachInitialState::positive_saturation, 1.0));
  auto state = model.initial_state();
  EXPECT_EQ(model.output(state), 232.0);
  EXPECT_TRUE(state.from_positive_saturation());
  EXPECT_EQ(model.step(state, -2.0), -230.0);
  EXPECT_FALSE(state.from_positive_saturation());
  EXPECT_EQ(state.size, 1U);
  EXPECT_EQ(model.step(state, 3.0), 232.0);
  EXPECT_TRUE(state.from_positive_saturation());
}

TEST(Preisach, ADefaultConstructedStateIsNegativeSaturation) {
  const Preisach model(grid_params(21, random_weights(21, 47)));
  PreisachState fresh;
  auto initial = model.make_state(PreisachInitialState::negative_saturation);
  EXPECT_EQ(model.output(fresh), model.output_min());
  for (double v : test::random_walk(300, 47, 1.1, 0.3))
    ASSERT_EQ(model.step(fresh, v), model.step(initial, v));
}

TEST(Preisach, EnumerationsConvertToAndFromText) {
  for (auto s : {PreisachInitialState::negative_saturation,
                 PreisachInitialState::positive_saturation, PreisachInitialState::demagnetised}) {
    EXPECT_EQ(preisach_initial_state_from_string(to_string(s)), s);
  }
  for (auto l : {PreisachGridLayout::cell_centred, PreisachGridLayout::endpoints})
    EXPECT_EQ(preisach_grid_layout_from_string(to_string(l)), l);
  EXPECT_HYST_ERROR(preisach_initial_state_from_string("virgin"),
                    "unknown Preisach initial state 'virgin'");
  EXPECT_HYST_ERROR(preisach_grid_layout_from_string("centred"),
                    "unknown Preisach grid layout 'centred'");
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST(Preisach, RejectsBadParameters) {
  const auto with = [](auto change) {
    auto p = grid_params(3, uniform_relay_weights(3, 1.0));
    change(p);
    return p;
  };
  EXPECT_HYST_ERROR(Preisach(with([](auto& p) { p.everett.levels = 0; })),
                    "Preisach levels N = 0 must be in 1 .. 4096");
  EXPECT_HYST_ERROR(Preisach(with([](auto& p) { p.everett.weights.pop_back(); })),
                    "Preisach has 5 relay weights but N = 3 levels need N(N+1)/2 = 6");
  EXPECT_HYST_ERROR(Preisach(with([](auto& p) { p.everett.weights[4] = -0.1; })),
                    "Preisach relay weight mu[4] (i = 2, j = 1) = -0.1 must be >= 0");
  EXPECT_HYST_ERROR(Preisach(with([](auto& p) { p.everett.weights[2] = NAN; })),
                    "Preisach relay weight mu[2] (i = 1, j = 1) = nan is not finite");
  EXPECT_HYST_ERROR(Preisach(with([](auto& p) { p.everett.upper = -2; })),
                    "Preisach upper = -2 must be > lower = -1");
  EXPECT_HYST_ERROR(Preisach(with([](auto& p) { p.everett.lower = -INFINITY; })),
                    "Preisach lower = -inf is not finite");
  EXPECT_HYST_ERROR(Preisach(with([](auto& p) { p.offset = NAN; })),
                    "Preisach offset = nan is not finite");
  EXPECT_HYST_ERROR(Preisach(with([](auto& p) {
                      p.everett.levels = 1;
                      p.everett.weights = {1.0};
                      p.everett.layout = PreisachGridLayout::endpoints;
                    })),
                    "Preisach levels N = 1 must be >= 2 for the endpoints layout");
  EXPECT_HYST_ERROR(PreisachRelayGrid(with([](auto& p) { p.everett.weights[0] = -1; })),
                    "Preisach relay weight mu[0] (i = 0, j = 0) = -1 must be >= 0");
  EXPECT_HYST_ERROR(uniform_relay_weights(3, -1.0), "uniform relay weight = -1");
}

TEST(Preisach, ErrorsNameTheOffendingField) {
  const auto field_of = [](Preisach::Params params) -> std::string {
    try {
      Preisach model(std::move(params));
    } catch (const Error& error) {
      return error.field();
    }
    return "no error";
  };
  auto p = grid_params(3, uniform_relay_weights(3, 1.0));
  p.everett.weights[4] = -1;
  EXPECT_EQ(field_of(p), "weights[4]");
  p = grid_params(3, uniform_relay_weights(3, 1.0));
  p.everett.weights.push_back(1);
  EXPECT_EQ(field_of(p), "weights");
  p = grid_params(3, uniform_relay_weights(3, 1.0));
  p.everett.upper = -1;
  EXPECT_EQ(field_of(p), "upper");
  p = grid_params(3, uniform_relay_weights(3, 1.0));
  p.offset = INFINITY;
  EXPECT_EQ(field_of(p), "offset");
}

TEST(Preisach, RejectsInconsistentStates) {
  const Preisach model(grid_params(5, uniform_relay_weights(5, 1.0)));
  const auto neg = PreisachInitialState::negative_saturation;
  EXPECT_HYST_ERROR(model.make_state(PreisachInitialState::demagnetised, {}, 0.0),
                    "must start at negative_saturation or positive_saturation");
  EXPECT_HYST_ERROR(model.make_state(neg, std::vector<double>{0.5, 0.6}, 0.55),
                    "memory[1] = 0.6 must be below the extremum before it (0.5)");
  EXPECT_HYST_ERROR(model.make_state(neg, std::vector<double>{0.5, -0.5, 0.7}, 0.0),
                    "memory[2] = 0.7 must be below the maximum before it (0.5)");
  EXPECT_HYST_ERROR(model.make_state(neg, std::vector<double>{0.5, -0.5, 0.3, -0.6}, -0.55),
                    "memory[3] = -0.6 must be above the minimum before it (-0.5)");
  EXPECT_HYST_ERROR(model.make_state(neg, std::vector<double>{1.5}, 0.0),
                    "memory[0] = 1.5 must be finite and in the input range [-1, 1]");
  EXPECT_HYST_ERROR(model.make_state(neg, std::vector<double>{0.5, -0.5}, 0.6),
                    "input = 0.6 must lie at or above the last extremum -0.5 and below the one "
                    "before it (0.5)");
  EXPECT_HYST_ERROR(model.make_state(neg, std::vector<double>{0.5}, NAN),
                    "input = nan must be finite");
}

}  // namespace
}  // namespace hyst
