#include "hyst/core/checks.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

void require_finite(std::span<const double> samples, std::string_view name) {
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (!std::isfinite(samples[k])) {
      throw Error(fmt::format("{}[{}] = {} is not finite", name, k, samples[k]));
    }
  }
}

void require_finite(double value, std::string_view name) {
  if (!std::isfinite(value)) throw Error(fmt::format("{} = {} is not finite", name, value));
}

void require_same_size(std::size_t a, std::string_view name_a, std::size_t b,
                       std::string_view name_b) {
  if (a != b) {
    throw Error(fmt::format("{} has {} values but {} has {}; they must have the same length",
                            name_a, a, name_b, b));
  }
}

void require_not_empty(std::size_t size, std::string_view name) {
  if (size == 0) throw Error(fmt::format("{} is empty", name));
}

void require_same_length(std::size_t first_size, std::size_t second_size, std::string_view owner,
                         const ListName& first, const ListName& second) {
  if (first_size != second_size) {
    throw Error(fmt::format("{} has {} {} {} but {} {} {}; they must have the same length", owner,
                            first_size, first.plural, first.symbol, second_size, second.plural,
                            second.symbol),
                std::string(second.field));
  }
}

void require_increasing_from_zero(std::span<const double> values, std::string_view what,
                                  std::string_view symbol, std::string_view field,
                                  std::string_view why_zero) {
  if (values.empty()) return;
  if (values[0] != 0.0) {
    throw Error(fmt::format("{} {}[0] = {} must be 0 ({})", what, symbol, values[0], why_zero),
                fmt::format("{}[0]", field));
  }
  for (std::size_t j = 1; j < values.size(); ++j) {
    if (!(values[j] > values[j - 1])) {
      throw Error(fmt::format("{} {}[{}] = {} must be > {}[{}] = {}", what, symbol, j, values[j],
                              symbol, j - 1, values[j - 1]),
                  fmt::format("{}[{}]", field, j));
    }
  }
}

}  // namespace hyst
