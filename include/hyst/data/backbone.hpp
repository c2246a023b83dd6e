#pragma once
//! \file
//! The backbone (centre line) of a hysteresis loop and its half-width, on a common input grid.
//!
//! For one loop (a cycle, cycles.hpp), taken as closed and started at its first reversal point so
//! that the record's start does not split a branch, the longest ascending and the longest
//! descending branch (branches.hpp) are interpolated linearly at the same inputs: `points` uniform
//! values over the input range both branches cover. Then
//!     centre     = (ascending + descending) / 2   the backbone: the loop without its hysteresis,
//!                                                 e.g. an anhysteretic B(H) curve or the mean
//!                                                 voltage-displacement characteristic of a piezo
//!     half_width = (descending - ascending) / 2   half the loop's vertical opening (> 0 for the
//!                                                 usual counter-clockwise loop)
//! Example: x = A sin t, y = B sin(t - phi) gives centre = (B/A) cos(phi) x and
//! half_width = B sin(phi) sqrt(1 - x^2/A^2).
//! On a branch that wiggles within the band, the first passage through each grid input is used.

#include <cstddef>
#include <span>
#include <vector>

namespace hyst::data {

struct Backbone {
  std::vector<double> input;       //!< the common grid, increasing
  std::vector<double> ascending;   //!< output of the ascending branch at each input
  std::vector<double> descending;  //!< output of the descending branch
  std::vector<double> centre;      //!< (ascending + descending) / 2
  std::vector<double> half_width;  //!< (descending - ascending) / 2
};

//! The backbone of the loop traced by samples first..last (inclusive) of a record, with hysteresis
//! band `band` for the branches. Throws hyst::Error for invalid data, a range outside the record,
//! points < 2, or a loop without both an ascending and a descending branch over a common input
//! range.
Backbone backbone(std::span<const double> input, std::span<const double> output, double band,
                  std::size_t first, std::size_t last, std::size_t points = 101);

}  // namespace hyst::data
