#include "hyst/signals/generators.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"

namespace hyst::signals {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

void expect_all_finite(const std::vector<double>& v) {
  for (std::size_t k = 0; k < v.size(); ++k)
    ASSERT_TRUE(std::isfinite(v[k])) << "k = " << k;
}

// Times of the sign changes of v - level, by linear interpolation between samples.
std::vector<double> crossings(const std::vector<double>& v, double dt, double level = 0.0) {
  std::vector<double> t;
  for (std::size_t k = 1; k < v.size(); ++k) {
    const double a = v[k - 1] - level;
    const double b = v[k] - level;
    if ((a < 0.0 && b >= 0.0) || (a > 0.0 && b <= 0.0)) {
      t.push_back((static_cast<double>(k - 1) + a / (a - b)) * dt);
    }
  }
  return t;
}

// Largest |v - level| within each period of `period_samples` samples.
std::vector<double> peak_per_cycle(const std::vector<double>& v, std::size_t period_samples,
                                   double level) {
  std::vector<double> peaks;
  for (std::size_t start = 0; start + period_samples <= v.size(); start += period_samples) {
    double peak = 0.0;
    for (std::size_t k = start; k < start + period_samples; ++k) {
      peak = std::max(peak, std::abs(v[k] - level));
    }
    peaks.push_back(peak);
  }
  return peaks;
}

// ---- Reference values: hand calculation and closed forms -------------------------------------

TEST(TimeGridTest, TimesAreMultiplesOfDt) {
  EXPECT_EQ(times(TimeGrid{4, 0.5}), (std::vector<double>{0.0, 0.5, 1.0, 1.5}));
  EXPECT_EQ(times(TimeGrid{1, 3.0}), (std::vector<double>{0.0}));
}

TEST(SineTest, QuarterAndHalfPeriodValues) {
  // f = 2 Hz, dt = 1/16 s: t = 1/8 is a quarter period, 1/4 a half period, 3/8 three quarters.
  const auto v =
      generate(TimeGrid{17, 1.0 / 16}, Sine{.amplitude = 3, .frequency = 2, .offset = 1});
  ASSERT_EQ(v.size(), 17u);
  EXPECT_DOUBLE_EQ(v[0], 1.0);
  EXPECT_DOUBLE_EQ(v[2], 4.0);
  EXPECT_NEAR(v[4], 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(v[6], -2.0);
  EXPECT_NEAR(v[16], 1.0, 1e-15);
  EXPECT_NEAR(v[1], 1.0 + 3.0 * std::sqrt(0.5), 1e-15);
}

TEST(SineTest, PhaseHalfPiIsACosine) {
  const auto v =
      generate(TimeGrid{100, 0.01}, Sine{.amplitude = 2, .frequency = 1.5, .phase = kPi / 2});
  for (std::size_t k = 0; k < v.size(); ++k) {
    EXPECT_NEAR(v[k], 2.0 * std::cos(2 * kPi * 1.5 * 0.01 * static_cast<double>(k)), 1e-14) << k;
  }
}

TEST(SineTest, ZeroFrequencyIsTheConstantOffsetPlusPhaseTerm) {
  const auto v = generate(TimeGrid{5, 1.0},
                          Sine{.amplitude = 2, .frequency = 0, .phase = kPi / 2, .offset = -1});
  for (double x : v)
    EXPECT_DOUBLE_EQ(x, 1.0);
}

TEST(TriangleTest, PeaksAndZeroCrossingsAtQuarterPeriods) {
  const auto v = generate(TimeGrid{9, 1.0 / 8}, Triangle{.amplitude = 2, .frequency = 1});
  EXPECT_EQ(v, (std::vector<double>{0, 1, 2, 1, 0, -1, -2, -1, 0}));
}

TEST(TriangleTest, LinearBetweenPeaksWithSlopeFourAf) {
  // A = 1.5, f = 0.5 Hz: slope 4 A f = 3 per second on the rising quarter [0, 0.5 s].
  const auto v =
      generate(TimeGrid{51, 0.01}, Triangle{.amplitude = 1.5, .frequency = 0.5, .offset = 2});
  for (std::size_t k = 0; k <= 50; ++k) {
    EXPECT_NEAR(v[k], 2.0 + 3.0 * 0.01 * static_cast<double>(k), 1e-13) << k;
  }
}

TEST(TriangleTest, SamePhaseConventionAsSine) {
  const TimeGrid grid{2001, 0.001};
  for (double phase : {0.0, 0.7, kPi / 2, -2.0}) {
    SCOPED_TRACE(testing::Message() << "phase " << phase);
    const auto tri = generate(grid, Triangle{.frequency = 2, .phase = phase});
    const auto sine = generate(grid, Sine{.frequency = 2, .phase = phase});
    const auto a = crossings(tri, grid.dt);
    const auto b = crossings(sine, grid.dt);
    ASSERT_EQ(a.size(), b.size());
    // Linear interpolation finds the triangle's crossings exactly, the sine's to O(dt^3).
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR(a[i], b[i], 1e-8) << i;
    }
    // Peaks of the sine (phase + 2 pi f t = pi/2) are peaks of the triangle.
    const double t_peak = (kPi / 2 - phase + 2 * kPi) / (2 * kPi * 2);
    EXPECT_NEAR(generate(TimeGrid{2, t_peak}, Triangle{.frequency = 2, .phase = phase})[1], 1.0,
                1e-12);
  }
  // Phase pi/2 starts at the positive peak.
  EXPECT_DOUBLE_EQ(generate(grid, Triangle{.amplitude = 3, .phase = kPi / 2})[0], 3.0);
}

TEST(DecayingSineTest, EnvelopeAtThePeaks) {
  // f = 1 Hz, dt = 1/4 s: samples 1, 5, 9, ... are the peaks sin = 1, so v = A e^{-t/tau} + c.
  const DecayingSine signal{.amplitude = 2, .frequency = 1, .time_constant = 3, .offset = 0.5};
  const auto v = generate(TimeGrid{41, 0.25}, signal);
  for (std::size_t k = 1; k < v.size(); k += 4) {
    const double t = 0.25 * static_cast<double>(k);
    EXPECT_NEAR(v[k], 0.5 + 2.0 * std::exp(-t / 3.0), 1e-14) << "t = " << t;
  }
  for (std::size_t k = 3; k < v.size(); k += 4) {  // troughs
    const double t = 0.25 * static_cast<double>(k);
    EXPECT_NEAR(v[k], 0.5 - 2.0 * std::exp(-t / 3.0), 1e-14) << "t = " << t;
  }
}

TEST(GrowingSineTest, EnvelopeAtThePeaksStartsFromZero) {
  const GrowingSine signal{.amplitude = 2, .frequency = 1, .time_constant = 3, .offset = 0.5};
  const auto v = generate(TimeGrid{41, 0.25}, signal);
  EXPECT_DOUBLE_EQ(v[0], 0.5);
  for (std::size_t k = 1; k < v.size(); k += 4) {
    const double t = 0.25 * static_cast<double>(k);
    EXPECT_NEAR(v[k], 0.5 + 2.0 * (1.0 - std::exp(-t / 3.0)), 1e-14) << "t = " << t;
  }
}

TEST(MultisineTest, OneComponentEqualsSine) {
  const TimeGrid grid{500, 0.003};
  EXPECT_EQ(
      generate(grid, Multisine{{1.7}, {0.8}, {0.4}, -0.25}),
      generate(grid, Sine{.amplitude = 0.8, .frequency = 1.7, .phase = 0.4, .offset = -0.25}));
  // The one Schroeder phase is -pi 1 (1 - 1) / 1 = 0.
  EXPECT_EQ(generate(grid, Multisine{{1.7}, {0.8}, {}, 0.0}),
            generate(grid, Sine{.amplitude = 0.8, .frequency = 1.7}));
}

TEST(MultisineTest, IsTheSumOfItsComponents) {
  const TimeGrid grid{300, 0.01};
  const auto v = generate(grid, Multisine{{1, 2.5, 7}, {1, -0.5, 0.25}, {0, 1, 2}, 3});
  const auto a = generate(grid, Sine{.amplitude = 1, .frequency = 1, .phase = 0});
  const auto b = generate(grid, Sine{.amplitude = -0.5, .frequency = 2.5, .phase = 1});
  const auto c = generate(grid, Sine{.amplitude = 0.25, .frequency = 7, .phase = 2});
  for (std::size_t k = 0; k < v.size(); ++k)
    EXPECT_NEAR(v[k], 3 + a[k] + b[k] + c[k], 1e-14) << k;
}

TEST(MultisineTest, EmptyPhasesMeanSchroederPhases) {
  const TimeGrid grid{400, 0.005};
  // phi_k = -pi k (k-1) / K for K = 3: 0, -2 pi / 3, -2 pi.
  const auto schroeder = generate(grid, Multisine{{1, 2, 3}, {1, 1, 1}, {}, 0});
  const auto explicit_phases =
      generate(grid, Multisine{{1, 2, 3}, {1, 1, 1}, {0, -2 * kPi / 3, -2 * kPi}, 0});
  for (std::size_t k = 0; k < grid.samples; ++k) {
    EXPECT_NEAR(schroeder[k], explicit_phases[k], 1e-13) << k;
  }
}

TEST(MultisineTest, SchroederPhasesGiveALowCrestFactor) {
  // 16 harmonics of 1 Hz with equal amplitudes: in phase (cosines) the peak is 16; Schroeder
  // phases spread the energy over the period (crest factor about 1.7 instead of sqrt(32) = 5.7).
  const std::size_t count = 16;
  std::vector<double> f(count), a(count, 1.0), cosine(count, kPi / 2);
  for (std::size_t i = 0; i < count; ++i)
    f[i] = static_cast<double>(i + 1);
  const TimeGrid one_period{4000, 1.0 / 4000};
  const auto peak = [](const std::vector<double>& v) {
    double m = 0;
    for (double x : v)
      m = std::max(m, std::abs(x));
    return m;
  };
  EXPECT_NEAR(peak(generate(one_period, Multisine{f, a, cosine, 0})), 16.0, 1e-9);
  const double rms = std::sqrt(static_cast<double>(count) / 2);
  EXPECT_LT(peak(generate(one_period, Multisine{f, a, {}, 0})) / rms, 2.0);
}

TEST(ChirpTest, InstantaneousFrequencyFromZeroCrossingSpacing) {
  // 1 Hz -> 10 Hz over T = 10 s: f(t) = 1 + 0.9 t. Successive zero crossings are half an
  // instantaneous period apart, so f(t_mid) ~ 1 / (2 spacing).
  const TimeGrid grid{100001, 1e-4};
  const auto v = generate(grid, Chirp{.amplitude = 1, .start_frequency = 1, .end_frequency = 10});
  expect_all_finite(v);
  const auto t = crossings(v, grid.dt);
  // 2 pi (t + 0.45 t^2) = n pi has 110 solutions in (0, 10].
  ASSERT_GE(t.size(), 109u);
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double mid = 0.5 * (t[i] + t[i - 1]);
    const double estimate = 1.0 / (2.0 * (t[i] - t[i - 1]));
    EXPECT_NEAR(estimate, 1.0 + 0.9 * mid, 1e-3 * (1.0 + 0.9 * mid)) << "t = " << mid;
  }
  EXPECT_DOUBLE_EQ(v[0], 0.0);
}

