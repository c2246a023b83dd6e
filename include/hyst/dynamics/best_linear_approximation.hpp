#pragma once
//! \file
//! The best linear approximation (BLA) of a multi-input multi-output system from periodic data:
//! its frequency response at every excited DFT line, with the variances that say how far it can
//! be trusted (Pintelon & Schoukens, "System Identification: A Frequency Domain Approach",
//! 2nd ed., ch. 3 and 4: the "robust method" for random-phase multisines).
//!
//! Data: m inputs and p outputs, R realisations of P periods of N samples each. The
//! realisations come in blocks of m (one per input); within a block the input spectra at a line
//! form an invertible m x m matrix U (orthogonal multisines make it well conditioned). Per block
//! and period, G = Y U^-1 (p x m); averaged over the periods of a block it is that block's
//! estimate, and averaged over the blocks it is the BLA. The spread over periods is noise
//! (variance of the mean over periods and blocks); the spread over blocks is noise plus the
//! stochastic nonlinear distortions (random phases give different distortions), the total
//! variance that a parametric fit should weight by.
//!
//! Several experiments (e.g. amplitude levels) pool their blocks into one BLA: the linear model
//! that serves them all.

#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "hyst/dynamics/periodic_signals.hpp"

namespace hyst {

//! One periodic experiment: inputs and outputs with the same samples, realisations and periods.
struct PeriodicExperiment {
  PeriodicSignals input;   //!< m channels
  PeriodicSignals output;  //!< p channels
};

struct BlaOptions {
  //! A line is excited when its input power, averaged over channels, realisations and periods, is
  //! at least this fraction of the largest line's. DC (line 0) and the Nyquist line never count.
  double excitation_threshold = 1e-4;
  //! Periods dropped at the start of each realisation (a transient before steady state).
  std::size_t transient_periods = 0;
};

struct BestLinearApproximation {
  double sample_time = 0.0;                //!< Ts [s]
  std::size_t samples = 0;                 //!< N per period
  std::vector<std::size_t> lines;          //!< excited DFT lines k; frequency k / (N Ts)
  std::vector<Eigen::MatrixXcd> response;  //!< G at each line, p x m
  //! Variance of each entry of G from the noise (spread over periods), per line; empty with one
  //! period.
  std::vector<Eigen::MatrixXd> noise_variance;
  //! Variance of each entry of G from noise and nonlinear distortions (spread over blocks), per
  //! line; empty with one block.
  std::vector<Eigen::MatrixXd> total_variance;
  std::size_t blocks = 0;   //!< blocks of m realisations averaged
  std::size_t periods = 0;  //!< periods per block used

  std::size_t inputs() const { return response.empty() ? 0 : std::size_t(response[0].cols()); }
  std::size_t outputs() const { return response.empty() ? 0 : std::size_t(response[0].rows()); }
  //! Frequencies of the lines [Hz].
  std::vector<double> frequencies() const;
};

//! The BLA of one or several experiments (pooled), all with the same N, inputs and outputs.
//! Throws hyst::Error naming the experiment for mismatched sizes, a realisation count that is not
//! a whole number of blocks of m, no excited line, a singular input matrix at an excited line
//! (the realisations of a block do not excite every input independently), non-finite samples.
BestLinearApproximation estimate_bla(std::span<const PeriodicExperiment> experiments,
                                     double sample_time, const BlaOptions& options = {});

}  // namespace hyst
