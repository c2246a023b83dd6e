#pragma once
// What `hyst fit` writes for a fitted model, whichever route fitted it (records or FORC files):
// the model file with its "info" block (the fit report as JSON) and, on request, the report text;
// then the one-line summary and a warning when the fit did not converge.

#include <string>

#include <nlohmann/json.hpp>

#include "hyst/identify/fit_report.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst::cli {

//! The model file's "info" block: the report's status, costs and metrics, the yardstick, the
//! preprocessing, and what was fitted (`data`) with which options.
nlohmann::json fit_info_json(const FitReport& report, nlohmann::json data, nlohmann::json options);

//! Writes the model file `out` (with `info`) and, unless `report_path` is empty, the report text,
//! replaced together; prints the summary (to stderr when an output is standard output).
void write_fitted_model(const DynamicModel& model, const nlohmann::json& info,
                        const FitReport& report, const std::string& out,
                        const std::string& report_path);

}  // namespace hyst::cli
