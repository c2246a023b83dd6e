#pragma once
//! \file
//! Identification of the modified PI model with creep (modified_prandtl_ishlinskii_creep.hpp) by
//! one NNLS in Kuhnen's equation-error form, from one record or several records at different
//! rates. Through the inverse dead-zone map S' = S^{-1} the model is linear in every weight:
//!
//!     S'(y[k] - y_off) = q + sum_j p_j w_j[k] + sum_ij c_ij z_ij[k],   S'(z) = sum_i g'_i
//!     S_{d'_i}(z)
//!
//! (w_j, z_ij: the plays and creep lags of the measured input at each record's sample time;
//! g'_0 = 1 fixes the scale shared by Gamma_c and S). Hysteresis weights p_j, creep weights c_ij
//! and the slopes of S' are found together under the bounds that keep the model invertible:
//! p_0 >= eps_p, p_j >= 0, c_ij >= 0 and every slope of S' >= eps_g
//! (fit_modified_prandtl_ishlinskii.hpp for the dead-zone part, fit_prandtl_ishlinskii_creep.hpp
//! for the creep part). The forward map is S = S'^{-1}. That residual is in Gamma units (the
//! equation error), which weights the samples by the slope of S' (heavily where the output
//! saturates); a second stage therefore minimises the output error y_off + S(Gamma_c[v]) - y by
//! bounded Levenberg-Marquardt (Ceres, analytic Jacobian) from the NNLS solution, over the same
//! weights and the slopes of S (its thresholds kept), under the same bounds. The report gives the
//! output error of the simulated model.
//!
//! Defaults: plays and time constants as the PI with creep fit (uniform thresholds below half the
//! input range; `lags` time constants log-spaced from 10 Ts to the longest record's duration);
//! y_off and the dead-zone thresholds as the modified PI fit, over the outputs of every record.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/modified_prandtl_ishlinskii_creep.hpp"

namespace hyst {

struct ModifiedPiCreepFitOptions {
  std::size_t operators = 10;        //!< plays when `thresholds` is empty, >= 1
  std::vector<double> thresholds{};  //!< r_j, 0 = r_0 < ...; empty = uniform (as the PI fit)
  std::size_t lags = 5;  //!< time constants when `time_constants` is empty; 0: the modified PI
  std::vector<double> time_constants{};  //!< tau_i [s], increasing; empty = log-spaced
  double sample_time = 1.0;              //!< Ts > 0 [s] of every record (sample_times empty)
  //! Several records: Ts > 0 [s] of each; the fitted model is discretised at the first one's.
  std::vector<double> sample_times{};
  std::size_t dead_zones = 3;  //!< l dead zones per side when dead_zone_thresholds is empty
  //! d'_i of the inverse map S' [output units, relative to y_off], increasing, containing 0.
  std::vector<double> dead_zone_thresholds{};
  std::optional<double> output_offset = std::nullopt;  //!< y_off; not set = mid-range of output
  double min_weight = 1e-6;  //!< relative lower bound of p_0 and of the slopes of S', > 0
  //! virgin (plays and lags at 0) or periodic (each record is one period in steady state).
  PiFitOptions::InitialState initial_state = PiFitOptions::InitialState::virgin;
  //! Limit the output to the fitted records' output range widened by output_margin (range) on
  //! each side; false = no limits.
  bool clamp_output = true;
  //! >= 0, fraction of the fitted output range. Not 0 as for the modified PI: creep carries a
  //! slower record beyond the range of faster ones.
  double output_margin = 0.1;
  //! Iterations of the output-error stage (0: the equation-error solution alone), at most
  //! kMaxIterations.
  std::size_t output_error_iterations = 200;
  double validate_fraction = 0.0;  //!< one record: held out at its end, [0, 1)

  static constexpr std::size_t kMaxIterations = 100000;
};

struct ModifiedPiCreepFit {
  ModifiedPrandtlIshlinskiiCreep model;
  //! The state the fit started the (first) record from.
  ModifiedPrandtlIshlinskiiCreep::State initial_state;
  FitReport report;  //!< model "modified_pi_creep"
};

//! One record; the last `validate_fraction` of it is held out and reported as validation.
//! Throws hyst::Error for invalid data or options.
ModifiedPiCreepFit fit_modified_prandtl_ishlinskii_creep(
    std::span<const double> input, std::span<const double> output,
    const ModifiedPiCreepFitOptions& options = {});

//! Several records of one actuator (e.g. one triangle at several rates), fitted together;
//! `validate_fraction` must be 0. Throws hyst::Error naming the record for invalid data.
ModifiedPiCreepFit fit_modified_prandtl_ishlinskii_creep(
    std::span<const FitRecord> records, const ModifiedPiCreepFitOptions& options = {});

}  // namespace hyst
