#include "hyst/registry/record_score.hpp"

#include <cmath>

#include "hyst/core/error.hpp"
#include "hyst/identify/reference_predictors.hpp"

namespace hyst {
namespace {

double deviation(std::span<const double> values) {
  double mean = 0.0;
  for (const double v : values)
    mean += v / double(values.size());
  double squares = 0.0;
  for (const double v : values)
    squares += (v - mean) * (v - mean);
  return std::sqrt(squares / double(values.size()));
}

}  // namespace

PredictionScore score_prediction(std::span<const double> measured,
                                 std::span<const double> predicted) {
  PredictionScore score{error_metrics(measured, predicted), 0.0};
  score.nrmse_std_percent = 100.0 * score.metrics.rmse / deviation(measured);
  return score;
}

RecordScore score_on_record(const DynamicModel& model, std::span<const double> input,
                            std::span<const double> output, const ValidationRule& rule) {
  RecordScore score;
  score.predicted = predict_record(model, input, output, rule);
  score.model = score_prediction(output, score.predicted);
  score.yardsticks.push_back(
      {"mean", score_prediction(output, predict_mean(output, output.size()))});
  try {
    score.yardsticks.push_back(
        {"cubic y(v)", score_prediction(output, predict_polynomial(input, output, input, 3))});
  } catch (const Error&) {
    // a constant input or fewer than four samples: no cubic to fit
  }
  return score;
}

}  // namespace hyst
