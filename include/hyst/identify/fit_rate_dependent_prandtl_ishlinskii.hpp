#pragma once
//! \file
//! Identification of the rate-dependent PI model's weights for fixed nominal thresholds, rate gain
//! beta, sample time and rate filter. With those fixed, the play outputs w_j[k] (whose thresholds
//! r_j + beta |vdot[k]| follow from the input alone) are known and the output is linear in the
//! weights, as for the classical PI (fit_prandtl_ishlinskii.hpp):
//!
//!     min_{p, y_off} sum_k (y_meas[k] - y_off - sum_j p_j w_j[k])^2,   p_0 >= eps, p_j >= 0
//!
//! solved by NNLS. beta itself enters nonlinearly: choose it from the loop widening between two
//! frequencies, or scan a few values and keep the best report. Initial state: at rest at v = 0.

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/identify/fit_report.hpp"
#include "hyst/models/rate_dependent_prandtl_ishlinskii.hpp"

namespace hyst {

struct RateDependentPiFitOptions {
  std::size_t operators = 10;        //!< plays when thresholds is empty, >= 1
  std::vector<double> thresholds{};  //!< nominal r_j, 0 = r_0 < ...; empty = uniform (as PI)
  double rate_gain = 0.0;            //!< beta >= 0 [s], fixed
  double sample_time = 1.0;          //!< Ts > 0 [s] of the record
  double rate_filter = 0.0;          //!< T_f >= 0 [s]
  bool fit_offset = true;
  double min_linear_weight = 1e-9;  //!< p_0 >= this * (y range / v range), > 0
  double validate_fraction = 0.0;   //!< held out at the end of the record, [0, 1)
};

struct RateDependentPiFit {
  RateDependentPrandtlIshlinskii model;
  FitReport report;  //!< model "rate_dependent_pi", method "nnls (Lawson-Hanson)"
};

//! Throws hyst::Error for invalid data or options.
RateDependentPiFit fit_rate_dependent_prandtl_ishlinskii(
    std::span<const double> input, std::span<const double> output,
    const RateDependentPiFitOptions& options = {});

}  // namespace hyst
