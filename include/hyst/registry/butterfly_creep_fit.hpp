#pragma once
//! \file
//! The butterfly strain with creep fit with measured polarisation
//! (hyst/identify/fit_butterfly_strain_creep.hpp), as a registered model
//! ('butterfly_strain_creep') for model files and Python. The options are read by name, as
//! `hyst fit butterfly_strain_creep --option` reads them, with fit_leakage.

#include <memory>
#include <span>

#include <nlohmann/json.hpp>

#include "hyst/identify/fit_report.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst {

struct ButterflyCreepTwoStageModelFit {
  std::unique_ptr<DynamicModel> model;  //!< the chain v -> P -> y, in its start state
  FitReport report;                     //!< of the strain
  FitReport polarisation_report;        //!< of the measured polarisation
};

//! Throws hyst::Error naming an unknown or invalid option, or invalid data.
ButterflyCreepTwoStageModelFit fit_butterfly_strain_creep_model_with_polarisation(
    std::span<const double> input, std::span<const double> polarisation,
    std::span<const double> output, const nlohmann::json& options);

}  // namespace hyst
