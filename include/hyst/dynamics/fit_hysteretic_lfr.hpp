#pragma once
//! \file
//! A hysteretic LFR fitted to periodic experiments on the simulation error, starting from a
//! fitted linear model (fit_state_space.hpp). The structure follows a piezo stage: the hysteresis
//! sits in the actuators, whose forces enter the structure where the inputs do, and it is driven by
//! the actuators' elongations, which the measured displacements see through a linear map. So the
//! feedback is
//!
//!     z = T (Cy x + Dyu u)                  (T: q x p, the elongations from the outputs)
//!     w_i = PI_i[z_i]                       (one PI model per channel, q = p by default)
//!     u_eff = u + Theta w                   (Theta: m x q, enters where the inputs do)
//!
//! i.e. the LFR's linear block has Bw = Bu Theta, Dyw = Dyu Theta, Cz = T Cy, Dzu = T Dyu. With
//! Theta = 0 it is the linear model. Each PI has thresholds at fixed fractions of the largest |z_i|
//! over the data (the first 0, its weight held at 1: it is the linear stiffness change, the others,
//! starting at 0.1, make it depend on the amplitude); Theta, T and the other weights are fitted by
//! Levenberg-Marquardt (Ceres, with the Jacobian from the simulation's forward sensitivities) on
//! the free-run simulation error of every realisation, started in the model's own periodic steady
//! state (HystereticLfr::periodic_state, at every parameter vector tried: a vector whose loop has
//! none for a training input is refused), each period after the first scored, each experiment's
//! channels weighted by 1 / their standard deviation (the benchmark's relative error, so the fitted
//! cost is the periodic score). With fit_poles, the poles of the linear block (in real modal form)
//! are fitted with them, and with fit_io_matrices its B, C and D: all parameters jointly. Then
//! (general_iterations) every matrix of the LFR is freed from that structure and fitted on, from
//! where it ended.

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/core/progress.hpp"
#include "hyst/dynamics/best_linear_approximation.hpp"
#include "hyst/dynamics/hysteretic_lfr.hpp"
#include "hyst/dynamics/state_space.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {

//! The most hysteresis channels a fit takes: the fit's cost grows with the square of its
//! parameters, about 2 n + 10 per channel for n states.
inline constexpr std::size_t kMaxFeedbackChannels = 64;

//! The most PI thresholds (plays) per hysteresis channel a fit takes (hysteretic LFR and
//! Hammerstein fits alike): each play is a parameter of every channel, and the fit's cost grows
//! with the square of its parameters (the fits use 6).
inline constexpr std::size_t kMaxThresholdFractions = 100;

struct HystereticLfrFitOptions {
  //! PI thresholds as fractions of the largest |z_i|, increasing from 0; at most
  //! kMaxThresholdFractions.
  std::vector<double> threshold_fractions = {0.0, 0.02, 0.05, 0.1, 0.2, 0.4};
  //! Accepted Levenberg-Marquardt steps in the structure above (one Jacobian each; rejected trial
  //! steps cost one simulation each and are not counted).
  std::size_t max_iterations = 30;
  //! Then this many accepted steps with every matrix of the LFR free: the feedback paths Bw, Cz,
  //! Dyw and Dzu no longer follow B, C and D through Theta and T, so the fit finds where in the
  //! structure the hysteresis acts (fit_poles still decides on the poles). 0: the structure above
  //! only.
  std::size_t general_iterations = 20;
  //! Hysteresis channels q; 0: one per output. Channel i = k p + j starts driven by output j, and
  //! for k > 0 also by half of output (j + k) mod p: the channels must differ, or they would stay
  //! copies of each other. At most kMaxFeedbackChannels.
  std::size_t feedback_channels = 0;
  std::size_t threads = 2;  //!< realisations simulated in parallel
  //! Fit the poles of the linear block too (radius and angle of each), when its A is in real modal
  //! form (fit_state_space's is): the feedback then shifts the resonances around poles that need
  //! not be the pooled linear fit's compromise.
  bool fit_poles = true;
  //! Fit B, C and D of the linear block too (all its parameters jointly with the feedback's).
  bool fit_io_matrices = true;
  double max_pole_radius = 0.99999;  //!< bound on every fitted pole's magnitude
  ProgressCallback progress{};       //!< told before the fit and when it ends
};

struct HystereticLfrFit {
  HystereticLfr<PrandtlIshlinskii> model;
  FitReport report;  //!< fit: relative to the measured outputs of the scored periods
};

//! Throws hyst::Error for no experiment, experiments whose channel counts differ from the linear
//! model's, fewer than 2 periods in a realisation (the first is not scored), thresholds that do not
//! increase from 0, more than kMaxFeedbackChannels channels, or a linear model whose periodic
//! state does not exist.
HystereticLfrFit fit_hysteretic_lfr(const StateSpace& linear,
                                    std::span<const PeriodicExperiment> experiments,
                                    const HystereticLfrFitOptions& options = {});

}  // namespace hyst
