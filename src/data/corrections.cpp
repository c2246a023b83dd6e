#include "hyst/data/corrections.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/error.hpp"
#include "hyst/data/cycles.hpp"
#include "record_checks.hpp"

namespace hyst::data {
OffsetReference offset_reference_from_string(std::string_view text) {
  return hyst::detail::value_named(text, enum_names<OffsetReference>, "offset reference");
}

OffsetRemoval remove_offset(std::span<const double> values, OffsetReference reference) {
  detail::require_samples(values, "values", 1);
  OffsetRemoval result;
  switch (reference) {
    case OffsetReference::mean:
      result.offset =
          std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
      break;
    case OffsetReference::first:
      result.offset = values.front();
      break;
    case OffsetReference::midrange: {
      const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
      result.offset = 0.5 * (*lowest + *highest);
      break;
    }
  }
  result.values.reserve(values.size());
  for (const double value : values)
    result.values.push_back(value - result.offset);
  return result;
}

DriftRemoval remove_drift(std::span<const double> input, std::span<const double> output,
                          double band) {
  detail::require_record(input, output, 3);
  const auto found = cycles(input, band);
  if (found.empty()) {
    throw Error(fmt::format(
        "drift removal needs at least one complete cycle, but the input (hysteresis band {}) "
        "has none: it does not return to its first value {} after a maximum and a minimum",
        band, input.front()));
  }
  std::vector<std::size_t> boundaries{found.front().first};
  for (const auto& cycle : found)
    boundaries.push_back(cycle.last);

  DriftRemoval result;
  result.cycles = found.size();
  result.drift.assign(output.size(), 0.0);
  const double reference = output[boundaries.front()];
  const auto drift_at = [&](std::size_t j) { return output[boundaries[j]] - reference; };
  for (std::size_t j = 1; j < boundaries.size(); ++j) {
    result.closure_error = std::max(result.closure_error, std::abs(drift_at(j)));
    const std::size_t from = boundaries[j - 1];
    const std::size_t to = boundaries[j];
    const double slope = (drift_at(j) - drift_at(j - 1)) / static_cast<double>(to - from);
    const std::size_t end = j + 1 == boundaries.size() ? output.size() - 1 : to;
    for (std::size_t k = from; k <= end; ++k) {
      result.drift[k] = drift_at(j - 1) + slope * static_cast<double>(k - from);
    }
  }
  result.output.resize(output.size());
  for (std::size_t k = 0; k < output.size(); ++k)
    result.output[k] = output[k] - result.drift[k];
  return result;
}

}  // namespace hyst::data
