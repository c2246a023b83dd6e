#pragma once
//! \file
//! Identification of a Maxwell-slip model from one position/force record: for fixed slip
//! displacements D_i the element deflections delta_i[k] (stop operators) follow from the
//! position alone, and the force is linear in the stiffnesses:
//!
//!     F[k] = F_off + k_lin x[k] + s sum_i k_i delta_i[k]
//!     min_{k_i >= 0, k_lin >= 0, F_off} sum_k (F_meas[k] - F[k])^2
//!
//! The sign s is the loop orientation (maxwell_slip.hpp): given, or detected from the sign of the
//! area the fit record encloses in the (x, F) plane (shoelace formula, closed by the chord from the
//! last sample back to the first): A = 1/2 sum_k (F[k] + F[k+1]) (x[k+1] - x[k]) > 0 for a
//! clockwise loop, < 0 for a counter-clockwise one (0: clockwise).
//!
//! solved by NNLS; the break-away forces follow as f_i = k_i D_i. Elements whose stiffness comes
//! out 0 are dropped. Default slip displacements: D_i = i (x_max - x_min) / (2 (N + 1)), i = 1..N:
//! an element with D >= (x_max - x_min)/2 would never slip after the first reversal and act as a
//! linear spring (collinear with k_lin). Initial state: relaxed springs at the first position.

#include <cstddef>
#include <optional>
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
  //! Loop orientation; empty = detected from the sign of the enclosed area (file comment).
  std::optional<MaxwellSlip::Orientation> orientation{};
  double validate_fraction = 0.0;  //!< held out at the end of the record, [0, 1)
};

struct MaxwellSlipFit {
  MaxwellSlip model;
  MaxwellSlip::State initial_state;  //!< relaxed at the record's first position
  FitReport report;                  //!< model "maxwell_slip", method "nnls (Lawson-Hanson)"
};

//! Signed area the record (x, F) encloses, closed by the chord back to the first sample: > 0 for
//! a clockwise loop (file comment). Needs equal sizes.
double enclosed_area(std::span<const double> position, std::span<const double> force);

//! Throws hyst::Error for invalid data or options, or when every stiffness comes out 0 (the
//! message names the orientation used and the enclosed area).
MaxwellSlipFit fit_maxwell_slip(std::span<const double> position, std::span<const double> force,
                                const MaxwellSlipFitOptions& options = {});

}  // namespace hyst
