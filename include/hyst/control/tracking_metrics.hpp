#pragma once
//! \file
//! Figures of merit of a tracking run: y (measured output) against r (reference), u the control
//! effort signal (e.g. coil voltage).
//!
//! - rms_error = sqrt(mean (r - y)^2),  max_error = max |r - y|
//! - for a step from a to b at t_s (StepEvent): overshoot = max over t >= t_s of (y - b)/(b - a),
//!   in percent, clipped at 0; settling time = the time after t_s from which |y - b| stays
//!   within band |b - a| (2 % by default); NaN when it never settles or without a step
//! - control_effort = sqrt(mean u^2) (RMS of u)

#include <cstddef>
#include <optional>
#include <span>

#include "hyst/control/references.hpp"

namespace hyst::control {

struct TrackingMetrics {
  double rms_error = 0.0;
  double max_error = 0.0;
  double settling_time = 0.0;  //!< [s] after the step; NaN without a step or if never settled
  double overshoot = 0.0;      //!< [%]; NaN without a step
  double control_effort = 0.0;
};

//! hyst::Error for different lengths, empty or non-finite input, or a band not in (0, 1).
TrackingMetrics tracking_metrics(std::span<const double> reference, std::span<const double> output,
                                 std::span<const double> effort, double sample_time,
                                 const std::optional<StepEvent>& step, double band = 0.02);

}  // namespace hyst::control
