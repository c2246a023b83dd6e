#pragma once
//! \file
//! Contiguous split of one record into a fit part and a validation part.
//!
//! Hysteresis has memory, so samples are never shuffled: the fit part is [fit_begin, fit_end), the
//! validation part the samples right after it, [validation_begin, validation_end), predicted by
//! continuing the simulation from the state reached at the end of the fit part. Holding out the
//! last part of a record tests the model on reversals it has not seen, which a random split would
//! hide (neighbouring samples of a smooth record are nearly equal).

#include <cstddef>

namespace hyst {

//! Index ranges [begin, end) of the fit and validation parts of a record.
struct DataSplit {
  std::size_t fit_begin = 0;
  std::size_t fit_end = 0;
  std::size_t validation_begin = 0;
  std::size_t validation_end = 0;

  std::size_t fit_size() const { return fit_end - fit_begin; }
  std::size_t validation_size() const { return validation_end - validation_begin; }
  bool has_validation() const { return validation_end > validation_begin; }
};

//! Splits `samples` so that the last `validate_fraction` of them (rounded to the nearest sample)
//! are the validation part and all before them the fit part. validate_fraction = 0 gives no
//! validation part. Throws hyst::Error unless samples >= 1 and 0 <= validate_fraction < 1, and
//! unless both parts (the validation part only when the fraction is > 0) hold at least one sample.
DataSplit split_by_fraction(std::size_t samples, double validate_fraction);

}  // namespace hyst