TEST(ChirpTest, DownwardSweepAndConstantFrequency) {
  const TimeGrid grid{20001, 1e-3};  // T = 20 s
  const auto down = generate(grid, Chirp{.start_frequency = 5, .end_frequency = 1});
  const auto t = crossings(down, grid.dt);
  ASSERT_GE(t.size(), 119u);  // 2 pi (5 t - 0.1 t^2) = n pi: 120 solutions in (0, 20]
  double previous = 5.0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double mid = 0.5 * (t[i] + t[i - 1]);
    const double estimate = 1.0 / (2.0 * (t[i] - t[i - 1]));
    EXPECT_NEAR(estimate, 5.0 - 0.2 * mid, 1e-3) << "t = " << mid;
    EXPECT_LT(estimate, previous);
    previous = estimate;
  }
  // Equal start and end frequencies give a sine.
  const TimeGrid short_grid{300, 0.01};
  EXPECT_EQ(
      generate(
          short_grid,
          Chirp{
              .amplitude = 2, .start_frequency = 3, .end_frequency = 3, .phase = 0.2, .offset = 1}),
      generate(short_grid, Sine{.amplitude = 2, .frequency = 3, .phase = 0.2, .offset = 1}));
  // One sample: no duration, no sweep.
  EXPECT_EQ(generate(TimeGrid{1, 0.1}, Chirp{.offset = 4}), std::vector<double>{4.0});
}

