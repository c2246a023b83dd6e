#pragma once
//! \file
//! Validation of user-supplied numbers and sample sequences. Each check throws hyst::Error with a
//! message that names the quantity, the index and the offending value.

#include <cstddef>
#include <span>
#include <string_view>

namespace hyst {

//! Throws unless every sample is finite: "input[17] = nan is not finite".
void require_finite(std::span<const double> samples, std::string_view name);

//! Throws unless the value is finite: "PI offset = inf is not finite".
void require_finite(double value, std::string_view name);

//! Throws unless both sequences have the same length, naming both.
void require_same_size(std::size_t a, std::string_view name_a, std::size_t b,
                       std::string_view name_b);

//! Throws unless the sequence is not empty.
void require_not_empty(std::size_t size, std::string_view name);

}  // namespace hyst
