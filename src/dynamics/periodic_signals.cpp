#include "hyst/dynamics/periodic_signals.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

void require_finite_signals(const PeriodicSignals& signals, std::string_view what) {
  for (std::size_t r = 0; r < signals.realisations; ++r)
    for (std::size_t p = 0; p < signals.periods; ++p)
      for (std::size_t n = 0; n < signals.samples; ++n)
        for (std::size_t c = 0; c < signals.channels; ++c)
          if (const double value = signals(n, c, r, p); !std::isfinite(value))
            throw Error(
                fmt::format("{}: the value at (N = {}, channel = {}, realisation = {}, "
                            "period = {}) is {}; every sample must be finite",
                            what, n, c, r, p, value));
}

PeriodicSignals periodic_signals_from_columns(const std::vector<std::vector<double>>& columns,
                                              std::size_t samples_per_period,
                                              std::string_view source) {
  if (columns.empty()) throw Error(fmt::format("{}: no column", source));
  const std::size_t length = columns[0].size();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].size() != length)
      throw Error(fmt::format("{}: column {} has {} samples, column 1 has {}", source, c + 1,
                              columns[c].size(), length));
    require_finite(columns[c], fmt::format("{} column {}", source, c + 1));
  }
  if (length == 0) throw Error(fmt::format("{}: the columns are empty", source));
  const std::size_t period = samples_per_period == 0 ? length : samples_per_period;
  if (length % period != 0)
    throw Error(fmt::format("{}: {} samples are not a whole number of periods of {}", source,
                            length, period));
  PeriodicSignals signals{period, columns.size(), 1, length / period, {}};
  signals.values.resize(length * columns.size());
  for (std::size_t k = 0; k < length; ++k)
    for (std::size_t c = 0; c < columns.size(); ++c)
      signals.values[k * columns.size() + c] = columns[c][k];
  return signals;
}

}  // namespace hyst
