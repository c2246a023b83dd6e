#pragma once
//! \file
//! A saved model scored on a measured record (`hyst evaluate --model m.json --data r.csv`,
//! Python `hyst.evaluate(model, input, output)`): its prediction under a validation rule
//! (validation_rule.hpp), the validation metrics of `hyst fit --validation-data`, the NRMSE by the
//! output's standard deviation, and yardsticks fitted on the record itself (its mean, a static
//! cubic y(v)): the floor that a predictor without memory reaches there, which a model fitted on
//! another record has to beat to have carried anything over.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hyst/identify/error_metrics.hpp"
#include "hyst/registry/dynamic_model.hpp"
#include "hyst/registry/validation_rule.hpp"

namespace hyst {

//! The figures of one prediction of a record.
struct PredictionScore {
  ErrorMetrics metrics;            //!< RMSE, NRMSE by the range, max error
  double nrmse_std_percent = 0.0;  //!< 100 RMSE / std of the measured output [%]
};

//! A yardstick fitted on the scored record, and its score.
struct RecordYardstick {
  std::string name;  //!< "mean", "cubic y(v)"
  PredictionScore score;
};

struct RecordScore {
  std::vector<double> predicted;  //!< the model's prediction under the rule
  PredictionScore model;
  std::vector<RecordYardstick> yardsticks;  //!< the cubic is left out for a constant input
};

//! The figures of `predicted` against `measured`; hyst::Error as error_metrics().
PredictionScore score_prediction(std::span<const double> measured,
                                 std::span<const double> predicted);

//! `model` (not changed) predicts the record under `rule` (predict_record()), scored with the
//! yardsticks. hyst::Error for mismatched, empty or non-finite records and a constant output.
RecordScore score_on_record(const DynamicModel& model, std::span<const double> input,
                            std::span<const double> output, const ValidationRule& rule);

}  // namespace hyst