// Values from an independent Python implementation of MT19937-64 (checked against the C++
// standard's requirement that the 10000th draw for seed 5489 is 9981545732273789042) and the
// walk rule u = (x >> 11) 2^-53, s = max_step (2u - 1), reflection at the bounds.
TEST(RandomWalkTest, MatchesReferenceSequence) {
  const auto v =
      generate(TimeGrid{6, 1.0},
               RandomWalk{.max_step = 0.1, .lower = -1, .upper = 1, .start = 0, .seed = 1});
  EXPECT_EQ(v, (std::vector<double>{0.0, -0.07322467119749347, -0.14594326392425402,
                                    -0.1557002831553464, -0.251495437472001, -0.2813158147154171}));
}

TEST(RandomWalkTest, MatchesReferenceSequenceWithReflections) {
  // Reflections at the upper bound (steps 1 and 7) and the lower bound (steps 4 and 6).
  const auto v = generate(
      TimeGrid{8, 1.0}, RandomWalk{.max_step = 0.9, .lower = 0, .upper = 1, .start = 1, .seed = 4});
  EXPECT_EQ(v, (std::vector<double>{1.0, 0.4860130781280285, 0.4029066182635186, 0.5725577516716625,
                                    0.21528448874887451, 0.30165252006717735, 0.4968519542358508,
                                    0.8889726037649179}));
}

