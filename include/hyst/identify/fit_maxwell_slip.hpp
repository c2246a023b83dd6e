#pragma once
//! \file
//! Identification of a Maxwell-slip model from one position/force record: for fixed slip
//! displacements D_i the element deflections delta_i[k] (stop operators) follow from the
//! position alone, and the force is linear in the stiffnesses:
//!
//!     F[k] = F_off + k_lin x[k] + sum_i k_i delta_i[k]
//!     min_{k_i >= 0, k_lin >= 0, F_off} sum_k (F_meas[k] - F[k])^2
//!
//! solved by NNLS; the break-away forces follow as f_i = k_i D_i. Elements whose stiffness comes
//! out 0 are dropped. Default slip displacements: D_i = i (x_max - x_min) / (2 (N + 1)), i = 1..N:
//! an element with D >= (x_max - x_min)/2 would never slip after the first reversal and act as a
//! linear spring (collinear with k_lin). Initial state: relaxed springs at the first position.

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/identify/fit_report.hpp"
#include "hyst/models/maxwell_slip.hpp"

namespace hyst {

struct MaxwellSlipFitOptions {
  std::size_t elements = 10;  //!< N when slip_displacements is empty, >= 1
  //! D_i [position units], > 0 and strictly increasing; empty = uniform (file comment).
  std::vector<double> slip_displacements{};
  bool fit_linear_stiffness = true;  //!< fit k_lin >= 0; false = 0
  bool fit_offset = true;            //!< fit F_off; false = 0
  double validate_fraction = 0.0;    //!< held out at the end of the record, [0, 1)
};

struct MaxwellSlipFit {
  MaxwellSlip model;
  MaxwellSlip::State initial_state;  //!< relaxed at the record's first position
  FitReport report;                  //!< model "maxwell_slip", method "nnls (Lawson-Hanson)"
};

//! Throws hyst::Error for invalid data or options, or when every stiffness comes out 0.
MaxwellSlipFit fit_maxwell_slip(std::span<const double> position, std::span<const double> force,
                                const MaxwellSlipFitOptions& options = {});

}  // namespace hyst
