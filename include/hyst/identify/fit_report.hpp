#pragma once
//! \file
//! The report every fitter of hyst returns, whatever the model and the method.
//!
//! Cost and error metrics, with e[k] = measured[k] - predicted[k] over N samples:
//!
//!     cost      = 0.5 * sum_k e[k]^2                       [output units^2]
//!     RMSE      = sqrt(sum_k e[k]^2 / N)                   [output units]
//!     NRMSE     = RMSE / (max_k measured[k] - min_k measured[k])   [-]
//!     max error = max_k |e[k]|                             [output units]
//!
//! `initial_cost` is the cost before fitting: for a linear-in-the-weights model it is the cost of
//! the best constant (all weights 0, offset fitted), so final_cost / initial_cost says how much of
//! the variance the model explains. `fit` is measured on the samples used for fitting;
//! `validation`, when present, on held-out samples (the last part of the record, or another record)
//! that the fitter never saw. NRMSE is normalised by the range (not the standard deviation) of the
//! measured output, so 0.01 means "1 % of the peak-to-peak output".

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hyst {

//! Why an iterative fit stopped.
enum class Termination {
  converged,       //!< the optimality conditions hold within the tolerance
  max_iterations,  //!< the iteration limit was reached first; the result is feasible but not
                   //!< optimal
  no_progress,     //!< the method could not improve further (rounding, degenerate data)
  failed,          //!< the method failed; the result is not usable
};

//! "converged", "max_iterations", "no_progress", "failed".
std::string_view to_string(Termination termination);
//! The inverse of to_string(); throws hyst::Error for any other text
//! ("unknown termination 'done' (expected converged, max_iterations, no_progress or failed)").
Termination termination_from_string(std::string_view text);

//! How well a prediction matches a measurement (definitions in the file comment).
struct ErrorMetrics {
  std::size_t samples = 0;  //!< N
  double rmse = 0.0;        //!< [output units]
  double nrmse = 0.0;       //!< RMSE / range of the measured output [-]
  double max_error = 0.0;   //!< max |measured - predicted| [output units]
};

//! Metrics of `predicted` against `measured`. Throws hyst::Error unless both have the same,
//! non-zero length, every sample is finite, and the measured output is not constant (its range
//! normalises the NRMSE).
ErrorMetrics error_metrics(std::span<const double> measured, std::span<const double> predicted);

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
  //! How `validation` was predicted, in words (registry/validation_rule.hpp); empty when the
  //! fitter alone decided it.
  std::string validation_rule;

  //! One paragraph: model, method, termination, cost, fit and validation error, preprocessing.
  std::string brief() const;
  //! A multi-line text table of every field.
  std::string full() const;
};

}  // namespace hyst
