#pragma once
//! \file
//! Identification of the butterfly strain model with creep (butterfly_strain_creep.hpp) from the
//! voltage v and the strain y alone (the polarisation is latent, normalised as in the butterfly
//! fit: switching part of total weight 1).
//!
//! 1. The switching part and the map: the butterfly strain fit of the record
//!    (fit_butterfly_strain.hpp, Levenberg-Marquardt on relay weights and map), which gives the
//!    switching polarisation P_s[k] of every sample.
//! 2. The creep weights: with the plays and lags of the creep part fixed by the input, the creep
//!    C = Z c is linear in the weights c >= 0, and the strain y = q(P_s + Z c) + d v is linearised
//!    about the current weights c0 (Gauss-Newton):
//!
//!        min_{c >= 0} || y - q(P_0) - d v - diag(q'(P_0)) Z (c - c0) ||^2 + ||D c||^2,
//!        P_0 = P_s + Z c0,
//!
//!    one NNLS (Lawson-Hanson), D the logarithmic law's smoothness penalty across lags (as the PI
//!    with creep fit, fit_prandtl_ishlinskii_creep.hpp); then the map y_off, d, q_n by linear
//!    least squares on P_s + Z c. `rounds` such rounds, the best strain fit kept.
//! The law's smoothing, when not given, is chosen from 0.01, 0.03, 0.1, 0.3 and 1 by forward
//! validation on the fit data alone (step 2 on the first 70 % of the fit part with step 1's
//! switching part, scored on the rest continued from there); the choice is named in the report.
//!
//! The leakage charge strains nothing, so it cannot be identified from a displacement: the fitted
//! model has none (add a measured one to the model file, or fit the polarisation record with
//! `pi_creep` and `fit_leakage`). Records start as the butterfly fit's `initial_state` says
//! (periodic by default: the creep's exact periodic steady state with it).
//! Common mistakes: a record with no hold (the lags slower than its period act as a constant and
//! the law is unidentified: say so with a fixed smoothing, or fit on a record with holds).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "hyst/core/progress.hpp"
#include "hyst/identify/creep_law.hpp"
#include "hyst/identify/fit_butterfly_strain.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/butterfly_strain_creep.hpp"

namespace hyst {

struct ButterflyCreepFitOptions {
  //! The switching part's and the map's options (levels, range, degree, field term, start,
  //! iterations); their validate_fraction, sample_time and progress are this struct's.
  ButterflyFitOptions switching{};
  std::size_t creep_operators = 3;         //!< plays of the creep part without creep_thresholds
  std::vector<double> creep_thresholds{};  //!< r_j, 0 = r_0 < ...; empty: uniform
  CreepLaw creep_law = CreepLaw::logarithmic;
  //! logarithmic: the penalty's weight in [0, 1e6]; not set: chosen (file comment).
  std::optional<double> law_smoothing = std::nullopt;
  std::size_t lags = 5;                  //!< free law, without time_constants: log-spaced lags
  std::vector<double> time_constants{};  //!< tau_i [s], increasing; empty: by the law
  std::size_t lags_per_decade = 2;       //!< logarithmic, without time_constants: 1 .. 12
  double longest_time_constant = 1e5;    //!< logarithmic, without time_constants [s]
  double sample_time = 1.0;              //!< Ts > 0 [s] of the record
  //! Several records: Ts > 0 [s] of each (the lags are discretised exactly for each); empty:
  //! `sample_time` for all. The model is discretised at the first record's.
  std::vector<double> sample_times{};
  //! With measured polarisation only: fit the leakage charge g sum Ts v + i0 t (g >= 0) of the
  //! measured polarisation; the fits from the strain alone refuse it.
  bool fit_leakage = false;
  std::size_t rounds = 10;         //!< Gauss-Newton rounds of step 2, 1 .. 50
  double validate_fraction = 0.0;  //!< held out at the record's end, [0, 1)
  ProgressCallback progress{};     //!< told by the switching part's fit; may be empty
};

struct ButterflyCreepFit {
  ButterflyStrainCreep model;
  ButterflyStrainCreep::State initial_state;  //!< the state the record starts from
  FitReport report;                           //!< model "butterfly_strain_creep"
};

//! Fits one record (file comment). Throws hyst::Error for invalid data or options, naming the
//! option.
ButterflyCreepFit fit_butterfly_strain_creep(std::span<const double> input,
                                             std::span<const double> output,
                                             const ButterflyCreepFitOptions& options = {});

//! Several records of one sample fitted together, each at its own sample time and from its own
//! start (validate_fraction must be 0: hold out a record instead); the law's smoothing, when not
//! given, is chosen on the last record. Throws hyst::Error naming the record or the option.
ButterflyCreepFit fit_butterfly_strain_creep(std::span<const FitRecord> records,
                                             const ButterflyCreepFitOptions& options = {});

//! The fit with measured polarisation (records with v, P and y, e.g. an aixACCT export's V+, P1
//! and D1), in two stages:
//! 1. the measured polarisation P_m = P_off + sum_r mu_r s_r + sum_ij c_ij z_ij (+ g Q + i0 t
//!    with fit_leakage) by one NNLS over the relay, creep and leakage weights (mu, c, g >= 0),
//!    the law's penalty on c, its smoothing chosen on the last 30 % of the polarisation when not
//!    given;
//! 2. the map y = y_off + d v + sum q_n P^n by linear least squares on the model's P without the
//!    leakage charge (a leakage strains nothing).
struct ButterflyCreepTwoStageFit {
  ButterflyCreepFit fit;          //!< the chain v -> P -> y; its report is the strain's
  FitReport polarisation_report;  //!< stage 1: P_m(v) against the measured polarisation
};

//! Throws hyst::Error for invalid data or options (polarisation, input and output of one length).
ButterflyCreepTwoStageFit fit_butterfly_strain_creep_with_polarisation(
    std::span<const double> input, std::span<const double> polarisation,
    std::span<const double> output, const ButterflyCreepFitOptions& options = {});

}  // namespace hyst
