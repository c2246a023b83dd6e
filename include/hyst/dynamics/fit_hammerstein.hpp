#pragma once
//! \file
//! A Hammerstein system fitted to periodic experiments on the simulation error, starting from a
//! fitted linear model (fit_state_space.hpp): each input u_i passes through its own PI model
//! w_i = PI_i[u_i], whose outputs drive the MIMO linear block (HystereticLfr::hammerstein). Each
//! PI has thresholds at fixed fractions of the largest |u_i| over the data; the weight of its
//! r = 0 play is held at 1 (the linear block carries the gain), so the fit starts at the linear
//! model. The other weights, the poles of the linear block (when its A is in real modal form, as
//! fit_state_space returns it) and its B, C and D are fitted jointly by Levenberg-Marquardt
//! (Ceres, with the Jacobian from the simulation's forward sensitivities) on the free-run
//! simulation error of every realisation, started in the model's own periodic steady state, each
//! period after the first scored, each experiment's channels weighted by 1 / their standard
//! deviation (the benchmark's relative error).
//!
//! A hysteresis ahead of the dynamics distorts and scales each input with its amplitude; it cannot
//! move a resonance (fit_hysteretic_lfr.hpp's feedback can).

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/core/progress.hpp"
#include "hyst/dynamics/best_linear_approximation.hpp"
#include "hyst/dynamics/fit_hysteretic_lfr.hpp"
#include "hyst/dynamics/hysteretic_lfr.hpp"
#include "hyst/dynamics/state_space.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {

struct HammersteinFitOptions {
  //! PI thresholds as fractions of the largest |u_i|, increasing from 0; at most
  //! kMaxThresholdFractions (fit_hysteretic_lfr.hpp).
  std::vector<double> threshold_fractions = {0.0, 0.05, 0.1, 0.2, 0.4, 0.7};
  //! Accepted Levenberg-Marquardt steps (one Jacobian each; rejected trial steps cost one
  //! simulation each and are not counted).
  std::size_t max_iterations = 30;
  std::size_t threads = 2;           //!< realisations simulated in parallel
  bool fit_poles = true;             //!< fit the linear block's poles (real modal form)
  bool fit_io_matrices = true;       //!< fit its B, C and D
  double max_pole_radius = 0.99999;  //!< bound on every fitted pole's magnitude
  ProgressCallback progress{};       //!< told before the fit and when it ends
};

struct HammersteinFit {
  HystereticLfr<PrandtlIshlinskii> model;  //!< the Hammerstein system as an LFR (z = u)
  FitReport report;  //!< fit: relative to the measured outputs of the scored periods
};

//! Throws hyst::Error for no experiment, experiments whose channel counts differ from the linear
//! model's, fewer than 2 periods in a realisation (the first is not scored), thresholds that do not
//! increase from 0, an input that is zero throughout, or a pole beyond max_pole_radius.
HammersteinFit fit_hammerstein(const StateSpace& linear,
                               std::span<const PeriodicExperiment> experiments,
                               const HammersteinFitOptions& options = {});

}  // namespace hyst
