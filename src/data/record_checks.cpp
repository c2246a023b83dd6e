#include "record_checks.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst::data::detail {

void require_samples(std::span<const double> values, std::string_view name, std::size_t minimum) {
  if (values.size() < minimum) {
    throw Error(
        fmt::format("{} has {} samples; at least {} are needed", name, values.size(), minimum));
  }
  require_finite(values, name);
}

void require_record(std::span<const double> input, std::span<const double> output,
                    std::size_t minimum) {
  require_same_size(input.size(), "input", output.size(), "output");
  require_samples(input, "input", minimum);
  require_finite(output, "output");
}

void require_band(double band) {
  require_positive(band, "hysteresis band");
}

void require_positive(double value, std::string_view name) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw Error(fmt::format("{} = {} must be finite and > 0", name, value));
  }
}

}  // namespace hyst::data::detail
