#pragma once
//! \file
//! Identification of a neural NARX model with play-operator regressors (models/narx.hpp).
//!
//! Method: nonlinear least squares on the one-step-ahead prediction error (series-parallel
//! training: the regressors hold the measured past outputs), Levenberg-Marquardt in Ceres with
//! an exact Jacobian by backpropagation, plus a small ridge penalty on the network weights:
//!
//!     min_theta  sum_k ( s(y[k]) - f_theta(s(phi[k])) )^2 + lambda N sum_hidden theta_i^2
//!
//! Start: the least-squares ARX model for the linear term, network weights drawn from a uniform
//! (Glorot) distribution by a std::mt19937_64 seeded with `seed` - the same seed and data give
//! the same model. Ceres runs single-threaded, so the result is reproducible bit for bit. With
//! `starts` > 1 the whole training runs from that many seeds and the best run is kept (the
//! multistart engine of every Ceres-based fitter, without its screening: a few iterations say
//! little about where a network's training ends).
//!
//! Then (simulation_iterations > 0 and n_y > 0) the same weights are refined on the simulation
//! error itself - the free run over the training rows from their first measured lags - with the
//! Jacobian by forward sensitivities (real-time recurrent learning), S_k = d y_k / d theta =
//! d f / d theta + sum_i (d f / d y_{k-i}) S_{k-i}. One-step training alone weighs the noise in
//! the measured lags like signal and can give a model that drifts in free run.
//!
//! Early stopping: the last `early_stopping_fraction` of the fit part is not trained on; after
//! every iteration the model is run there in free run (its own past outputs, started from the
//! measured history) and the parameters with the lowest free-run error are kept. The iteration
//! stops when that error has not improved for `patience` iterations. Free run is what matters
//! for compensation, and one-step training alone can give a model that drifts or diverges in
//! free run.
//!
//! Report (FitReport): `fit` and `validation` are free-run errors (the fit part from rest at its
//! first sample; the validation part continuing the free run from the state reached at the end
//! of the fit part, or a separate record from rest at its first sample); costs are one-step
//! costs on the training rows. The one-step-ahead errors are in NarxFit and in the message.
//!
//! Data: finite, input and output not constant, at least as many training rows as parameters.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "hyst/core/progress.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/narx.hpp"

namespace hyst {

struct NarxFitOptions {
  std::size_t input_lags = 2;   //!< n_u
  std::size_t output_lags = 2;  //!< n_y
  //! Number of plays when play_thresholds is empty: r_i = i / (q + 1) * (input range) / 2.
  std::size_t plays = 4;
  std::vector<double> play_thresholds;       //!< given thresholds [input units]
  std::vector<std::size_t> hidden_sizes{8};  //!< one or two hidden layers
  std::uint64_t seed = 1;                    //!< initial network weights
  //! Initialisations (seeds seed, seed + 1, ...), each trained in full; the one with the lowest
  //! free-run error on the early-stopping part (without one: the lowest final cost) is kept.
  std::size_t starts = 1;
  std::size_t max_iterations = 100;  //!< one-step LM iterations (>= 1)
  //! Told before each start of the fit and its refinement (task "starts"); may be empty.
  ProgressCallback progress{};
  //! LM iterations on the simulation (free-run) error after the one-step stage; 0: none.
  std::size_t simulation_iterations = 100;
  std::size_t patience = 15;             //!< early stopping (>= 1)
  double early_stopping_fraction = 0.2;  //!< of the fit part, [0, 0.9]; 0: none
  double regularization = 1e-6;          //!< lambda >= 0 (normalised units)
  //! Ts [s] of the record, stored in the model (its lags count samples of this step); 0: not
  //! stated, the model then runs on any record sample by sample.
  double sample_time = 0.0;
  //! Fraction of the record, at its end, held out for validation (data_split.hpp); [0, 1).
  double validate_fraction = 0.0;
};

struct NarxFit {
  Narx model;
  Narx::State initial_state;  //!< at rest at the first input and output of the record
  FitReport report;           //!< model "narx"; fit/validation errors in free run
  ErrorMetrics one_step_fit;  //!< one-step-ahead error on the fit part
  std::optional<ErrorMetrics> one_step_validation;
  std::size_t best_iteration = 0;  //!< the iteration whose parameters were kept (0: the start)
  std::size_t best_stage = 1;      //!< its stage: 1 one-step, 2 simulation error
};

//! Every trained start is run free on the whole fit part (from rest at its first sample); one
//! that leaves the measured output range by more than 10 of its widths has run away and is not
//! kept. When every start runs away, they are trained again with a ridge 1000 times stronger;
//! when those run away too, the report's termination is "failed" with the message "unstable in
//! free run: ..." naming the sample where the first start left the range.
//!
//! Fits one record, optionally holding out its last part for validation. Throws hyst::Error for
//! invalid data (lengths differ, non-finite sample with its index, constant input or output, too
//! few samples for the parameters) or options (named).
NarxFit fit_narx(std::span<const double> input, std::span<const double> output,
                 const NarxFitOptions& options = {});

//! Same, validated on a separate record (free run from rest at its first sample);
//! options.validate_fraction must be 0.
NarxFit fit_narx(std::span<const double> input, std::span<const double> output,
                 std::span<const double> validation_input,
                 std::span<const double> validation_output, const NarxFitOptions& options = {});

}  // namespace hyst
