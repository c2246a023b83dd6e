#pragma once
//! \file
//! The score of a dynamic model on periodic test data, as the nonlinear system identification
//! benchmarks define it: the model simulates each realisation (free run: no measured output is
//! used), and per output channel
//!
//!     RMSE_c     = mean over realisations and periods of sqrt(mean_n (y - y_model)^2)   [units]
//!     relative_c = RMSE_c / std(y_c)           (std over every sample of the channel)
//!
//! then both averaged over the channels. A simulation starts either from rest, with the first
//! `transient_samples` of each realisation left out, or (periodic) in periodic steady state: the
//! state that the first period's input returns to after one period, so that no transient needs
//! leaving out.

#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "hyst/dynamics/free_run_check.hpp"
#include "hyst/dynamics/periodic_signals.hpp"
#include "hyst/dynamics/state_space.hpp"

namespace hyst {

struct ChannelScore {
  double rmse = 0.0;            //!< [output units]
  double relative_error = 0.0;  //!< RMSE / std of the measured channel
  double output_std = 0.0;      //!< std of the measured channel [output units]
};

struct SimulationScore {
  std::vector<ChannelScore> channels;
  double mean_rmse = 0.0;
  double mean_relative_error = 0.0;
  std::size_t scored_samples = 0;  //!< per channel, over every realisation and period
  RunawayCount runaway;            //!< simulated samples far outside the measured range
};

struct ScoreOptions {
  bool periodic = false;              //!< start each realisation in periodic steady state
  std::size_t transient_samples = 0;  //!< left out at the start of each realisation
  //! The benchmark's submission rule: each realisation starts from the state estimated from its
  //! input and its first init_samples measured outputs (initial_state_estimate.hpp), which are
  //! then left out of the score (transient_samples is taken as init_samples). 0: not used.
  std::size_t init_samples = 0;
};

//! The transient a score leaves out: init_samples when given, else transient_samples. Throws
//! hyst::Error for init_samples with periodic (two ways to start).
std::size_t scored_transient(const ScoreOptions& options);

//! Simulates one realisation: input (periods * N x m) to output (periods * N x p); `one_period`
//! (N x m, the first period) is what a periodic simulation computes its initial state from.
using RealisationSimulator =
    std::function<Eigen::MatrixXd(const Eigen::MatrixXd& input, const Eigen::MatrixXd& one_period)>;

//! Scores any simulator. The realisations are simulated in order (a simulator that needs the
//! measured output of its realisation, ScoreOptions::init_samples, counts them). Throws hyst::Error
//! for mismatched sizes, a transient that leaves no sample of a period, a constant output channel
//! (std 0) or a non-finite simulated sample.
SimulationScore score_simulation(const PeriodicSignals& input, const PeriodicSignals& output,
                                 const RealisationSimulator& simulate,
                                 std::size_t transient_samples);

//! Scores a linear state-space model (periodic: x0 from StateSpace::periodic_state).
SimulationScore score_state_space(const StateSpace& model, const PeriodicSignals& input,
                                  const PeriodicSignals& output, const ScoreOptions& options = {});

//! One realisation of a signal set as a record: periods * N rows, one column per channel.
Eigen::MatrixXd realisation_record(const PeriodicSignals& signals, std::size_t realisation);

}  // namespace hyst
