#pragma once
//! \file
//! A periodic record split into cycles (periods of the input).
//!
//! A cycle starts at the record's first sample, with anchor level a = input[0] and the direction d
//! of the first branch, and ends at the first sample at which the input - after it has passed one
//! maximum and one minimum reversal (reversal_points.hpp) - is back at or beyond a while moving in
//! direction d (a turning point that stops within `band` short of a counts as back, so that a
//! record starting at an extreme closes at each noisy return to it). The next cycle starts at that
//! sample (cycles share their boundary sample) and closes the same way, against the same anchor
//! level, so that drift of the input does not move the cycles. Minor loops inside a cycle belong to
//! it: a branch that turns back before reaching the anchor level extends the cycle by one more pair
//! of reversals.
//!
//! A record that stops just short of the anchor level (a measurement of one period usually does)
//! closes its last cycle at the last sample when that sample is on a d-branch, past both
//! reversals, and within `band` of a; `ends_at_record_end` says so. Likewise a record that starts
//! at an extreme (it never goes more than `band` beyond a) closes its last cycle at a last sample
//! back within `band` of that extreme (an extreme the record ends on is never a confirmed
//! reversal). Input before the first reversal pair is part of the first cycle; input after the
//! last closed cycle belongs to none.

#include <cstddef>
#include <span>
#include <vector>

namespace hyst::data {

struct Cycle {
  std::size_t first = 0;  //!< index of the first sample
  std::size_t last = 0;   //!< index of the last sample (inclusive)
  //! True when the cycle was closed by the end of the record within `band` of the anchor level
  //! rather than by reaching it.
  bool ends_at_record_end = false;

  std::size_t samples() const { return last - first + 1; }
};

//! The complete cycles of `input` (possibly none). Throws hyst::Error as reversal_points() does.
std::vector<Cycle> cycles(std::span<const double> input, double band);

}  // namespace hyst::data