// ---- Properties ------------------------------------------------------------------------------

TEST(RandomWalkTest, StaysInBoundsWithStepsAtMostMaxStep) {
  for (std::uint64_t seed : {1u, 2u, 3u, 77u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const RandomWalk walk{.max_step = 0.7, .lower = -0.5, .upper = 0.5, .start = 0.5, .seed = seed};
    const auto v = generate(TimeGrid{20000, 1e-3}, walk);
    ASSERT_EQ(v.front(), 0.5);
    expect_all_finite(v);
    double low = v[0], high = v[0];
    for (std::size_t k = 0; k < v.size(); ++k) {
      ASSERT_GE(v[k], -0.5) << k;
      ASSERT_LE(v[k], 0.5) << k;
      if (k > 0) {
        ASSERT_LE(std::abs(v[k] - v[k - 1]), 0.7 + 1e-15) << k;
      }
      low = std::min(low, v[k]);
      high = std::max(high, v[k]);
    }
    EXPECT_LT(low, -0.45);  // it explores the whole range
    EXPECT_GT(high, 0.45);
  }
}

TEST(RandomWalkTest, SameSeedSameWalkOtherSeedOtherWalk) {
  const TimeGrid grid{1000, 1.0};
  const auto a = generate(grid, RandomWalk{.seed = 9});
  EXPECT_EQ(a, generate(grid, RandomWalk{.seed = 9}));
  const auto b = generate(grid, RandomWalk{.seed = 10});
  ASSERT_EQ(a.size(), b.size());
  std::size_t equal = 0;
  for (std::size_t k = 1; k < a.size(); ++k)
    equal += a[k] == b[k] ? 1 : 0;
  EXPECT_EQ(equal, 0u);
}

TEST(RandomWalkTest, ZeroStepStaysAtTheStart) {
  const auto v = generate(TimeGrid{50, 1.0}, RandomWalk{.max_step = 0, .start = -0.3});
  for (double x : v)
    EXPECT_EQ(x, -0.3);
}

TEST(DecayingSineTest, AmplitudeDecreasesCycleToCycleAndReversalsNest) {
  // Each reversal lies strictly inside the previous one of the same sign: nested minor loops.
  const double offset = 0.2;
  const std::size_t per_period = 200;
  const auto v = generate(
      TimeGrid{per_period * 30, 1.0 / per_period},
      DecayingSine{
          .amplitude = 1.5, .frequency = 1, .time_constant = 4, .phase = 0.3, .offset = offset});
  const auto peaks = peak_per_cycle(v, per_period, offset);
  ASSERT_EQ(peaks.size(), 30u);
  for (std::size_t i = 1; i < peaks.size(); ++i) {
    EXPECT_LT(peaks[i], peaks[i - 1]) << "cycle " << i;
    EXPECT_NEAR(peaks[i] / peaks[i - 1], std::exp(-1.0 / 4), 1e-10) << "cycle " << i;
  }
  std::vector<double> maxima, minima;
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    if (v[k] > v[k - 1] && v[k] >= v[k + 1]) maxima.push_back(v[k]);
    if (v[k] < v[k - 1] && v[k] <= v[k + 1]) minima.push_back(v[k]);
  }
  ASSERT_GE(maxima.size(), 29u);
  for (std::size_t i = 1; i < maxima.size(); ++i)
    EXPECT_LT(maxima[i], maxima[i - 1]) << i;
  for (std::size_t i = 1; i < minima.size(); ++i)
    EXPECT_GT(minima[i], minima[i - 1]) << i;
}

