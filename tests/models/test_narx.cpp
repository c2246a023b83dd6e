// NARX model with play-operator regressors: the output against a hand calculation, validation
// messages, states, and a step() that does not allocate.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"
#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/models/narx.hpp"

namespace hyst {
namespace {

// 1 past input, 1 past output, 1 play (r = 0.5), one hidden layer of 2: 4 regressors,
// 2 * 4 + 2 hidden values, 2 output weights, c, 4 linear weights = 17.
Narx::Params small_params() {
  Narx::Params p;
  p.input_lags = 1;
  p.output_lags = 1;
  p.play_thresholds = {0.5};
  p.hidden_sizes = {2};
  p.weights = {0.5,  0.1,  0.0, 0.3,   // W1 row 0
               -0.2, 0.0,  0.1, 0.4,   // W1 row 1
               0.05, -0.1,             // b1
               0.3,  -0.2,             // output weights
               0.01,                   // c
               0.4,  0.0,  0.3, 0.2};  // linear weights
  p.input_offset = 0.1;
  p.input_scale = 2.0;
  p.output_offset = -0.2;
  p.output_scale = 0.5;
  return p;
}

// The model written out by hand for this structure.
struct HandNarx {
  double past_input = 0.0, past_output = 0.0, play = 0.0;
  double step(double v) {
    play = std::max(v - 0.5, std::min(v + 0.5, play));
    const double phi[4] = {(v - 0.1) / 2.0, (past_input - 0.1) / 2.0, (past_output + 0.2) / 0.5,
                           (play - 0.1) / 2.0};
    const double h0 = std::tanh(0.05 + 0.5 * phi[0] + 0.1 * phi[1] + 0.0 * phi[2] + 0.3 * phi[3]);
    const double h1 = std::tanh(-0.1 - 0.2 * phi[0] + 0.0 * phi[1] + 0.1 * phi[2] + 0.4 * phi[3]);
    const double net =
        0.3 * h0 - 0.2 * h1 + 0.01 + 0.4 * phi[0] + 0.0 * phi[1] + 0.3 * phi[2] + 0.2 * phi[3];
    const double y = -0.2 + 0.5 * net;
    past_input = v;
    past_output = y;
    return y;
  }
};

TEST(Narx, StepMatchesHandCalculation) {
  const Narx model(small_params());
  EXPECT_EQ(model.regressor_count(), 4u);
  auto state = model.initial_state();
  HandNarx hand;
  const auto v = test::random_walk(500, 3);
  for (std::size_t k = 0; k < v.size(); ++k) {
    SCOPED_TRACE(k);
    ASSERT_NEAR(model.step(state, v[k]), hand.step(v[k]), 1e-14);
  }
}

TEST(Narx, TwoHiddenLayersMatchHandCalculation) {
  // No lags, no plays: phi = v; layers [1, 1]: y = w_o tanh(w2 tanh(w1 v + b1) + b2) + c + l v.
  Narx::Params p;
  p.input_lags = 0;
  p.output_lags = 0;
  p.hidden_sizes = {1, 1};
  p.weights = {0.7, 0.1, -1.3, 0.2, 0.9, 0.05, 0.4};
  ASSERT_EQ(Narx::network_parameter_count(1, p.hidden_sizes), p.weights.size());
  const Narx model(p);
  auto state = model.initial_state();
  for (const double v : {-1.0, 0.3, 2.5}) {
    const double expected = 0.9 * std::tanh(-1.3 * std::tanh(0.7 * v + 0.1) + 0.2) + 0.05 + 0.4 * v;
    EXPECT_NEAR(model.step(state, v), expected, 1e-15);
  }
}

TEST(Narx, OneStepPredictionUsesMeasuredOutputs) {
  const Narx model(small_params());
  const std::vector<double> v = {0.2, 0.9, -0.4};
  const std::vector<double> y = {1.0, -2.0, 0.5};
  auto state = model.initial_state();
  const auto predicted = narx_one_step_prediction(model, state, v, y);
  HandNarx hand;
  for (std::size_t k = 0; k < v.size(); ++k) {
    EXPECT_NEAR(predicted[k], hand.step(v[k]), 1e-14);
    hand.past_output = y[k];  // the measured output replaces the model's
  }
}

TEST(Narx, StateAfterHistoryMatchesRunningThePlays) {
  const Narx model(small_params());
  const std::vector<double> v = {0.0, 1.0, 0.2};
  const std::vector<double> y = {0.1, 0.2, 0.3};
  const auto state = model.state_after(v, y);
  EXPECT_EQ(state.past_inputs, std::vector<double>{0.2});
  EXPECT_EQ(state.past_outputs, std::vector<double>{0.3});
  // play r = 0.5 from 0: 0 -> 0.5 (v = 1) -> 0.5 (v = 0.2, inside the band)
  EXPECT_EQ(state.play, std::vector<double>{0.5});
}

TEST(Narx, RejectsInvalidParameters) {
  auto p = small_params();
  p.weights.pop_back();
  EXPECT_HYST_ERROR(Narx{p}, "NARX weights: expected 17 values for 4 regressors");
  p = small_params();
  p.play_thresholds = {-0.5};
  EXPECT_HYST_ERROR(Narx{p}, "NARX play threshold r[0] = -0.5 must be finite and > 0");
  p = small_params();
  p.hidden_sizes = {2, 2, 2};
  EXPECT_HYST_ERROR(Narx{p}, "must list one or two hidden layers");
  p = small_params();
  p.output_scale = 0.0;
  EXPECT_HYST_ERROR(Narx{p}, "NARX output_scale = 0 must be finite and > 0");
  p = small_params();
  p.weights[3] = NAN;
  EXPECT_HYST_ERROR(Narx{p}, "NARX weight [3] = nan is not finite");
}

TEST(Narx, RejectsInvalidStates) {
  const Narx model(small_params());
  EXPECT_HYST_ERROR(model.make_state({0.0, 1.0}, {0.0}, {0.0}),
                    "NARX state past_inputs: expected 1 values, got 2");
  EXPECT_HYST_ERROR(model.make_state({0.0}, {INFINITY}, {0.0}),
                    "NARX state past_outputs[0] = inf is not finite");
  const std::vector<double> nan_history = {0.0, NAN};
  const std::vector<double> outputs = {0.0, 0.0};
  EXPECT_HYST_ERROR(model.state_after(nan_history, outputs), "history inputs[1] = nan");
}

TEST(Narx, StepDoesNotAllocate) {
  auto p = small_params();
  p.input_lags = 3;
  p.output_lags = 4;
  p.play_thresholds = {0.2, 0.4, 0.8};
  p.hidden_sizes = {6, 3};
  p.weights.assign(Narx::network_parameter_count(1 + 3 + 4 + 3, p.hidden_sizes), 0.05);
  const Narx model(p);
  auto state = model.initial_state();
  const auto v = test::random_walk(100'000, 4);
  double sink = 0.0;
  const long before = test::allocation_count();
  for (const double x : v)
    sink += model.step(state, x);
  for (const double x : v)
    sink += model.predict(state, x, 0.1);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace hyst
