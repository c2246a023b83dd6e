#pragma once
//! \file
//! Identification of the Krasnosel'skii-Pokrovskii model's kernel weights from one input/output
//! record, by non-negative least squares like the Preisach relay grid (fit_preisach.hpp).
//!
//! From the known initial state (every kernel at -1) the kernel outputs kappa_ij[k] follow from
//! the input alone, and the output is linear in the weights:
//!
//!     y[k] = y_off + sum_{i >= j} mu_ij kappa_ij[k]
//!     min_{mu >= 0, y_off} sum_k (y_meas[k] - y[k])^2
//!
//! mu >= 0 keeps the fitted model monotone. Kernels the input never moves (reversals never
//! inside their cells) give constant or coinciding columns: their weights split arbitrarily, the
//! output does not. Cost: an M x N(N+1)/2 NNLS; practical up to N ~ 30.

#include <cstddef>
#include <optional>
#include <span>

#include "hyst/identify/fit_report.hpp"
#include "hyst/models/krasnoselskii_pokrovskii.hpp"

namespace hyst {

struct KpFitOptions {
  std::size_t levels = 12;  //!< N cells (N(N+1)/2 kernels), >= 1
  //! Input range of the grid [input units]; not set = min and max of the fitted input.
  std::optional<double> lower = std::nullopt;
  std::optional<double> upper = std::nullopt;
  double ramp_cells = 1.0;  //!< kernel ramp width in cells, > 0
  bool fit_offset = true;   //!< fit y_off; false = 0
  //! Fraction of the record, at its end, held out for validation, [0, 1).
  double validate_fraction = 0.0;
};

struct KpFit {
  KrasnoselskiiPokrovskii model;
  FitReport report;  //!< model "kp", method "nnls (Lawson-Hanson) on kernel weights"
};

//! Fits the kernel weights and offset. Throws hyst::Error for invalid data or options.
KpFit fit_krasnoselskii_pokrovskii(std::span<const double> input, std::span<const double> output,
                                   const KpFitOptions& options = {});

}  // namespace hyst
