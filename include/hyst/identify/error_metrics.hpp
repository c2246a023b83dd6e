#pragma once
//! \file
//! How well a prediction matches a measurement.
//!
//! With e[k] = measured[k] - predicted[k] over N samples:
//!
//!     RMSE      = sqrt(sum_k e[k]^2 / N)                             [output units]
//!     NRMSE     = 100 % * RMSE / (max_k measured[k] - min_k measured[k])   [%]
//!     max error = max_k |e[k]|                                       [output units]
//!
//! The NRMSE is normalised by the range (not the standard deviation) of the measured output and
//! given in percent everywhere (reports, tables, fields), so 1 means "1 % of the peak-to-peak
//! output".

#include <cstddef>
#include <span>

namespace hyst {

//! How well a prediction matches a measurement (definitions in the file comment).
struct ErrorMetrics {
  std::size_t samples = 0;     //!< N
  double rmse = 0.0;           //!< [output units]
  double nrmse_percent = 0.0;  //!< 100 * RMSE / range of the measured output [%]
  double max_error = 0.0;      //!< max |measured - predicted| [output units]
};

//! Metrics of `predicted` against `measured`. Throws hyst::Error unless both have the same,
//! non-zero length, every sample is finite, and the measured output is not constant (its range
//! normalises the NRMSE).
ErrorMetrics error_metrics(std::span<const double> measured, std::span<const double> predicted);

}  // namespace hyst
