#pragma once
//! \file
//! The sample time of a record from its time column. Models with dynamics (creep, rate
//! dependence, oscillators) are discretised at one sample time, so a time column must be uniform:
//! a non-uniform one is refused with the place where it departs, rather than silently treated as
//! uniform.

#include <span>
#include <string_view>

namespace hyst::data {

//! The step of `times` [s], checked to be uniform: at least 2 finite, strictly increasing values
//! whose every step is within 0.1 % of the median step (plus the rounding of a value printed with
//! 7 significant digits); the mean step is returned. Throws hyst::Error naming `what` (e.g. "table
//! 2 column 'Time [s]'") and the first step that breaks the rule.
double uniform_sample_time(std::span<const double> times, std::string_view what);

}  // namespace hyst::data
