#pragma once
//! \file
//! Multichannel signals of a periodic experiment: N samples per period, several channels, several
//! realisations (e.g. random-phase multisines with different phases) and several consecutive
//! periods of each realisation. What the nonlinear system identification benchmarks publish.

#include <cstddef>
#include <string_view>
#include <vector>

namespace hyst {

struct PeriodicSignals {
  std::size_t samples = 0;       //!< N, samples per period
  std::size_t channels = 0;      //!< inputs or outputs
  std::size_t realisations = 0;  //!< independent experiments
  std::size_t periods = 0;       //!< consecutive periods of each realisation
  //! Index ((r * periods + p) * samples + n) * channels + c: one realisation's periods follow each
  //! other in time, so that realisation r is a contiguous (periods * samples) x channels record.
  std::vector<double> values;

  std::size_t index(std::size_t n, std::size_t c, std::size_t r, std::size_t p) const {
    return ((r * periods + p) * samples + n) * channels + c;
  }
  double operator()(std::size_t n, std::size_t c, std::size_t r, std::size_t p) const {
    return values[index(n, c, r, p)];
  }
  double& operator()(std::size_t n, std::size_t c, std::size_t r, std::size_t p) {
    return values[index(n, c, r, p)];
  }
  //! Samples of one realisation, all periods in time order (periods * samples rows).
  std::size_t record_length() const { return periods * samples; }
};

//! Throws hyst::Error unless every value is finite, naming the first that is not by its place
//! on the axes of the default layout: "`what`: the value at (N = 5, channel = 1, realisation = 0,
//! period = 1) is inf; every sample must be finite" (indices from 0).
void require_finite_signals(const PeriodicSignals& signals, std::string_view what);

//! One realisation from equally long columns (one per channel) of a measured record, cut into
//! periods of `samples_per_period` (0: the whole record is one period). Throws hyst::Error
//! (prefixed with `source`) for no column, columns of different lengths, a record that is not a
//! whole number of periods, or a non-finite sample.
PeriodicSignals periodic_signals_from_columns(const std::vector<std::vector<double>>& columns,
                                              std::size_t samples_per_period,
                                              std::string_view source);

}  // namespace hyst
