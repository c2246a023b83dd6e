#pragma once
//! \file
//! Resampling a record branch by branch, so that a fit weights the loop evenly instead of by the
//! time spent in each part (a slow or paused input leaves many nearly equal samples that would
//! otherwise dominate a least-squares cost).
//!
//! Each branch (branches.hpp) is resampled on its own and keeps its end samples exactly, so the
//! reversal points - all a rate-independent model remembers - are unchanged and the resampled
//! record drives such a model through the same loops. Between the ends the branch gets m
//! intervals of equal size with m = ceil(length / step):
//!   * on an input grid: equal input increments (length = |input change over the branch|);
//!   * by arc length: equal steps along the (input, output) curve, with input and output scaled
//!     by their ranges over the record (length = normalised arc length; step 0.01 = 1 % of the
//!     range).
//! Values in between are interpolated linearly between the two samples around the grid point: on
//! an input grid the first sample at or beyond the grid value in the branch's direction and the
//! one before it (a branch that wiggles within the band uses its first passage).

#include <span>
#include <vector>

namespace hyst::data {

struct ResampledRecord {
  std::vector<double> input;
  std::vector<double> output;
};

//! Resampled on a uniform input grid per branch, intervals at most `input_step` [input units].
//! Throws hyst::Error for invalid data, band or step (finite, > 0).
ResampledRecord resample_on_input_grid(std::span<const double> input,
                                       std::span<const double> output, double band,
                                       double input_step);

//! Resampled at uniform normalised arc length per branch, intervals at most `step`. Throws
//! hyst::Error for invalid data, band or step, and when input or output is constant.
ResampledRecord resample_by_arc_length(std::span<const double> input,
                                       std::span<const double> output, double band, double step);

}  // namespace hyst::data
