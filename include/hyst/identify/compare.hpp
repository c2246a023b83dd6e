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
//! order they were asked for. Columns: validation NRMSE, RMSE and max error, number of
//! parameters, fit time [s] and simulation time per sample [ns] (DynamicModel::simulate over the
//! whole record, repeated for at least `timing_seconds`).

#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hyst/identify/data_split.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {

struct CompareOptions {
  //! Registry names; empty: every model that has a fitter.
  std::vector<std::string> models;
  //! The last fraction of the record, held out for ranking; (0, 1).
  double validate_fraction = 0.25;
  //! Fit options by model name (the model's FitRequest::options); others get their defaults.
  std::map<std::string, nlohmann::json> fit_options;
  //! Minimum total time of the simulation timing per model [s] (>= 0; 0: one run).
  double timing_seconds = 0.05;
};

//! One row of the comparison.
struct ComparedModel {
  std::string model;                //!< registry name
  bool ok = false;                  //!< fitted and evaluated
  std::string error;                //!< why not, when !ok
  std::optional<FitReport> report;  //!< the fitter's own report (on the fit part)
  ErrorMetrics validation;          //!< free run on the held-out part
  std::size_t parameters = 0;
  double fit_seconds = 0.0;
  double ns_per_sample = 0.0;
  std::vector<double> simulated;  //!< free run over the whole record (fit and validation part)
};

struct ModelComparison {
  DataSplit split;
  std::vector<ComparedModel> ranking;  //!< best first; failed rows last
};

//! Fits and ranks the models (see the file comment). Throws hyst::Error only for problems that
//! concern every model alike before any fit: lengths that differ, a record too short to split,
//! a validate_fraction out of range, an unknown model name, a model without a fitter, fit
//! options for a model that is not compared. Data problems (NaN, constant input, too short for
//! a model) are reported per model.
ModelComparison compare_models(std::span<const double> input, std::span<const double> output,
                               const CompareOptions& options = {},
                               const ModelRegistry& registry = ModelRegistry::builtin());

//! The ranking as a Markdown table (one row per model; failed rows carry the reason).
std::string model_comparison_markdown(const ModelComparison& comparison);
//! The ranking as CSV: rank,model,status,validation_nrmse,validation_rmse,validation_max_error,
//! parameters,fit_seconds,simulation_ns_per_sample,message (quoted).
std::string model_comparison_csv(const ModelComparison& comparison);

}  // namespace hyst
