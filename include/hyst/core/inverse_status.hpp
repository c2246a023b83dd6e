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
};

constexpr EnumNames<InverseStatus, 3> enumerator_names(InverseStatus) {
  return {{
      {InverseStatus::ok, "ok"},
      {InverseStatus::below_range, "below_range"},
      {InverseStatus::above_range, "above_range"},
  }};
}

//! One inverse sample: the input to apply and whether it had to be limited.
struct InverseSample {
  double input = 0.0;
  InverseStatus status = InverseStatus::ok;
};

//! Summary of a batch inversion.
struct InverseReport {
  std::size_t saturated_samples = 0;  //!< samples whose status was not ok
  std::size_t first_saturated = 0;    //!< index of the first such sample (if any)
  bool ok() const { return saturated_samples == 0; }
};

}  // namespace hyst
