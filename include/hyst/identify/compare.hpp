#pragma once
//! \file
//! "Which model fits my actuator?": fits several registered models to the same record and ranks
//! them on the same held-out part.
//!
//! The record is split once (data_split.hpp): every model is fitted on the fit part only (no
//! validation inside the fitter), then run in free run over the whole record from the initial
//! state its fitter returned; the validation metrics are those of the last part, the one no
//! fitter saw. So all models are judged on the same samples in the same way, whatever their
//! fitters do internally. A model whose fit or evaluation fails (bad data for it, too few
//! samples for its parameters, an output that diverges) gets a row with the reason and does not
//! stop the others.
//!
//! Ranking: the fitted models by validation NRMSE (lowest first), then the failed ones in the
//! order they were asked for. Columns: validation NRMSE [%], RMSE and max error, whether the model
//! beats the yardstick, number of parameters, fit time [s], simulation time per sample [ns]
//! (DynamicModel::simulate over the whole record, repeated for at least `timing_seconds`) and the
//! status (FitReport::status(): "converged", "iteration limit", "no progress", or "degenerate" /
//! "unstable" when the free run judged on the held-out part says so, fit_quality.hpp).
//!
//! Yardstick: the reference predictors (reference_predictors.hpp) are fitted on the same fit part
//! and scored on the same held-out part; a model beats the yardstick when its held-out NRMSE is
//! below the best reference's. No-fit verdict: when even the best model's held-out NRMSE exceeds
//! `no_fit_percent`, the tables say in one line that no model describes the record, with what the
//! cheap looks of record_diagnosis.hpp see (butterfly, drift, extrapolation).

#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hyst/core/progress.hpp"
#include "hyst/identify/data_split.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/identify/fitted_domain.hpp"
#include "hyst/identify/record_diagnosis.hpp"
#include "hyst/identify/reference_predictors.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {

struct CompareOptions {
  //! Registry names; empty: every model that has a fitter.
  std::vector<std::string> models;
  //! The last fraction of the record, held out for ranking; (0, 1).
  double validate_fraction = 0.25;
  //! Fit options by model name (the model's FitRequest::options); others get their defaults.
  std::map<std::string, nlohmann::json> fit_options;
  //! The records' sample time [s]: the fit option sample_time of every model whose fitter has
  //! one (with_sample_time()); none: each such model's default (time constants in samples).
  std::optional<double> sample_time;
  //! Minimum total time of the simulation timing per model [s] (>= 0; 0: one run).
  double timing_seconds = 0.05;
  //! Best held-out NRMSE [%] above which no model is said to describe the record (> 0).
  double no_fit_percent = 20.0;
  //! The samples are a time series (ARX is among the reference predictors); false for a record
  //! resampled on an input grid.
  bool time_series = true;
  //! Told before each model's fit and at the end (task "models"); empty: nothing is told.
  ProgressCallback progress{};
};

//! One row of the comparison.
struct ComparedModel {
  std::string model;                //!< registry name
  bool ok = false;                  //!< fitted and evaluated
  std::string error;                //!< why not, when !ok
  std::optional<FitReport> report;  //!< the fitter's own report (on the fit part)
  ErrorMetrics validation;          //!< free run on the held-out part
  bool beats_yardstick = false;     //!< validation NRMSE below the best reference's
  std::size_t parameters = 0;
  double fit_seconds = 0.0;
  double ns_per_sample = 0.0;
  std::vector<double> simulated;  //!< free run over the whole record (fit and validation part)
  //! The held-out inputs against the domain of the fit part (report->domain): where the ranking
  //! scores extrapolation.
  DomainCheck held_out_domain;
};

struct ModelComparison {
  DataSplit split;
  std::vector<ComparedModel> ranking;      //!< best first; failed rows last
  std::vector<ReferenceScore> references;  //!< the yardstick, on the same held-out part
  double no_fit_percent = 20.0;            //!< the threshold of the no-fit verdict [%]
  //! Set when the best model's held-out NRMSE exceeds no_fit_percent: what the record shows.
  std::optional<RecordDiagnosis> no_fit;
};

//! Fits and ranks the models (see the file comment). Throws hyst::Error only for problems that
//! concern every model alike before any fit: lengths that differ, a record too short to split,
//! a validate_fraction out of range, an unknown model name, a model without a fitter, fit
//! options for a model that is not compared. Data problems (NaN, constant input, too short for
//! a model) are reported per model.
ModelComparison compare_models(std::span<const double> input, std::span<const double> output,
                               const CompareOptions& options = {},
                               const ModelRegistry& registry = ModelRegistry::builtin());

//! The registry entries of `models` (empty: every model with a fitter), in the order given.
//! hyst::Error for an unknown name, a model without a fitter, a name listed twice, and fit
//! options for a model that is not among them.
std::vector<const ModelEntry*> compared_models(
    const std::vector<std::string>& models,
    const std::map<std::string, nlohmann::json>& fit_options,
    const ModelRegistry& registry = ModelRegistry::builtin());

//! One line naming every reference predictor's held-out NRMSE and the best of them, e.g.
//! "Yardstick (reference predictors on the held-out part): mean 48.1 %, ...; best: last value
//! held, 2.5 %. Models that do not beat it: narx, pi."
std::string yardstick_line(const ModelComparison& comparison);
//! The no-fit verdict in one line, e.g. "No model describes this record: the best held-out NRMSE
//! is 373 % (pi), above 20 %. Seen: butterfly: ..."; empty when comparison.no_fit is not set.
std::string no_fit_line(const ModelComparison& comparison);

//! "The held-out part leaves the domain the models were fitted on: pi, kp: 120 of 400 samples:
//! inputs above ..."; empty when it stays inside every fitted model's domain.
std::string held_out_domain_line(const ModelComparison& comparison);

//! The ranking as a Markdown table (one row per model; failed rows carry the reason), after the
//! yardstick line, the no-fit verdict and the held-out domain line.
std::string model_comparison_markdown(const ModelComparison& comparison);
//! The ranking as CSV: rank,model,status,validation_nrmse_percent,validation_rmse,
//! validation_max_error,beats_yardstick,parameters,fit_seconds,simulation_ns_per_sample,message
//! (quoted); then one row per reference predictor with rank "reference" and model "reference:
//! NAME".
std::string model_comparison_csv(const ModelComparison& comparison);

}  // namespace hyst
