#pragma once
//! \file
//! "Which model fits my actuator?" judged on records the fitters never saw: several models are
//! fitted on some records and ranked by their error on other, separate records (another
//! amplitude, another measurement). Unlike the time split of compare.hpp, the ranking does not
//! measure how a model extrapolates from the start of one record to its end.
//!
//! Fit records: the registry fitters take one record, so the fit records are joined one after
//! the other into one; the model state runs on across each junction (a record that starts where
//! the previous one ended, as one period of a steady loop does, joins without a jump).
//! Held-out records: each is predicted by the one validation rule of validation_rule.hpp (start
//! rest / periodic / continue, alignment none / first-sample), as `hyst fit` does for a separate
//! validation record; "continue" continues from the end of the joined fit records.
//!
//! Leave-one-out: each record in turn is held out and the models are fitted on the others; a
//! model's row gives the held-out NRMSE of every record, their mean and their worst.
//!
//! Ranking: the models by mean held-out NRMSE (lowest first), then the failed ones in the order
//! they were asked for. A model fails as a whole when any of its fits or predictions fails (the
//! reason names the record); the others still run.
//!
//! Yardstick: the reference predictors of reference_predictors.hpp (mean, last value held, a
//! cubic y(v); ARX only with start "continue", where a held-out record follows the fit records in
//! time) are fitted on the same joined fit records and scored on each held-out record with the
//! same alignment as the models; a model beats the yardstick when its mean held-out NRMSE is below
//! the best reference's mean. No-fit verdict: for each held-out record on which even the best
//! model's NRMSE exceeds `no_fit_percent`, the tables say that no model describes that record,
//! with what the looks of record_diagnosis.hpp see on it (butterfly, drift, and extrapolation
//! beyond the input range of the records the models were fitted on).

#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hyst/core/progress.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/identify/fitted_domain.hpp"
#include "hyst/identify/record_diagnosis.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/registry/validation_rule.hpp"

namespace hyst {

//! One measured record with a name for the tables (e.g. "Vplus_15kv:Displacement_15kv").
struct NamedRecord {
  std::string name;
  std::vector<double> input;
  std::vector<double> output;
};

struct CrossRecordOptions {
  //! Registry names; empty: every model that has a fitter.
  std::vector<std::string> models;
  //! Fit options by model name (the model's FitRequest::options); others get their defaults.
  std::map<std::string, nlohmann::json> fit_options;
  //! The records' sample time [s]: the fit option sample_time of every model whose fitter has
  //! one (with_sample_time()); none: each such model's default (time constants in samples).
  std::optional<double> sample_time;
  //! How each held-out record is predicted.
  ValidationRule validation;
  //! Best held-out NRMSE [%] on a record above which no model is said to describe it (> 0).
  double no_fit_percent = 20.0;
  //! The records are time series (ARX joins the yardstick when the start is "continue").
  bool time_series = true;
  //! Told before each model's fits and at the end (task "models"); empty: nothing is told.
  ProgressCallback progress{};
};

//! The error of one model on one held-out record, fitted on `fitted_on`.
struct HeldOutScore {
  std::string record;
  std::vector<std::string> fitted_on;
  ErrorMetrics metrics;
  //! The held-out record's inputs against the domain of the records the model was fitted on.
  DomainCheck domain;
};

//! One row of the cross-record comparison.
struct CrossRecordRow {
  std::string model;
  bool ok = false;
  std::string error;                 //!< why not, when !ok
  std::vector<HeldOutScore> scores;  //!< one per held-out record, in the order given
  double mean_nrmse_percent = 0.0;   //!< mean of the scores' NRMSE [%]
  double worst_nrmse_percent = 0.0;  //!< largest of the scores' NRMSE [%]
  std::string worst_record;          //!< the record of the worst score
  std::size_t parameters = 0;        //!< of the (last) fitted model
  double fit_seconds = 0.0;          //!< all fits together
  std::string status;                //!< FitReport::status() of the (last) fit
  bool beats_yardstick = false;      //!< mean NRMSE below the best reference's mean
};

//! One reference predictor of the yardstick, scored like a model row.
struct CrossRecordReference {
  std::string name;  //!< "mean", "last value held", ...
  bool ok = false;
  std::string error;                 //!< why not, when !ok
  std::vector<HeldOutScore> scores;  //!< one per held-out record, in the order given
  double mean_nrmse_percent = 0.0;
  double worst_nrmse_percent = 0.0;
  std::string worst_record;
};

//! A held-out record that no model describes.
struct NoFitVerdict {
  std::string record;
  std::string best_model;           //!< the model with the lowest NRMSE on this record
  double best_nrmse_percent = 0.0;  //!< its NRMSE there [%]
  RecordDiagnosis seen;             //!< what the looks at the record find
};

struct CrossRecordComparison {
  bool leave_one_out = false;
  std::vector<std::string> fit_records;          //!< empty in leave-one-out mode
  std::vector<std::string> validate_records;     //!< every record in leave-one-out mode
  std::string rule;                              //!< describe(validation rule)
  std::vector<CrossRecordRow> ranking;           //!< best first; failed rows last
  std::vector<CrossRecordReference> references;  //!< the yardstick
  double no_fit_percent = 20.0;                  //!< the threshold of the no-fit verdict [%]
  std::vector<NoFitVerdict> no_fit;              //!< held-out records no model describes
};

//! Fits each model once on `fit` (joined) and scores it on every record of `validate`. Throws
//! hyst::Error before any fit for: no fit or no held-out record, a record with input and output
//! of different lengths or fewer than 2 samples, two records of the same name, an unknown model,
//! a model without a fitter, fit options for a model that is not compared.
CrossRecordComparison compare_across_records(
    const std::vector<NamedRecord>& fit, const std::vector<NamedRecord>& validate,
    const CrossRecordOptions& options = {},
    const ModelRegistry& registry = ModelRegistry::builtin());

//! Leave-one-out over `records` (at least 2): each held out in turn, the models fitted on the
//! others joined in the order given. The same checks as compare_across_records().
CrossRecordComparison compare_leave_one_out(
    const std::vector<NamedRecord>& records, const CrossRecordOptions& options = {},
    const ModelRegistry& registry = ModelRegistry::builtin());

//! The best reference predictor (lowest mean NRMSE), or null when none could be made.
const CrossRecordReference* best_cross_record_reference(const CrossRecordComparison& comparison);

//! The ranking as Markdown: a line naming the fit and held-out records and the rule, the no-fit
//! verdicts, the yardstick line, then one row per model with its mean, worst and per-record
//! held-out NRMSE [%] and one row per reference predictor.
std::string cross_record_markdown(const CrossRecordComparison& comparison);

//! One paragraph per held-out record that leaves the domain of any model fitted on the others
//! ("Held-out record 'v2:y2' leaves the domain ...: pi, kp: 120 of 400 samples: ..."), each
//! followed by a blank line; empty when every record stays inside.
std::string held_out_domain_lines(const CrossRecordComparison& comparison);
//! The ranking as CSV: rank,model,status,mean_nrmse_percent,worst_nrmse_percent,worst_record,
//! parameters,fit_seconds,beats_yardstick, one column "nrmse_percent:RECORD" per held-out record,
//! message; then one row per reference predictor with rank "reference" and model
//! "reference: NAME".
std::string cross_record_csv(const CrossRecordComparison& comparison);

}  // namespace hyst
