// A saved model scored on a record, by hand: the prediction under each start and alignment of
// the validation rule, the figures of a prediction, and the yardsticks fitted on the record.

#include "hyst/registry/record_score.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/registry/model_file.hpp"

namespace hyst {
namespace {

// y = z0 + z1 with plays of thresholds 0 and 0.5, the second starting at `z1`.
std::unique_ptr<DynamicModel> two_plays(double z1) {
  return model_from_json({{"model", "pi"},
                          {"version", 1},
                          {"params", {{"thresholds", {0.0, 0.5}}, {"weights", {1.0, 1.0}}}},
                          {"state", {{"play", {0.0, z1}}}}},
                         "test");
}

TEST(RecordScore, FiguresOfAPredictionByHand) {
  const std::vector<double> measured{0.0, 1.0, 2.0, 3.0};
  const std::vector<double> predicted{0.0, 1.0, 2.0, 4.0};
  const auto score = score_prediction(measured, predicted);
  EXPECT_DOUBLE_EQ(score.metrics.rmse, 0.5);                  // sqrt(1 / 4)
  EXPECT_DOUBLE_EQ(score.metrics.nrmse_percent, 50.0 / 3.0);  // 0.5 / range 3
  EXPECT_DOUBLE_EQ(score.metrics.max_error, 1.0);
  EXPECT_NEAR(score.nrmse_std_percent, 50.0 / std::sqrt(1.25), 1e-12);  // std 1.118
}

TEST(RecordScore, ThePredictionStartsAsTheRuleSays) {
  // From rest: v = 0, 1, 0 gives z1 = 0, 0.5, 0.5 and y = 0, 1.5, 0.5.
  const std::vector<double> input{0.0, 1.0, 0.0};
  const std::vector<double> measured{1.0, 2.0, 0.0};
  const auto model = two_plays(-0.5);
  const auto rest = predict_record(*model, input, measured, saved_model_rule("rest", "none", "t"));
  EXPECT_EQ(rest, (std::vector<double>{0.0, 1.5, 0.5}));
  // Periodic: the second pass starts with z1 = 0.5.
  EXPECT_EQ(predict_record(*model, input, measured, saved_model_rule("periodic", "none", "t")),
            (std::vector<double>{0.5, 1.5, 0.5}));
  // File: from the model's own z1 = -0.5, which v = 0 leaves where it is.
  EXPECT_EQ(predict_record(*model, input, measured, saved_model_rule("file", "none", "t")),
            (std::vector<double>{-0.5, 1.5, 0.5}));
  // First-sample: the rest prediction shifted by 1 - 0 onto the measured first sample.
  EXPECT_EQ(predict_record(*model, input, measured, saved_model_rule("rest", "first-sample", "t")),
            (std::vector<double>{1.0, 2.5, 1.5}));
  // The model itself keeps its state.
  EXPECT_EQ(model->state()["play"][1].get<double>(), -0.5);
}

TEST(RecordScore, SavedModelRuleRefusesWhatAModelFileCannotDo) {
  EXPECT_EQ(saved_model_rule("file", "none", "t").start, ValidationStart::continued);
  EXPECT_EQ(saved_model_rule("periodic", "first-sample", "t").align,
            ValidationAlignment::first_sample);
  EXPECT_HYST_ERROR(saved_model_rule("continue", "none", "'hyst evaluate'"),
                    "'continue' needs the record the model was fitted to; 'hyst evaluate'");
  EXPECT_HYST_ERROR(saved_model_rule("hot", "none", "t"),
                    "'hot' is not known (rest, periodic, file)");
  EXPECT_HYST_ERROR(saved_model_rule("rest", "last", "t"), "validation align 'last' is not known");
}

TEST(RecordScore, YardsticksAreFittedOnTheRecordItself) {
  const auto model = two_plays(0.0);
  std::vector<double> input, output;
  for (int k = 0; k < 40; ++k) {
    input.push_back(std::sin(0.3 * k));
    output.push_back(2.0 * input.back() * input.back() * input.back() - input.back() + 0.25);
  }
  const auto score = score_on_record(*model, input, output, saved_model_rule("rest", "none", "t"));
  ASSERT_EQ(score.yardsticks.size(), 2u);
  EXPECT_EQ(score.yardsticks[0].name, "mean");
  EXPECT_NEAR(score.yardsticks[0].score.nrmse_std_percent, 100.0, 1e-9);  // by definition
  // The output is a cubic of the input: the cubic yardstick reproduces it.
  EXPECT_EQ(score.yardsticks[1].name, "cubic y(v)");
  EXPECT_LT(score.yardsticks[1].score.metrics.rmse, 1e-9);
  EXPECT_EQ(score.predicted.size(), input.size());
  // Too few samples for a cubic: the mean alone.
  const std::vector<double> three{0.0, 1.0, 0.0};
  EXPECT_EQ(score_on_record(*model, three, three, saved_model_rule("rest", "none", "t"))
                .yardsticks.size(),
            1u);
}

}  // namespace
}  // namespace hyst
