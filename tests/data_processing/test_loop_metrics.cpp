// Loop figures against analytic values: the sampled ellipse x = A sin t, y = B sin(t - phi) has
// polygon area (N/2) sin(2 pi/N) A B sin(phi) (an affine image of a regular N-gon), coercive
// inputs +-A sin(phi) and remanent outputs +-B sin(phi).

#include "hyst/data/loop_metrics.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/data/cycles.hpp"
#include "hyst/data/reversal_points.hpp"
#include "hyst/io/aixacct.hpp"
#include "synthetic_records.hpp"

namespace hyst::data {
namespace {

constexpr double kPi = std::numbers::pi;

struct Ellipse {
  std::vector<double> x, y;
};

// `periods` periods of N samples at t = 2 pi (k + 1/2) / N (no sample exactly on an axis).
Ellipse ellipse(double a, double b, double phi, std::size_t n, std::size_t periods) {
  Ellipse e;
  for (std::size_t k = 0; k < n * periods; ++k) {
    const double t = 2.0 * kPi * (static_cast<double>(k) + 0.5) / static_cast<double>(n);
    e.x.push_back(a * std::sin(t));
    e.y.push_back(b * std::sin(t - phi));
  }
  return e;
}

TEST(LoopArea, SampledEllipseMatchesThePolygonFormula) {
  const double a = 2.0, b = 3.0, phi = 0.7;
  for (const std::size_t n : {7U, 100U, 4000U}) {
    const auto e = ellipse(a, b, phi, n, 1);
    const double nd = static_cast<double>(n);
    const double exact = nd / 2.0 * std::sin(2.0 * kPi / nd) * a * b * std::sin(phi);
    EXPECT_NEAR(loop_area(e.x, e.y), exact, 1e-12 * exact) << n;
  }
  // And tends to the ellipse's pi A B sin(phi); reversed traversal flips the sign.
  const auto fine = ellipse(a, b, phi, 4000, 1);
  EXPECT_NEAR(loop_area(fine.x, fine.y), kPi * a * b * std::sin(phi), 1e-5);
  const std::vector<double> rx(fine.x.rbegin(), fine.x.rend()), ry(fine.y.rbegin(), fine.y.rend());
  EXPECT_NEAR(loop_area(rx, ry), -loop_area(fine.x, fine.y), 1e-12);
}

TEST(LoopArea, UnitSquareCounterClockwiseIsOne) {
  EXPECT_DOUBLE_EQ(loop_area(std::vector<double>{0, 1, 1, 0}, std::vector<double>{0, 0, 1, 1}),
                   1.0);
}

TEST(LoopCrossings, EllipseCoerciveAndRemanentValues) {
  const double a = 2.0, b = 3.0, phi = 0.7;
  const auto e = ellipse(a, b, phi, 2000, 2);
  // Linear interpolation between samples 2 pi / 2000 apart: error below (dt^2 / 8) * amplitude.
  const double tolerance = 1e-5;
  const auto coercive = coercive_inputs(e.x, e.y);
  // y = 0 at t = phi (x rising), pi + phi (falling), 2 pi + phi, 3 pi + phi.
  ASSERT_EQ(coercive.size(), 4U);
  EXPECT_NEAR(coercive[0].value, a * std::sin(phi), tolerance);
  EXPECT_EQ(coercive[0].direction, Direction::ascending);
  EXPECT_NEAR(coercive[1].value, -a * std::sin(phi), tolerance);
  EXPECT_EQ(coercive[1].direction, Direction::descending);
  const auto remanent = remanent_outputs(e.x, e.y);
  // x = 0 at t = pi (falling: y = B sin phi), 2 pi (rising: -B sin phi), 3 pi.
  ASSERT_EQ(remanent.size(), 3U);
  EXPECT_NEAR(remanent[0].value, b * std::sin(phi), tolerance);
  EXPECT_EQ(remanent[0].direction, Direction::descending);
  EXPECT_NEAR(remanent[1].value, -b * std::sin(phi), tolerance);
  EXPECT_EQ(remanent[1].direction, Direction::ascending);
  EXPECT_EQ(remanent[1].index, 2000U - 1);  // between the last sample of period 1 and the next
  // Another level: the input where the output crosses B/2 on the way up: t = phi + pi/6.
  const auto half = coercive_inputs(e.x, e.y, b / 2.0);
  EXPECT_NEAR(half[0].value, a * std::sin(phi + kPi / 6.0), tolerance);
}

TEST(LoopMetrics, CyclesOfADriftingLoopReportTheirClosureError) {
  // A triangle input (cycles of 40 samples) and a parallelogram loop (the descending half of
  // each period 5 above the ascending one) plus a drift of 0.01 per sample.
  const auto input = test::triangle(10, 3);
  std::vector<double> output(input.size());
  const double drift = 0.01;  // per sample
  for (std::size_t k = 0; k < input.size(); ++k) {
    const std::size_t phase = k % 40;
    const double shift = (phase > 10 && phase < 30) ? 5.0 : (phase == 10 || phase == 30 ? 2.5 : 0);
    output[k] = input[k] + shift + drift * static_cast<double>(k);
  }
  const auto metrics = cycle_metrics(input, output, 1.5);
  ASSERT_EQ(metrics.size(), 3U);
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_EQ(metrics[j].first, 40 * j);
    EXPECT_NEAR(metrics[j].closure_error, 40 * drift, 1e-12);
    EXPECT_EQ(metrics[j].input_mismatch, 0.0);
    EXPECT_EQ(metrics[j].input_min, -10.0);
    EXPECT_EQ(metrics[j].input_max, 10.0);
  }
  const auto single = loop_metrics(input, output, 0, 40);
  EXPECT_NEAR(single.area, loop_area(std::span(input).first(41), std::span(output).first(41)),
              1e-12);
  // x leaves 0 at k = 0 (no crossing into it), reaches 0 falling at k = 20 and rising at k = 40.
  ASSERT_EQ(single.remanent.size(), 2U);
  EXPECT_EQ(single.remanent[0].index, 19U);
  EXPECT_EQ(single.remanent[0].direction, Direction::descending);
  EXPECT_NEAR(single.remanent[0].value, 5.0 + 20 * drift, 1e-12);
}

TEST(LoopMetrics, RejectsInvalidData) {
  const std::vector<double> x{0, 1, 0}, y{0, 1};
  EXPECT_HYST_ERROR(loop_area(x, y), "input");
  EXPECT_HYST_ERROR(loop_area(std::vector<double>{0, 1}, std::vector<double>{0, 1}), "at least 3");
  EXPECT_HYST_ERROR(loop_metrics(x, x, 1, 5), "loop samples 1..5");
  const std::vector<double> with_inf{0, INFINITY, 0};
  EXPECT_HYST_ERROR(coercive_inputs(x, with_inf), "output[1] = inf");
}

// The aixACCT analyser computes its own loop figures from each P(V) loop and stores them in the
// table's metadata (6 significant digits): Wloss = loop area [uJ/cm2 = V uC/cm2], Vc+/Vc- =
// coercive voltages, Pr+ = remanent polarisation on the descending branch. They are an independent
// reference for loop_metrics() on measured data. (Pr- is not compared: the instrument's value
// differs by 0.15..0.43 uC/cm2 from the rising branch's polarisation at V = 0 in every table; its
// definition is not documented in the file.)
TEST(LoopMetrics, MeasuredPolarisationLoopsMatchTheInstrumentsOwnFigures) {
  const auto file =
      io::read_aixacct(HYST_SHARED_DATA_DIR "/piezo_pzt_aixacct_butterfly/RMN_TRAP_SLOW.dat");
  ASSERT_EQ(file.measurements.size(), 10U);
  const auto close = [](double value, double reference) {
    return std::abs(value - reference) <= 1e-5 * std::abs(reference) + 1e-3;
  };
  for (const auto& table : file.measurements) {
    SCOPED_TRACE(table.number);
    const auto& v = table.column("V+").values;
    const auto& p = table.column("P1").values;
    // One period per table: one cycle, closed by the record end.
    const auto found = cycles(v, default_band(v));
    ASSERT_EQ(found.size(), 1U);
    EXPECT_TRUE(found[0].ends_at_record_end);
    const auto m = loop_metrics(v, p, 0, v.size() - 1);
    EXPECT_PRED2(close, m.area, *table.metadata_number("Wloss [uJ/cm2]"));
    ASSERT_EQ(m.coercive.size(), 2U);
    EXPECT_EQ(m.coercive[0].direction, Direction::ascending);
    EXPECT_PRED2(close, m.coercive[0].value, *table.metadata_number("Vc+ [V]"));
    EXPECT_PRED2(close, m.coercive[1].value, *table.metadata_number("Vc- [V]"));
    ASSERT_EQ(m.remanent.size(), 2U);
    EXPECT_EQ(m.remanent[0].direction, Direction::descending);
    EXPECT_PRED2(close, m.remanent[0].value, *table.metadata_number("Pr+ [uC/cm2]"));
  }
}

}  // namespace
}  // namespace hyst::data
