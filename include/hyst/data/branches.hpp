#pragma once
//! \file
//! A record split into monotone branches between its reversal points (reversal_points.hpp).
//!
//! Branch boundaries are the first sample, every reversal point and the last sample; consecutive
//! branches share their boundary sample (the reversal), so the branches of a record cover every
//! sample exactly once apart from those shared ends. A branch is ascending when it ends at a
//! maximum (or, for the last branch, when it leaves a minimum), descending otherwise. Within a
//! branch the input may wiggle by up to the band, never more.

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace hyst::data {

enum class Direction : unsigned char { ascending, descending };

//! "ascending" or "descending".
std::string_view to_string(Direction direction);

struct Branch {
  std::size_t first = 0;  //!< index of the first sample
  std::size_t last = 0;   //!< index of the last sample (inclusive), > first
  Direction direction = Direction::ascending;

  std::size_t samples() const { return last - first + 1; }
};

//! The branches of `input`. Throws hyst::Error as reversal_points() does, and when the input never
//! moves by more than `band` (its range is not larger than the band: no branch at all).
std::vector<Branch> branches(std::span<const double> input, double band);

}  // namespace hyst::data
