#pragma once
//! \file
//! Is a fitted model's simulation usable at all? The check behind the fit status "degenerate"
//! and "unstable", whatever the fit method reported about its own ending.
//!
//! A method can converge to a useless optimum: weights at their bounds that leave the output
//! nearly constant, or parameters whose free run runs away. So after every fit its free-run
//! simulation is judged against the measured output:
//!
//! - unstable: a simulated sample is not finite, or lies outside the band of 10 times the measured
//!   range centred on the measured range, [mid - 5 R, mid + 5 R] with mid = (max + min) / 2 and
//!   R = max - min of the measured output (the whole record);
//! - degenerate: on the judged part (the held-out part when there is one, else the whole record)
//!   the standard deviation of the simulation is below 1 % of that of the measured output;
//! - sound: neither.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "hyst/core/enum_names.hpp"

namespace hyst {

enum class FitQuality {
  unchecked,   //!< no simulation was judged
  sound,       //!< neither of the below
  degenerate,  //!< the simulation is nearly constant where it is judged
  unstable,    //!< the simulation is not finite or leaves the band around the measured range
};

//! "unchecked", "sound", "degenerate", "unstable".
constexpr EnumNames<FitQuality, 4> enumerator_names(FitQuality) {
  return {{
      {FitQuality::unchecked, "unchecked"},
      {FitQuality::sound, "sound"},
      {FitQuality::degenerate, "degenerate"},
      {FitQuality::unstable, "unstable"},
  }};
}

struct QualityVerdict {
  FitQuality quality = FitQuality::unchecked;
  std::string reason;  //!< one sentence with the figures, empty when sound
};

//! Judges `simulated` against `measured` (same length, the whole record) as the file comment
//! says; the degeneracy is judged on the samples from `judged_begin` on. Throws hyst::Error when
//! the lengths differ, the record is empty or judged_begin is not a sample of it.
QualityVerdict judge_simulation(std::span<const double> measured, std::span<const double> simulated,
                                std::size_t judged_begin = 0);

}  // namespace hyst
