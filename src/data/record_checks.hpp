#pragma once
// Validation shared by the functions of hyst/data: records of input (and output) samples and the
// hysteresis band. Each throws hyst::Error naming the argument and the rule.

#include <cstddef>
#include <span>
#include <string_view>

namespace hyst::data::detail {

//! At least `minimum` samples, all finite.
void require_samples(std::span<const double> values, std::string_view name, std::size_t minimum);
//! Input and output of equal length (>= minimum), all finite.
void require_record(std::span<const double> input, std::span<const double> output,
                    std::size_t minimum);
//! A finite band > 0.
void require_band(double band);
//! A finite value > 0 named `name`.
void require_positive(double value, std::string_view name);

}  // namespace hyst::data::detail
