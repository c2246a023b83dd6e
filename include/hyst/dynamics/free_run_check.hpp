#pragma once
//! \file
//! Whether a free-run simulation can be trusted: a linear block with a pole outside the unit circle
//! grows without bound, and a simulated output far outside everything measured has run away (a
//! loop that diverges, or one that settled on another equilibrium). `hyst evaluate` and Python's
//! `hyst.evaluate` turn these into warnings, or errors with --strict / strict=True.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hyst/dynamics/periodic_signals.hpp"
#include "hyst/dynamics/state_space.hpp"

namespace hyst {

//! A simulated sample has run away when it lies beyond its channel's measured range by more than
//! this many widths of that range: a stable model with a poor fit stays well inside (its error is
//! of the order of the range), a diverging one leaves it by orders of magnitude.
inline constexpr double kRunawayRangeWidths = 10.0;

//! Simulated samples that ran away, and where the first one is (all indices from 0).
struct RunawayCount {
  std::size_t samples = 0;      //!< every channel, every realisation
  std::size_t realisation = 0;  //!< of the first one (in realisation order, then time)
  std::size_t sample = 0;       //!< of the first one, in its realisation's record
  std::size_t channel = 0;      //!< of the first one
};

//! The measured range of each channel, which a run-away sample leaves (minimum, maximum).
struct ChannelRange {
  double minimum = 0.0;
  double maximum = 0.0;
};

//! The range of every channel of `signals`, over all realisations and periods.
std::vector<ChannelRange> channel_ranges(const PeriodicSignals& signals);

//! Adds the samples of one realisation's simulated record (samples x channels) that lie beyond
//! `ranges` by more than kRunawayRangeWidths widths to `count`.
void count_runaway(const Eigen::MatrixXd& simulated, const std::vector<ChannelRange>& ranges,
                   std::size_t realisation, RunawayCount& count);

//! Largest pole magnitude above which a linear block counts as unstable: 1 (the unit circle).
inline constexpr double kUnstablePoleMagnitude = 1.0;

//! One sentence per reason not to trust a free-run score: a pole of `linear` outside the unit
//! circle, samples that ran away. Empty when there is none.
std::vector<std::string> free_run_warnings(const StateSpace& linear, const RunawayCount& runaway);

}  // namespace hyst
