#pragma once
//! \file
//! Identification of the Bouc-Wen oscillator (bouc_wen_oscillator.hpp) from force/displacement
//! records by simulation-error minimisation with Ceres Solver.
//!
//!     theta = (m, c, k, alpha, beta gamma, beta delta, nu)      (nu held at 1 unless fit_nu)
//!     min_theta  sum_records sum_{k >= skip} ( y_meas[k] - y_sim,theta[k] )^2,  theta within
//!     bounds
//!
//! y_sim is the free-run simulation from rest (never the one-step-ahead prediction), so the fitted
//! model is the one that is good in simulation, the benchmark's figure of merit. beta is a gauge
//! (only beta gamma and beta delta enter the output): the returned model keeps beta of the first
//! start and reports gamma = (beta gamma) / beta, delta = (beta delta) / beta.
//!
//! Method: Levenberg-Marquardt (Ceres, dense QR) with exact derivatives by automatic
//! differentiation through the RK4 simulation (ceres::Jet); parameters are scaled by their
//! starting values. Several starts, each `screening_iterations`, the best continued up to
//! `max_iterations`. Default starts: a linear least-squares fit u = m y'' + c y' + K y (central
//! differences) gives m, c and the total stiffness K, split as k = f K, alpha = (1 - f) K with
//! f in {0.3, 0.6}; beta gamma, beta delta in {(0.4, -0.6), (0.4, 0.2)} / max|y|.
//!
//! Band-limited inputs: a record may carry its input oversampled (`oversampling` input samples per
//! output sample, e.g. from upsample_periodic()), then the model runs at Ts / oversampling and
//! output sample k is compared with the simulation after input sample k * oversampling. A
//! periodic record in steady state is fitted from rest with its first periods skipped (`skip`).

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/core/progress.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/bouc_wen_oscillator.hpp"

namespace hyst {

//! One force/displacement record: input u [N], output y [m]; oversampling and skip as the fit
//! needs them (a periodic record in steady state fitted from rest with its first periods skipped).
using BoucWenOscillatorRecord = FitRecord;

struct BoucWenOscillatorFitOptions {
  double sample_time = 1.0 / 750.0;  //!< of the output samples [s] > 0
  std::size_t substeps = 1;          //!< RK4 steps per input sample
  bool fit_nu = false;               //!< also fit nu (>= 1); otherwise nu of the start (1)
  //! Starting points (beta of the first sets the gauge); empty = data-derived starts.
  std::vector<BoucWenOscillator::Params> starts;
  //! Cost evaluations of the global stage (NLopt CRS2-LM over the bounded box) before the
  //! local starts; its best point is one more start. 0: data-derived starts only.
  std::size_t global_evaluations = 300;
  std::size_t screening_iterations = 4;
  std::size_t max_iterations = 1000;
  //! Told before each start of the fit and its refinement (task "starts"); may be empty.
  ProgressCallback progress{};
  double function_tolerance = 1e-9;
  //! Fraction of a single record, at its end, held out for validation; [0, 1).
  double validate_fraction = 0.0;
};

struct BoucWenOscillatorFit {
  BoucWenOscillator model;  //!< sample time Ts / oversampling of the first record
  FitReport report;         //!< model "bouc_wen_oscillator"
  std::size_t starts = 0;
  std::size_t best_start = 0;
};

//! Throws hyst::Error for invalid records (lengths, non-finite samples, constant output, skip too
//! large) or options. A fit that does not converge is reported in report.termination.
BoucWenOscillatorFit fit_bouc_wen_oscillator(std::span<const BoucWenOscillatorRecord> records,
                                             const BoucWenOscillatorFitOptions& options);

//! One record at the model's sample rate (oversampling 1, skip 0), optionally with the last
//! options.validate_fraction held out for validation (continuing the simulation).
BoucWenOscillatorFit fit_bouc_wen_oscillator(std::span<const double> input,
                                             std::span<const double> output,
                                             const BoucWenOscillatorFitOptions& options);

//! The data-derived starts of the file comment (linear least squares on central differences).
std::vector<BoucWenOscillator::Params> bouc_wen_oscillator_starts(std::span<const double> input,
                                                                  std::span<const double> output,
                                                                  double sample_time);

//! Free-run simulation of a record from rest (input oversampled as in the record), one output per
//! output sample. As in BoucWenOscillator::step(), the rest state lies one input sample before the
//! record (previous input = first input), so the result equals hyst::simulate() of the model with
//! that state when oversampling is 1.
std::vector<double> simulate_bouc_wen_oscillator(const BoucWenOscillator& model,
                                                 std::span<const double> input,
                                                 std::size_t oversampling);

}  // namespace hyst
