#pragma once
//! \file
//! Reference trajectories for tracking scenarios, sampled at the control period h: steps, sines,
//! triangles with internal loops (turning points of decreasing amplitude, the input that shows
//! the hysteresis memory), and trajectories read from CSV files.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hyst::control {

//! Where a step reference steps, for settling time and overshoot.
struct StepEvent {
  double time = 0.0;  //!< [s]
  double from = 0.0;  //!< level before [reference units]
  double to = 0.0;    //!< level after
};

struct Reference {
  std::string name;            //!< short label (file names, tables): letters, digits, '_', '-'
  double sample_time = 1.0;    //!< h [s]
  std::vector<double> values;  //!< r[k] = r(k h)
  std::optional<StepEvent> step = std::nullopt;  //!< set for step references
  std::vector<double> times() const;
};

//! r = from until step_time, then to; `duration` [s]. hyst::Error for a non-positive h or
//! duration, a step time outside [0, duration) or non-finite levels.
Reference step_reference(double from, double to, double step_time, double duration,
                         double sample_time);
//! r = offset + amplitude sin(2 pi f t); duration [s].
Reference sine_reference(double offset, double amplitude, double frequency, double duration,
                         double sample_time);
//! Straight lines at `rate` [units/s] through the turning points low, high, then inward
//! (high - s, low + s, high - 2 s, ...) with s = (high - low)/(2 loops + 2), `loops` internal
//! reversals, then back to low: a major loop with nested internal loops.
Reference triangle_reference(double low, double high, std::size_t loops, double rate,
                             double sample_time);
//! A trajectory from a CSV file (hyst/io/csv.hpp) with a column "reference" (or else the last
//! column) and, when present, a column "t" [s] that must be uniformly spaced by h (relative
//! 1e-6). hyst::Error names the file, column and row.
Reference reference_from_csv(const std::filesystem::path& path, double sample_time);

}  // namespace hyst::control
