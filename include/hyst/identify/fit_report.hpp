#pragma once
//! \file
//! The report every fitter of hyst returns, whatever the model and the method.
//!
//! Cost, with e[k] = measured[k] - predicted[k] over the N samples of the fit part:
//!
//!     cost      = 0.5 * sum_k e[k]^2                       [output units^2]
//!
//! `initial_cost` is the cost before fitting: for a linear-in-the-weights model it is the cost of
//! the best constant (all weights 0, offset fitted), so final_cost / initial_cost says how much of
//! the variance the model explains. `fit` is measured on the samples used for fitting;
//! `validation`, when present, on held-out samples (the last part of the record, or another record)
//! that the fitter never saw; RMSE, NRMSE [%] and max error are defined in error_metrics.hpp.
//!
//! The status of a fit (status()) is decided in one place: how the method ended (`termination`),
//! overruled by the judgement of the fitted model's simulation (`quality`, fit_quality.hpp), so
//! that a converged fit whose prediction is nearly constant or runs away is never reported as
//! "converged". With a held-out part of the record, `references` holds the yardstick
//! (reference_predictors.hpp) scored on the same held-out samples as the model.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hyst/core/enum_names.hpp"
#include "hyst/identify/error_metrics.hpp"
#include "hyst/identify/fit_quality.hpp"
#include "hyst/identify/fitted_domain.hpp"
#include "hyst/identify/reference_predictors.hpp"

namespace hyst {

//! Why an iterative fit stopped.
enum class Termination {
  converged,       //!< the optimality conditions hold within the tolerance; for the Ceres-based
                   //!< fits also: the cost fell by less than 0.1 % over the last 50 iterations
                   //!< (a stagnating Levenberg-Marquardt run on a kinked cost)
  max_iterations,  //!< the iteration limit was reached first; the result is feasible but not
                   //!< optimal
  no_progress,     //!< the method could not improve further (rounding, degenerate data)
  failed,          //!< the method failed; the result is not usable
};

//! "converged", "max_iterations", "no_progress", "failed".
constexpr EnumNames<Termination, 4> enumerator_names(Termination) {
  return {{
      {Termination::converged, "converged"},
      {Termination::max_iterations, "max_iterations"},
      {Termination::no_progress, "no_progress"},
      {Termination::failed, "failed"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for any other text
//! ("unknown termination 'done' (expected converged, max_iterations, no_progress or failed)").
Termination termination_from_string(std::string_view text);

//! Outcome of a fit: how the method ended, the cost it reached and the error on fit and
//! validation data.
struct FitReport {
  std::string model;   //!< registry name of the model, e.g. "pi"
  std::string method;  //!< e.g. "nnls (Lawson-Hanson)"
  Termination termination = Termination::failed;
  std::string message;  //!< the method's own words on how it ended
  std::size_t iterations = 0;
  double initial_cost = 0.0;   //!< 0.5 * sum e^2 before fitting, on the fit part [output units^2]
  double final_cost = 0.0;     //!< 0.5 * sum e^2 of the fitted model, on the fit part
  std::size_t parameters = 0;  //!< number of fitted parameters
  ErrorMetrics fit;            //!< on the samples used for fitting
  std::optional<ErrorMetrics> validation;  //!< on held-out samples, when there were any
  double seconds = 0.0;                    //!< wall time of the fit [s]
  //! How the measured record was prepared before fitting, one line per step in the order applied
  //! (cycles selected, drift removed, resampled; see hyst/data/preprocessing.hpp); empty when it
  //! was used as measured.
  std::vector<std::string> preprocessing;
  //! The domain of the fit part (fitted_domain.hpp): what other records are checked against.
  std::optional<FittedDomain> domain;
  //! How `validation` was predicted, in words (registry/validation_rule.hpp); empty when the
  //! fitter alone decided it.
  std::string validation_rule;
  //! The judgement of the fitted model's simulation (fit_quality.hpp) and its reason.
  FitQuality quality = FitQuality::unchecked;
  std::string quality_note;
  //! The reference predictors scored on the held-out part (empty without one).
  std::vector<ReferenceScore> references;

  //! Takes a judgement (fit_quality.hpp) unless the report holds a graver one already (unstable
  //! over degenerate over sound over unchecked): the fitter's own verdict, e.g. that every fitted
  //! parameter ended at a bound of its range, stands when the simulation looks sound.
  void take_verdict(FitQuality verdict, std::string note);
  //! The one word on how the fit ended: "failed", "unstable", "degenerate" (from `quality`),
  //! else "iteration limit", "no progress" or "converged" (from `termination`).
  std::string_view status() const;
  //! The reference with the lowest held-out NRMSE, or null.
  const ReferenceScore* best_reference() const { return hyst::best_reference(references); }
  //! Does the validation NRMSE beat the best reference's? Empty without validation or references.
  std::optional<bool> beats_yardstick() const;

  //! One paragraph: model, method, status, cost, fit and validation error, yardstick,
  //! preprocessing.
  std::string brief() const;
  //! A multi-line text table of every field.
  std::string full() const;
};

}  // namespace hyst
