#include "hyst/identify/data_split.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

DataSplit split_by_fraction(std::size_t samples, double validate_fraction) {
  if (!(validate_fraction >= 0.0 && validate_fraction < 1.0)) {
    throw Error(fmt::format("validate_fraction = {} must be in [0, 1)", validate_fraction));
  }
  if (samples == 0) throw Error("cannot split a record of 0 samples");
  const auto validation =
      static_cast<std::size_t>(std::llround(validate_fraction * static_cast<double>(samples)));
  if (validate_fraction > 0.0 && validation == 0) {
    throw Error(fmt::format(
        "validate_fraction = {} of {} samples leaves the validation part empty; use 0 for no "
        "validation or a larger fraction",
        validate_fraction, samples));
  }
  if (validation >= samples) {
    throw Error(fmt::format("validate_fraction = {} of {} samples leaves the fit part empty",
                            validate_fraction, samples));
  }
  return DataSplit{0, samples - validation, samples - validation, samples};
}

}  // namespace hyst