TEST(GrowingSineTest, AmplitudeIncreasesCycleToCycleTowardsA) {
  const std::size_t per_period = 100;
  const auto v = generate(TimeGrid{per_period * 20, 1.0 / per_period},
                          GrowingSine{.amplitude = 2, .frequency = 1, .time_constant = 2});
  const auto peaks = peak_per_cycle(v, per_period, 0.0);
  for (std::size_t i = 1; i < peaks.size(); ++i)
    EXPECT_GT(peaks[i], peaks[i - 1]) << i;
  EXPECT_LT(peaks.back(), 2.0);
  EXPECT_GT(peaks.back(), 2.0 * (1 - std::exp(-19.0 / 2)) - 1e-3);
}

TEST(GeneratorsTest, EveryGeneratorGivesFiniteSamplesOfTheGridSize) {
  const TimeGrid grid{12345, 1e-3};
  const std::vector<std::vector<double>> outputs{
      times(grid),
      generate(grid, Sine{}),
      generate(grid, Triangle{}),
      generate(grid, DecayingSine{}),
      generate(grid, GrowingSine{}),
      generate(grid, Multisine{{1, 3, 5}, {1, 0.5, 0.2}, {}, 0}),
      generate(grid, Chirp{}),
      generate(grid, RandomWalk{})};
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "generator " << i);
    EXPECT_EQ(outputs[i].size(), grid.samples);
    expect_all_finite(outputs[i]);
  }
  // Long times and large (finite) parameters stay finite too.
  const TimeGrid long_grid{1000, 1e6};
  expect_all_finite(generate(long_grid, Sine{.amplitude = 1e300, .frequency = 123.456}));
  expect_all_finite(generate(long_grid, Triangle{.amplitude = 1e300, .frequency = 123.456}));
  expect_all_finite(generate(long_grid, DecayingSine{.amplitude = 1e300, .time_constant = 1e-300}));
  expect_all_finite(generate(long_grid, GrowingSine{.amplitude = 1e300, .time_constant = 1e300}));
  expect_all_finite(generate(long_grid, Chirp{.start_frequency = 0, .end_frequency = 1e6}));
  expect_all_finite(generate(
      long_grid, RandomWalk{.max_step = 1e308, .lower = -1e308, .upper = 1.5e308, .start = 1e308}));
}

// ---- Seeded randomized cases -----------------------------------------------------------------

TEST(GeneratorsTest, RandomParametersStayWithinTheirAmplitudeBounds) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 rng(seed);
    const auto uniform = [&](double lo, double hi) {
      return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
    };
    const TimeGrid grid{1 + rng() % 3000, uniform(1e-4, 0.1)};
    const double a = uniform(-5, 5), f = uniform(0, 20), phase = uniform(-10, 10);
    const double c = uniform(-3, 3), tau = uniform(0.01, 10);
    const double slack = 1e-12 * (1 + std::abs(c));
    const auto within = [&](const std::vector<double>& v, double bound) {
      ASSERT_EQ(v.size(), grid.samples);
      expect_all_finite(v);
      for (double x : v)
        ASSERT_LE(std::abs(x - c), bound + slack);
    };
    within(generate(grid, Sine{a, f, phase, c}), std::abs(a));
    within(generate(grid, Triangle{a, f, phase, c}), std::abs(a));
    within(generate(grid, DecayingSine{a, f, tau, phase, c}), std::abs(a));
    within(generate(grid, GrowingSine{a, f, tau, phase, c}), std::abs(a));
    within(generate(grid, Chirp{a, f, uniform(0, 20), phase, c}), std::abs(a));

    Multisine multi;
    multi.offset = c;
    double sum = 0;
    for (std::size_t i = 0, n = 1 + rng() % 8; i < n; ++i) {
      multi.frequencies.push_back(uniform(0, 50));
      multi.amplitudes.push_back(uniform(-2, 2));
      sum += std::abs(multi.amplitudes.back());
    }
    within(generate(grid, multi), sum);

    const double lower = uniform(-5, 0), upper = lower + uniform(0.1, 5);
    const RandomWalk walk{uniform(0, 0.99) * (upper - lower), lower, upper, uniform(lower, upper),
                          rng()};
    const auto w = generate(grid, walk);
    expect_all_finite(w);
    EXPECT_EQ(w, generate(grid, walk));
    for (double x : w) {
      ASSERT_GE(x, lower);
      ASSERT_LE(x, upper);
    }
  }
}

