// A saved model on a record with its own time axis: rate-independent models ignore time, the
// creep models give the same physical prediction at any sample time (measured triangles of
// RMN_TRAP_SLOW.dat run 20 times coarser and finer, and its tables at their own sample times),
// a non-uniform record is stepped run by run, and a NARX refuses another sample time.

#include "hyst/registry/timed_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hyst/core/error.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

// The statement throws hyst::Error whose message contains every one of `texts`.
template <class Statement>
void expect_timed_error(Statement statement, std::initializer_list<const char*> texts) {
  try {
    statement();
    ADD_FAILURE() << "expected hyst::Error, nothing was thrown";
  } catch (const Error& error) {
    for (const char* text : texts)
      EXPECT_NE(std::string(error.what()).find(text), std::string::npos)
          << "message: " << error.what() << "\nexpected to contain: " << text;
  }
}

std::unique_ptr<DynamicModel> model_of(const char* name, const nlohmann::json& params) {
  return model_from_json({{"model", name}, {"version", 1}, {"params", params}}, "test");
}

std::vector<double> run(std::unique_ptr<DynamicModel> model, const data::TimeAxis& axis,
                        const std::vector<double>& input) {
  std::vector<double> output(input.size());
  simulate_on_time_axis(model, axis, input, output);
  return output;
}

// Linear interpolation of `v` at `factor` points per interval (the last sample kept).
std::vector<double> finer(const std::vector<double>& v, std::size_t factor) {
  std::vector<double> out;
  for (std::size_t k = 0; k + 1 < v.size(); ++k) {
    for (std::size_t i = 0; i < factor; ++i)
      out.push_back(v[k] + (v[k + 1] - v[k]) * static_cast<double>(i) / double(factor));
  }
  out.push_back(v.back());
  return out;
}

std::vector<double> every(const std::vector<double>& v, std::size_t step) {
  std::vector<double> out;
  for (std::size_t k = 0; k < v.size(); k += step)
    out.push_back(v[k]);
  return out;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double largest = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    largest = std::max(largest, std::abs(a[k] - b[k]));
  return largest;
}

double range_of(const std::vector<double>& v) {
  const auto [low, high] = std::minmax_element(v.begin(), v.end());
  return *high - *low;
}

const io::AixacctFile& trapezoid_file() {
  static const auto file =
      io::read_aixacct(HYST_SHARED_DATA_DIR "/piezo_pzt_aixacct_butterfly/RMN_TRAP_SLOW.dat");
  return file;
}

// pi_creep fitted on the polarisation of table 1 (0.1 Hz triangle, 25 ms), in its periodic state.
std::unique_ptr<DynamicModel> creep_fitted_on_table_1() {
  const auto& table = trapezoid_file().measurement(1);
  FitRequest request;
  request.input = table.column("V+").values;
  request.output = table.column("P1").values;
  request.options = {{"sample_time", 0.025}, {"lags", 5}, {"initial_state", "periodic"}};
  auto outcome = fit_model(ModelRegistry::builtin().find("pi_creep"), request);
  outcome.model->reset();  // from rest: the comparison needs no fitted state
  return std::move(outcome.model);
}

TEST(TimedSimulation, ARateIndependentModelIgnoresTime) {
  const auto pi = model_of("pi", {{"thresholds", {0.0, 0.5}}, {"weights", {1.0, 0.5}}});
  EXPECT_EQ(pi->time_dependence(), TimeDependence::none);
  EXPECT_FALSE(pi->sample_time());
  const std::vector<double> input{0.0, 1.0, 0.2, 0.7, -1.0};
  std::vector<double> plain(input.size());
  pi->clone()->simulate(input, plain);
  // Any step, uniform or not, gives the same output.
  EXPECT_EQ(run(pi->clone(), {0.3, {}}, input), plain);
  EXPECT_EQ(run(pi->clone(), {0.2, {0.1, 0.1, 5.0, 0.01, 2.0}}, input), plain);
}

