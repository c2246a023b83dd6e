#pragma once
//! \file
//! The preparation of a measured record for fitting, built on cycles.hpp, corrections.hpp and
//! resampling.hpp, with a one-line description of each step applied (for the fit report).
//!
//! Order: drift removal on the whole record (it needs every cycle boundary), then the selection of
//! cycles, then resampling. The hysteresis band for reversal and cycle detection is `band`, or
//! default_band() (2 % of the input range) when it is 0.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hyst/core/enum_names.hpp"

namespace hyst::data {

using hyst::to_string;

//! Cycles first..last, 1-based and inclusive; last = 0 means "to the last cycle".
struct CycleRange {
  std::size_t first = 1;
  std::size_t last = 0;
};

//! "3" (cycle 3), "2-4", "2-" (2 to the last), "all"; throws hyst::Error for other text.
CycleRange cycle_range_from_string(std::string_view text);
//! "2-4", "3", "2-" or "all".
std::string to_string(const CycleRange& range);

enum class ResampleMethod : unsigned char { none, input_grid, arc_length };

//! "none", "input-grid", "arc-length" and back (hyst::Error for other text).
constexpr EnumNames<ResampleMethod, 3> enumerator_names(ResampleMethod) {
  return {{
      {ResampleMethod::none, "none"},
      {ResampleMethod::input_grid, "input-grid"},
      {ResampleMethod::arc_length, "arc-length"},
  }};
}
ResampleMethod resample_method_from_string(std::string_view text);

struct Preprocessing {
  double band = 0.0;                 //!< hysteresis band [input units]; 0 = default_band()
  bool detrend = false;              //!< remove_drift()
  std::optional<CycleRange> cycles;  //!< keep only these cycles
  ResampleMethod resample = ResampleMethod::none;
  //! Resampling step: [input units] on an input grid, normalised arc length otherwise;
  //! 0 = 1/100 of the input range (input grid) or 0.01 (arc length).
  double resample_step = 0.0;

  bool any() const { return detrend || cycles || resample != ResampleMethod::none; }
};

struct PreparedRecord {
  std::vector<double> input;
  std::vector<double> output;
  std::vector<std::string> steps;  //!< one line per step applied, e.g. "cycles 2-3 of 4 ..."
};

//! The record prepared as `options` asks. Throws hyst::Error for invalid data or options, e.g.
//! "cycles 3-4 requested but the record has 2 cycles".
PreparedRecord preprocess(std::span<const double> input, std::span<const double> output,
                          const Preprocessing& options);

//! A validation record prepared as `options` asks for what is a measurement artefact: its drift
//! is removed when options.detrend (with options.band, or default_band() of this record), so it
//! is compared with the model like the fit record; cycles and resampling choose what the fit
//! sees and are not applied. A record without a complete cycle keeps its drift, and the step
//! says so. Throws hyst::Error for invalid data.
PreparedRecord prepare_validation(std::span<const double> input, std::span<const double> output,
                                  const Preprocessing& options);

}  // namespace hyst::data