// ---- Invalid input: every rule, with its message ---------------------------------------------

TEST(GeneratorsErrorTest, TimeGrid) {
  EXPECT_HYST_ERROR(times(TimeGrid{0, 1.0}), "time grid samples = 0 must be >= 1");
  EXPECT_HYST_ERROR(times(TimeGrid{10, 0.0}), "time grid dt = 0 must be > 0");
  EXPECT_HYST_ERROR(times(TimeGrid{10, -1.0}), "time grid dt = -1 must be > 0");
  EXPECT_HYST_ERROR(times(TimeGrid{10, kNan}), "time grid dt = nan is not finite");
  EXPECT_HYST_ERROR(times(TimeGrid{10, kInf}), "time grid dt = inf is not finite");
  EXPECT_HYST_ERROR(times(TimeGrid{3, 1e308}), "time grid output[2] = inf is not finite");
  // Every generator validates the grid.
  EXPECT_HYST_ERROR(generate(TimeGrid{}, Sine{}), "time grid samples = 0 must be >= 1");
  EXPECT_HYST_ERROR(generate(TimeGrid{5, 0}, Triangle{}), "time grid dt = 0 must be > 0");
  EXPECT_HYST_ERROR(generate(TimeGrid{}, DecayingSine{}), "time grid samples = 0");
  EXPECT_HYST_ERROR(generate(TimeGrid{}, GrowingSine{}), "time grid samples = 0");
  EXPECT_HYST_ERROR(generate(TimeGrid{}, Multisine{{1}, {1}, {}, 0}), "time grid samples = 0");
  EXPECT_HYST_ERROR(generate(TimeGrid{}, Chirp{}), "time grid samples = 0");
  EXPECT_HYST_ERROR(generate(TimeGrid{5, -2}, RandomWalk{}), "time grid dt = -2 must be > 0");
}

