#pragma once
//! \file
//! Turning points of a measured input: the alternating maxima and minima a rate-independent
//! hysteresis model (play, Prandtl-Ishlinskii, Preisach) remembers, found with a hysteresis band
//! so that noise, glitches and plateaus do not count as reversals.
//!
//! Rule (a peak-valley filter with threshold `band` > 0): while the input rises, the running
//! maximum since the last turning point is a candidate; it becomes a maximum reversal only when
//! the input later falls more than `band` below it (and mirrored for minima). So every excursion
//! of at most `band` - a noise wiggle, a glitch, the ripple on a plateau - is ignored, and every
//! excursion of more than `band` is found, at the sample of its extreme value (the first such
//! sample on a plateau). Not every sign change of the derivative is a reversal.
//!
//! The record's first and last samples are not reversal points: the first is only where the record
//! starts (the direction is set by the first movement of more than `band`), the last is where it
//! stops (the final extreme was never confirmed by a return). The result alternates between
//! maxima and minima.
//!
//! preisach_memory() reduces that sequence to the alternating dominant extrema a Preisach model
//! keeps after the wiping-out rule (Mayergoyz): a new maximum deletes every earlier maximum not
//! larger than it together with the minimum stored after it, and mirrored for minima.

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace hyst::data {

enum class Extremum : unsigned char { maximum, minimum };

//! "maximum" or "minimum".
std::string_view to_string(Extremum kind);

struct ReversalPoint {
  std::size_t index = 0;  //!< sample index in the record
  double value = 0.0;     //!< input[index]
  Extremum kind = Extremum::maximum;
};

//! The reversal points of `input` (see the file comment). Throws hyst::Error unless the input has
//! at least 2 samples, every sample is finite, and band is finite and > 0.
std::vector<ReversalPoint> reversal_points(std::span<const double> input, double band);

//! The alternating dominant extrema left after wiping-out, in history order (the first entry is
//! the largest maximum or the smallest minimum). `points` must alternate (as reversal_points()
//! returns them); throws hyst::Error otherwise.
std::vector<ReversalPoint> preisach_memory(std::span<const ReversalPoint> points);

//! A hysteresis band suited to a record: `fraction` (default 2 %) of the input's range, so that
//! noise below that level is ignored. Throws hyst::Error for an empty or non-finite input,
//! a constant input, or fraction outside (0, 1).
double default_band(std::span<const double> input, double fraction = 0.02);

}  // namespace hyst::data
