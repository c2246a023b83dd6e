#pragma once
//! \file
//! Corrections of measured records before fitting: offset removal and removal of linear drift
//! between cycles, so that the loop of a periodic record closes.
//!
//! Drift: a periodic input should give a periodic output, but sensors drift (interferometer
//! zero, charge integrator leakage, temperature), so each cycle ends at another output than it
//! started. remove_drift() takes the cycle boundaries b_0 < b_1 < ... < b_C (cycles.hpp: each
//! boundary is at the same input level, moving in the same direction), reads the drift there as
//! d_j = output[b_j] - output[b_0], interpolates it linearly in the sample index between
//! boundaries (extrapolating the last segment's slope after b_C, and 0 before b_0) and subtracts
//! it. Afterwards every cycle closes: output[b_j] = output[b_0]. Linear in the sample index means
//! linear in time for uniformly sampled records.

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "hyst/core/enum_names.hpp"

namespace hyst::data {

using hyst::to_string;

enum class OffsetReference : unsigned char {
  mean,      //!< the mean of the samples
  first,     //!< the first sample (output zeroed at the start, as many instruments do)
  midrange,  //!< (min + max) / 2: centres the range on 0
};

//! "mean", "first", "midrange" and back (hyst::Error for other text).
constexpr EnumNames<OffsetReference, 3> enumerator_names(OffsetReference) {
  return {{
      {OffsetReference::mean, "mean"},
      {OffsetReference::first, "first"},
      {OffsetReference::midrange, "midrange"},
  }};
}
OffsetReference offset_reference_from_string(std::string_view text);

struct OffsetRemoval {
  std::vector<double> values;  //!< the samples minus the offset
  double offset = 0.0;         //!< what was subtracted
};

//! The samples minus their offset. Throws hyst::Error for an empty or non-finite sequence.
OffsetRemoval remove_offset(std::span<const double> values,
                            OffsetReference reference = OffsetReference::mean);

struct DriftRemoval {
  std::vector<double> output;  //!< the corrected output
  std::vector<double> drift;   //!< what was subtracted from each sample
  std::size_t cycles = 0;      //!< number of complete cycles used
  double closure_error = 0.0;  //!< largest |output[b_j] - output[b_0]| before correction
};

//! Removes linear drift between cycles (see the file comment), with hysteresis band `band` for
//! the cycle detection. Throws hyst::Error for invalid data or when the record has no complete
//! cycle.
DriftRemoval remove_drift(std::span<const double> input, std::span<const double> output,
                          double band);

}  // namespace hyst::data