TEST(TimedSimulation, ACreepModelAtAnotherSampleTimeHasTheExactDecays) {
  const auto creep = model_of("pi_creep", ModelRegistry::builtin().find("pi_creep").example_params);
  EXPECT_EQ(creep->time_dependence(), TimeDependence::continuous);
  ASSERT_TRUE(creep->sample_time());
  EXPECT_DOUBLE_EQ(*creep->sample_time(), 0.001);
  const auto slower = at_record_sample_time(creep->clone(), 0.004);
  EXPECT_DOUBLE_EQ(*slower->sample_time(), 0.004);
  // A hold of 4 samples at 1 ms and of 1 sample at 4 ms end in the same lag state: the lags are
  // z = 1 - exp(-t / tau) after a unit step from rest, exactly, at any step.
  const std::vector<double> fine_hold(4, 1.0);
  const std::vector<double> coarse_hold(1, 1.0);
  const auto fine = run(creep->clone(), {0.001, {}}, fine_hold);
  const auto coarse = run(creep->clone(), {0.004, {}}, coarse_hold);
  EXPECT_NEAR(fine.back(), coarse.back(), 1e-13);
  // By hand, with the example's weights: y = sum_j p_j P_rj[1] + sum_ij c_ij z_ij.
  const double plays[3] = {1.0, 0.75, 0.5};  // P_r[1] from rest for r = 0, 0.25, 0.5
  const double p[3] = {1.0, 0.5, 0.25};
  const double c[2][3] = {{0.1, 0.05, 0.02}, {0.05, 0.02, 0.01}};
  const double tau[2] = {0.01, 0.1};
  double expected = 0.0;
  for (int j = 0; j < 3; ++j) {
    expected += p[j] * plays[j];
    for (int i = 0; i < 2; ++i)
      expected += c[i][j] * plays[j] * -std::expm1(-0.004 / tau[i]);
  }
  EXPECT_NEAR(coarse.back(), expected, 1e-13);
}

TEST(TimedSimulation, TheMeasuredTriangleGivesTheSamePredictionTwentyTimesCoarserAndFiner) {
  const auto model = creep_fitted_on_table_1();
  const auto& v = trapezoid_file().measurement(1).column("V+").values;  // 401 samples, 25 ms
  const auto native = run(model->clone(), {0.025, {}}, v);
  const double range = range_of(native);

  // 20 times finer: the same triangle (linear between the measured samples) at 1.25 ms.
  const auto fine = run(model->clone(), {0.025 / 20, {}}, finer(v, 20));
  EXPECT_LT(largest_difference(every(fine, 20), native), 0.01 * range);

  // 20 times coarser, 0.5 s (21 samples a period): the triangle's corners are on the grid; the
  // lags take each interval's play output as held at its end value, a first-order error in the
  // step (measured: 5.9 % of the range at 0.5 s, 1.7 % at 0.125 s, 0.5 % at 1.25 ms).
  const auto coarse_input = every(v, 20);
  const auto coarse = run(model->clone(), {0.5, {}}, coarse_input);
  const double rediscretised = largest_difference(coarse, every(native, 20));
  EXPECT_LT(rediscretised, 0.08 * range);
  // The discretisation's own accuracy: the error shrinks with the step (first order in it).
  const auto five = run(model->clone(), {0.125, {}}, every(v, 5));
  EXPECT_LT(largest_difference(every(five, 4), every(native, 20)), 0.5 * rediscretised);
  // Run at the fit's 25 ms, as if the coarse samples were its own, the creep is 20 times too
  // slow: far off.
  const auto untimed = run(model->clone(), {0.025, {}}, coarse_input);
  EXPECT_GT(largest_difference(untimed, every(native, 20)), 3.0 * rediscretised);
}

TEST(TimedSimulation, HoldsOnTheCoarseGridAreExactAtEveryStep) {
  // A staircase with steps on the 0.5 s grid: the input is constant over every interval at each
  // sample time, so the lags' exact solution makes the outputs agree to rounding.
  const auto model = creep_fitted_on_table_1();
  std::vector<double> coarse_input;
  for (double level : {0.0, 800.0, 1400.0, 1400.0, -600.0, -1400.0, 200.0, 200.0, 900.0})
    coarse_input.insert(coarse_input.end(), 6, level);
  std::vector<double> fine_input;
  for (double level : coarse_input)
    fine_input.insert(fine_input.end(), 20, level);
  const auto coarse = run(model->clone(), {0.5, {}}, coarse_input);
  const auto fine = run(model->clone(), {0.025, {}}, fine_input);
  std::vector<double> fine_at_coarse;
  for (std::size_t k = 19; k < fine.size(); k += 20)
    fine_at_coarse.push_back(fine[k]);
  EXPECT_LT(largest_difference(coarse, fine_at_coarse), 1e-9 * range_of(coarse));
}

