#pragma once
//! \file
//! The butterfly strain fits that the registry's one-record fitter does not cover, as registered
//! models ('butterfly_strain') for model files and Python: several records fitted together, and
//! the two-stage fit with measured polarisation (hyst/identify/fit_butterfly_strain.hpp). The
//! options are read by name, as `hyst fit butterfly_strain --option` reads them: levels, lower,
//! upper, degree, fit_field_term, initial_state, max_iterations.

#include <memory>
#include <span>

#include <nlohmann/json.hpp>

#include "hyst/identify/fit_butterfly_strain.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst {

//! The fit options of `options` (an object of option names); throws hyst::Error naming an
//! unknown or invalid option.
ButterflyFitOptions butterfly_fit_options(const nlohmann::json& options);

struct ButterflyModelFit {
  std::unique_ptr<DynamicModel> model;  //!< 'butterfly_strain' in the state the fit started from
  FitReport report;
};

//! fit_butterfly_strain() of several records, as a registered model.
ButterflyModelFit fit_butterfly_strain_model(std::span<const FitRecord> records,
                                             const nlohmann::json& options);

struct ButterflyTwoStageModelFit {
  std::unique_ptr<DynamicModel> model;  //!< the chain v -> P -> y
  FitReport report;                     //!< of the strain
  FitReport polarisation_report;        //!< of P(v)
  FitReport map_report;                 //!< of y(v, P) on the measured polarisation
  double leakage_conductance = 0.0;     //!< g with the option fit_leakage, else 0
};

//! fit_butterfly_strain_with_polarisation(), as a registered model; the options also take
//! fit_leakage and sample_time.
ButterflyTwoStageModelFit fit_butterfly_strain_model_with_polarisation(
    std::span<const double> input, std::span<const double> polarisation,
    std::span<const double> output, const nlohmann::json& options);

}  // namespace hyst