TEST(GeneratorsErrorTest, Sine) {
  const TimeGrid g{10, 0.1};
  EXPECT_HYST_ERROR(generate(g, Sine{.amplitude = kNan}), "sine amplitude = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, Sine{.frequency = -1}), "sine frequency = -1 must be >= 0");
  EXPECT_HYST_ERROR(generate(g, Sine{.frequency = kInf}), "sine frequency = inf is not finite");
  EXPECT_HYST_ERROR(generate(g, Sine{.phase = -kInf}), "sine phase = -inf is not finite");
  EXPECT_HYST_ERROR(generate(g, Sine{.offset = kNan}), "sine offset = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, Sine{.amplitude = 1e308, .phase = kPi / 2, .offset = 1e308}),
                    "sine output[0] = inf is not finite");
}

TEST(GeneratorsErrorTest, Triangle) {
  const TimeGrid g{10, 0.1};
  EXPECT_HYST_ERROR(generate(g, Triangle{.amplitude = kInf}),
                    "triangle amplitude = inf is not finite");
  EXPECT_HYST_ERROR(generate(g, Triangle{.frequency = -2}), "triangle frequency = -2 must be >= 0");
  EXPECT_HYST_ERROR(generate(g, Triangle{.phase = kNan}), "triangle phase = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, Triangle{.offset = kInf}), "triangle offset = inf is not finite");
}

TEST(GeneratorsErrorTest, DecayingAndGrowingSine) {
  const TimeGrid g{10, 0.1};
  EXPECT_HYST_ERROR(generate(g, DecayingSine{.time_constant = -1}),
                    "decaying sine time_constant = -1 must be > 0");
  EXPECT_HYST_ERROR(generate(g, DecayingSine{.time_constant = 0}),
                    "decaying sine time_constant = 0 must be > 0");
  EXPECT_HYST_ERROR(generate(g, DecayingSine{.time_constant = kInf}),
                    "decaying sine time_constant = inf is not finite");
  EXPECT_HYST_ERROR(generate(g, DecayingSine{.amplitude = kNan}),
                    "decaying sine amplitude = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, DecayingSine{.frequency = -0.5}),
                    "decaying sine frequency = -0.5 must be >= 0");
  EXPECT_HYST_ERROR(generate(g, DecayingSine{.phase = kInf}),
                    "decaying sine phase = inf is not finite");
  EXPECT_HYST_ERROR(generate(g, DecayingSine{.offset = kNan}),
                    "decaying sine offset = nan is not finite");

  EXPECT_HYST_ERROR(generate(g, GrowingSine{.time_constant = 0}),
                    "growing sine time_constant = 0 must be > 0");
  EXPECT_HYST_ERROR(generate(g, GrowingSine{.time_constant = kNan}),
                    "growing sine time_constant = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, GrowingSine{.amplitude = kInf}),
                    "growing sine amplitude = inf is not finite");
  EXPECT_HYST_ERROR(generate(g, GrowingSine{.frequency = -3}),
                    "growing sine frequency = -3 must be >= 0");
  EXPECT_HYST_ERROR(generate(g, GrowingSine{.phase = kNan}),
                    "growing sine phase = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, GrowingSine{.offset = -kInf}),
                    "growing sine offset = -inf is not finite");
}

TEST(GeneratorsErrorTest, Multisine) {
  const TimeGrid g{10, 0.1};
  EXPECT_HYST_ERROR(generate(g, Multisine{}), "multisine frequencies is empty");
  EXPECT_HYST_ERROR(generate(g, Multisine{{1, 2}, {1}, {}, 0}),
                    "multisine amplitudes has 1 entries but frequencies has 2; they must have the "
                    "same length");
  EXPECT_HYST_ERROR(generate(g, Multisine{{1, 2}, {1, 1}, {0}, 0}),
                    "multisine phases has 1 entries but frequencies has 2; it must be empty");
  EXPECT_HYST_ERROR(generate(g, Multisine{{1, -3}, {1, 1}, {}, 0}),
                    "multisine frequencies[1] = -3 must be >= 0");
  EXPECT_HYST_ERROR(generate(g, Multisine{{kNan}, {1}, {}, 0}),
                    "multisine frequencies[0] = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, Multisine{{1, 2}, {kNan, 1}, {}, 0}),
                    "multisine amplitudes[0] = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, Multisine{{1, 2}, {1, 1}, {0, kInf}, 0}),
                    "multisine phases[1] = inf is not finite");
  EXPECT_HYST_ERROR(generate(g, Multisine{{1}, {1}, {}, kNan}),
                    "multisine offset = nan is not finite");
}

TEST(GeneratorsErrorTest, Chirp) {
  const TimeGrid g{10, 0.1};
  EXPECT_HYST_ERROR(generate(g, Chirp{.amplitude = kInf}), "chirp amplitude = inf is not finite");
  EXPECT_HYST_ERROR(generate(g, Chirp{.start_frequency = -1}),
                    "chirp start_frequency = -1 must be >= 0");
  EXPECT_HYST_ERROR(generate(g, Chirp{.end_frequency = -2}),
                    "chirp end_frequency = -2 must be >= 0");
  EXPECT_HYST_ERROR(generate(g, Chirp{.end_frequency = kNan}),
                    "chirp end_frequency = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, Chirp{.phase = kNan}), "chirp phase = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, Chirp{.offset = kInf}), "chirp offset = inf is not finite");
}

TEST(GeneratorsErrorTest, RandomWalk) {
  const TimeGrid g{10, 1.0};
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.lower = 1, .upper = 1}),
                    "random walk lower = 1 must be < upper = 1");
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.lower = 2, .upper = 1}),
                    "random walk lower = 2 must be < upper = 1");
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.start = 2}),
                    "random walk start = 2 must be in [lower, upper] = [-1, 1]");
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.start = -1.5}),
                    "random walk start = -1.5 must be in [lower, upper] = [-1, 1]");
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.max_step = -0.1}),
                    "random walk max_step = -0.1 must be >= 0");
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.max_step = 2}),
                    "random walk max_step = 2 must be < upper - lower = 2");
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.max_step = kNan}),
                    "random walk max_step = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.lower = -kInf}),
                    "random walk lower = -inf is not finite");
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.upper = kNan}),
                    "random walk upper = nan is not finite");
  EXPECT_HYST_ERROR(generate(g, RandomWalk{.start = kInf}),
                    "random walk start = inf is not finite");
}

}  // namespace
}  // namespace hyst::signals
