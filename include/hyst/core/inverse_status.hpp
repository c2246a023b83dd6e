#pragma once
//! \file
//! Outcome of one inverse-model sample. Inverses never throw from their step: a desired output
//! that needs an input outside the admissible range is answered with the nearest admissible
//! input and a status saying which limit was hit.

#include <cstddef>
#include <string_view>

#include "hyst/core/enum_names.hpp"

namespace hyst {

enum class InverseStatus : unsigned char {
  ok,           //!< the returned input produces the desired output
  below_range,  //!< the input was raised to its lower limit
  above_range,  //!< the input was lowered to its upper limit
  //! the output is not monotone in the input over the admissible range from this state (e.g. a
  //! butterfly loop across its vertex), or the target is NaN: no unique input exists; the
  //! previous input was held
  not_invertible,
};

constexpr EnumNames<InverseStatus, 4> enumerator_names(InverseStatus) {
  return {{
      {InverseStatus::ok, "ok"},
      {InverseStatus::below_range, "below_range"},
      {InverseStatus::above_range, "above_range"},
      {InverseStatus::not_invertible, "not_invertible"},
  }};
}

//! One inverse sample: the input to apply and whether it had to be limited.
struct InverseSample {
  double input = 0.0;
  InverseStatus status = InverseStatus::ok;
};

//! Summary of a batch inversion.
struct InverseReport {
  std::size_t saturated_samples = 0;       //!< samples whose status was not ok
  std::size_t first_saturated = 0;         //!< index of the first such sample (if any)
  std::size_t not_invertible_samples = 0;  //!< of those, samples with status not_invertible
  std::size_t first_not_invertible = 0;    //!< index of the first such sample (if any)
  std::size_t limited_samples = 0;         //!< of those, below_range or above_range samples
  std::size_t first_limited = 0;           //!< index of the first such sample (if any)
  bool ok() const { return saturated_samples == 0; }
  //! Counts sample k of status `status`.
  void record(std::size_t k, InverseStatus status) {
    if (status == InverseStatus::ok) return;
    if (saturated_samples++ == 0) first_saturated = k;
    if (status == InverseStatus::not_invertible) {
      if (not_invertible_samples++ == 0) first_not_invertible = k;
    } else if (limited_samples++ == 0) {
      first_limited = k;
    }
  }
};

}  // namespace hyst
