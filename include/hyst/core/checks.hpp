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

//! A list parameter as messages name it: "thresholds" "r", about the field "thresholds".
struct ListName {
  std::string_view plural;
  std::string_view symbol;
  std::string_view field;
};

//! Throws unless two lists that go together are equally long: "PI has 3 thresholds r but 2
//! weights p; they must have the same length", about the second list's field.
void require_same_length(std::size_t first_size, std::size_t second_size, std::string_view owner,
                         const ListName& first, const ListName& second);

//! Throws unless values[0] = 0 and the values increase strictly, e.g. for `what` "PI threshold",
//! `symbol` "r": "PI threshold r[0] = 0.1 must be 0 (<why_zero>)", "PI threshold r[2] = 1 must be
//! > r[1] = 1", about the field "<field>[j]". Empty values pass.
void require_increasing_from_zero(std::span<const double> values, std::string_view what,
                                  std::string_view symbol, std::string_view field,
                                  std::string_view why_zero);

}  // namespace hyst