TEST(TimedSimulation, TheSlowTableAtItsOwnSampleTimeMatchesItsInputAtTheFitsSampleTime) {
  // Table 2 (0.01 Hz, 250 ms) with the model fitted on table 1 (25 ms): run at 250 ms, and its
  // input interpolated to 25 ms and run there, they agree at the common instants.
  const auto model = creep_fitted_on_table_1();
  const auto& table = trapezoid_file().measurement(2);
  const auto& times = table.column("Time").values;
  const auto& v = table.column("V+").values;
  const auto axis = data::time_axis(times, "table 2");
  ASSERT_TRUE(axis.uniform());
  EXPECT_NEAR(axis.sample_time, 0.25, 1e-6);
  const auto own = run(model->clone(), axis, v);
  const auto at_fit_step = run(model->clone(), {axis.sample_time / 10, {}}, finer(v, 10));
  EXPECT_LT(largest_difference(own, every(at_fit_step, 10)), 0.02 * range_of(own));
}

TEST(TimedSimulation, ANonUniformRecordIsSteppedRunByRun) {
  const auto creep = model_of("pi_creep", ModelRegistry::builtin().find("pi_creep").example_params);
  const std::vector<double> input{0.2, 0.8, 0.8, 0.1, 0.1, -0.5};
  // Steps of 1 ms for three samples, then 3 ms: the same as running the parts at their steps.
  const data::TimeAxis axis{0.001, {0.001, 0.001, 0.001, 0.003, 0.003, 0.003}};
  const auto stepped = run(creep->clone(), axis, input);
  auto first = creep->clone();
  std::vector<double> expected(input.size());
  first->simulate(std::span(input).first(3), std::span(expected).first(3));
  auto second = first->at_sample_time(0.003);
  second->simulate(std::span(input).subspan(3), std::span(expected).subspan(3));
  EXPECT_EQ(stepped, expected);
  // The lags at 3 ms differ from those at 1 ms: the steps matter.
  EXPECT_NE(stepped, run(creep->clone(), {0.001, {}}, input));
}

nlohmann::json narx_params(double sample_time) {
  auto params = ModelRegistry::builtin().find("narx").example_params;
  params["sample_time"] = sample_time;
  return params;
}

TEST(TimedSimulation, ANarxRunsAtItsOwnSampleTimeOnly) {
  const auto narx = model_of("narx", narx_params(0.01));
  EXPECT_EQ(narx->time_dependence(), TimeDependence::discrete);
  EXPECT_DOUBLE_EQ(*narx->sample_time(), 0.01);
  const std::vector<double> input{0.1, 0.3, -0.2};
  EXPECT_EQ(run(narx->clone(), {0.010005, {}}, input).size(), 3U);  // within 0.1 %
  expect_timed_error(
      [&] {
        run(narx->clone(), {0.02, {}}, input);
      },
      {"model 'narx'", "0.01 s", "0.02 s", "resample"});
  expect_timed_error(
      [&] {
        run(narx->clone(), {0.01, {0.01, 0.01, 0.02}}, input);
      },
      {"discrete", "not uniformly sampled", "sample 2", "0.02 s"});
  // Fitted without a time axis, it takes any sample time, as its file says (no note).
  const auto untimed = model_of("narx", narx_params(0.0));
  EXPECT_FALSE(untimed->sample_time());
  EXPECT_EQ(run(untimed->clone(), {5.0, {}}, input).size(), 3U);
  EXPECT_EQ(untimed_record_note(*untimed), "");
  EXPECT_NE(untimed_record_note(*narx).find("sampled at the model's sample time 0.01 s"),
            std::string::npos);
}

TEST(TimedSimulation, BadSampleTimesAreRefusedByName) {
  const auto creep = model_of("pi_creep", ModelRegistry::builtin().find("pi_creep").example_params);
  expect_timed_error([&] { (void)creep->at_sample_time(0.0); }, {"pi_creep", "sample time"});
  expect_timed_error([&] { (void)creep->at_sample_time(NAN); }, {"pi_creep", "sample time"});
  expect_timed_error(
      [&] {
        run(creep->clone(), {0.001, {0.001}}, {1.0, 2.0});
      },
      {"time axis has 1 samples", "input has 2"});
  expect_timed_error([&] { (void)model_of("narx", narx_params(-1.0)); }, {"sample_time", ">= 0"});
}

}  // namespace
}  // namespace hyst
