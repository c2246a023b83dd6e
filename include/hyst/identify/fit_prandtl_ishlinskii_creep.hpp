#pragma once
//! \file
//! Identification of the PI model with creep (prandtl_ishlinskii_creep.hpp) from records sampled
//! at one sample time: for fixed thresholds r_j and time constants tau_i the plays w_j[k] and the
//! creep elements z_ij[k] follow from the input alone, and the output is linear in all weights,
//!
//!     min sum_records sum_k (y_meas[k] - y_off - sum_j p_j w_j[k] - sum_ij c_ij z_ij[k])^2
//!     subject to p_0 >= eps, p_j >= 0 (j >= 1), c_ij >= 0,
//!
//! solved together by NNLS (hysteresis and creep weights at once, Kuhnen's approach). Records of
//! the same actuator at different rates identify the creep: a slow triangle creeps further than a
//! fast one between the same voltages, and only the creep part can tell them apart. Every record
//! starts from the stated initial state: `virgin` (every play and lag at 0, as the PI fit) or
//! `periodic` (each record is one period in steady state: PrandtlIshlinskiiCreep::periodic_state()
//! of its input at its sample time).
//!
//! Defaults: thresholds as for the PI fit (uniform below half the input range of all records);
//! time constants log-spaced from 10 Ts (the shortest sample time) to the longest record's
//! duration, `lags` of them (a creep slower than the records cannot be identified from them).
//!
//! The creep law. With `creep_law = free` every c_ij is a free weight >= 0: the lags slower than
//! the records' holds are barely identified and extrapolate arbitrarily (a longer hold runs away,
//! or stops creeping). With `creep_law = logarithmic` the time constants span far beyond the
//! records, `lags_per_decade` per decade from 10 Ts to `longest_time_constant` (1e5 s), and the
//! weights of each play are held smooth in log tau by the penalty
//!
//!     law_smoothing^2 * sum_j |w_j - mean w_j|^2 * sum_i (c_{i+1,j} - c_ij)^2
//!
//! added to the least squares (|w_j - mean w_j|: the norm of play j's column, so that the
//! penalty scales with the record as its misfit does; lambda chosen by forward validation on the
//! fit data unless given). Equal weights per lag are a logarithmic
//! creep law, y(t) ~ y(0+) (1 + gamma log10(t / t0)) (pi_logarithmic_creep()): where the records
//! say nothing (the slow lags) the penalty keeps the weights on the law the identified lags set,
//! so a hold longer than any in the records continues to creep by the same amount per decade.
//!
//! Leakage. With `fit_leakage` the output carries the drift of a leakage current
//! (PrandtlIshlinskiiCreep: g sum Ts v + i0 t), two more unknowns identified from the holds,
//! where it is the only term that keeps growing linearly in time: a conduction g >= 0 and an
//! offset current i0 of either sign (a tester's integrator offset, or a leakage compensation
//! that does not match the sample).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "hyst/identify/creep_law.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"

namespace hyst {

struct PiCreepFitOptions {
  std::size_t operators = 10;        //!< plays when `thresholds` is empty, >= 1
  std::vector<double> thresholds{};  //!< r_j, 0 = r_0 < ...; empty = uniform (as the PI fit)
  //! Time constants when `time_constants` is empty; 0: no creep, the rate-independent PI fitted
  //! the same way (the yardstick of a creep fit).
  std::size_t lags = 5;
  std::vector<double> time_constants{};  //!< tau_i [s], increasing; empty = log-spaced
  double sample_time = 1.0;  //!< Ts > 0 [s] of every record (when sample_times is empty)
  //! Several records: Ts > 0 [s] of each (records at different rates need not share one; the
  //! lags are discretised exactly for each). Empty: `sample_time` for all. The fitted model is
  //! discretised at the first record's (PrandtlIshlinskiiCreep::at_sample_time() for others).
  std::vector<double> sample_times{};
  bool fit_offset = true;
  double min_linear_weight = 1e-9;  //!< p_0 >= this * (y range / v range), > 0
  double validate_fraction = 0.0;   //!< one record: held out at its end, [0, 1)
  //! The PI fit's vocabulary: virgin or periodic (see the file comment).
  PiFitOptions::InitialState initial_state = PiFitOptions::InitialState::virgin;
  CreepLaw creep_law = CreepLaw::free;  //!< free weights or a smooth spectrum (file comment)
  //! logarithmic: the penalty's weight lambda in [0, 1e6] (0: the long span, weights free). Not
  //! set: chosen from 0.01, 0.03, 0.1, 0.3 and 1 by forward validation on the fit data alone
  //! (one record: fitted on its first 70 %, scored on the rest continued from there; several:
  //! fitted on all but the last, scored on the last), the choice named in the report's method.
  std::optional<double> law_smoothing = std::nullopt;
  std::size_t lags_per_decade = 2;     //!< logarithmic, without time_constants: 1 .. 12
  double longest_time_constant = 1e5;  //!< logarithmic, without time_constants [s]
  //! Fit the leakage conductance g and current i0 (file comment); false: both 0.
  bool fit_leakage = false;
};

struct PiCreepFit {
  PrandtlIshlinskiiCreep model;
  //! The state the fit started the (first) record from.
  PrandtlIshlinskiiCreep::State initial_state;
  FitReport report;  //!< model "pi_creep", method "nnls (Lawson-Hanson)"
};

//! One record; the last `validate_fraction` of it is held out and reported as validation.
//! Throws hyst::Error for invalid data or options.
PiCreepFit fit_prandtl_ishlinskii_creep(std::span<const double> input,
                                        std::span<const double> output,
                                        const PiCreepFitOptions& options = {});

//! Several records of one actuator (e.g. one triangle at several rates), fitted together; the
//! report's fit metrics are over all of them. `validate_fraction` must be 0: hold out a record
//! instead. Throws hyst::Error naming the record ("records[1]") for invalid data.
PiCreepFit fit_prandtl_ishlinskii_creep(std::span<const FitRecord> records,
                                        const PiCreepFitOptions& options = {});

}  // namespace hyst
