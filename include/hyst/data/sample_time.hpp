#pragma once
//! \file
//! The sample time of a record from its time column. Models with dynamics (creep, rate
//! dependence, oscillators) are discretised at one sample time, so a time column must be uniform:
//! a non-uniform one is refused with the place where it departs, rather than silently treated as
//! uniform.

#include <span>
#include <string_view>
#include <vector>

namespace hyst::data {

//! Relative tolerance within which two sample times are the same (0.1 %): steps of a uniform
//! record, a record's sample time against a discrete model's.
inline constexpr double kSampleTimeTolerance = 1e-3;

//! True when `a` and `b` (> 0) are the same sample time within kSampleTimeTolerance.
bool same_sample_time(double a, double b);

//! A record's time axis: uniform (one sample time) or not (the step before each sample).
struct TimeAxis {
  //! The uniform step [s]; for a non-uniform axis the median step.
  double sample_time = 1.0;
  //! Empty when uniform; else one per sample, steps[k] = t[k] - t[k-1] and steps[0] = steps[1]
  //! (the step into the first sample is taken to be the next one).
  std::vector<double> steps;
  bool uniform() const { return steps.empty(); }
};

//! The time axis of `times` [s]: at least 2 finite, strictly increasing values, uniform when
//! every step lies within the rule of uniform_sample_time(). Throws hyst::Error naming `what`
//! and the first value that breaks the rule.
TimeAxis time_axis(std::span<const double> times, std::string_view what);

//! The step of `times` [s], checked to be uniform: at least 2 finite, strictly increasing values
//! whose every step is within 0.1 % of the median step (plus the rounding of a value printed with
//! 7 significant digits); the mean step is returned. Throws hyst::Error naming `what` (e.g. "table
//! 2 column 'Time [s]'") and the first step that breaks the rule.
double uniform_sample_time(std::span<const double> times, std::string_view what);

}  // namespace hyst::data
