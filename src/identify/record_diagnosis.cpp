#include "hyst/identify/record_diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/data/branches.hpp"
#include "hyst/data/reversal_points.hpp"

namespace hyst {
namespace {

constexpr double kTurnBack = 0.05;    // of the output range, beyond a branch's end values
constexpr double kDrift = 0.10;       // of the output range, trend from first to last crossing
constexpr double kOutOfRange = 0.05;  // of the fit input range, beyond it
constexpr double kButterflyTravel = 1.0 / 3.0;  // of the input travel, on branches that turn back

double range_of(std::span<const double> values) {
  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  return *highest - *lowest;
}

std::optional<std::string> butterfly(std::span<const double> input, std::span<const double> output,
                                     double output_range) {
  std::vector<data::Branch> branches;
  try {
    branches = data::branches(input, data::default_band(input));
  } catch (const std::exception&) {
    return std::nullopt;  // too short or constant: no branches to look at
  }
  std::size_t turning = 0;
  double travel = 0.0;          // input travel of all branches
  double turning_travel = 0.0;  // of the branches that turn back
  for (const auto& branch : branches) {
    const auto y = output.subspan(branch.first, branch.samples());
    const auto [lowest, highest] = std::minmax_element(y.begin(), y.end());
    const double beyond =
        std::max(*highest - std::max(y.front(), y.back()), std::min(y.front(), y.back()) - *lowest);
    const double branch_travel =
        std::abs(input[branch.first + branch.samples() - 1] - input[branch.first]);
    travel += branch_travel;
    if (beyond > kTurnBack * output_range) {
      ++turning;
      turning_travel += branch_travel;
    }
  }
  if (turning == 0 || !(turning_travel >= kButterflyTravel * travel)) return std::nullopt;
  return fmt::format(
      "butterfly: the output turns back on {} of {} input branches, {:.0f} % of the input "
      "travel (non-monotone output vs. input)",
      turning, branches.size(), 100.0 * turning_travel / travel);
}

// Slope of the least-squares line through values[i] over i, times (n - 1): the trend's change.
double trend_change(const std::vector<double>& values) {
  const double n = static_cast<double>(values.size());
  const double mean_i = 0.5 * (n - 1.0);
  double mean_y = 0.0;
  for (const double y : values)
    mean_y += y / n;
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double di = static_cast<double>(i) - mean_i;
    sxy += di * (values[i] - mean_y);
    sxx += di * di;
  }
  return sxx > 0.0 ? sxy / sxx * (n - 1.0) : 0.0;
}

std::optional<std::string> drift(std::span<const double> input, std::span<const double> output,
                                 double output_range) {
  const auto [lowest, highest] = std::minmax_element(input.begin(), input.end());
  const double level = 0.5 * (*lowest + *highest);
  std::vector<double> rising;
  std::vector<double> falling;
  for (std::size_t k = 1; k < input.size(); ++k) {
    const bool up = input[k - 1] < level && input[k] >= level;
    const bool down = input[k - 1] > level && input[k] <= level;
    if (!up && !down) continue;
    const double t = (level - input[k - 1]) / (input[k] - input[k - 1]);
    (up ? rising : falling).push_back(output[k - 1] + t * (output[k] - output[k - 1]));
  }
  double change = 0.0;
  std::size_t crossings = 0;
  for (const auto* values : {&rising, &falling}) {
    if (values->size() < 3) continue;
    const double this_change = trend_change(*values);
    if (std::abs(this_change) > std::abs(change)) {
      change = this_change;
      crossings = values->size();
    }
  }
  if (!(std::abs(change) > kDrift * output_range)) return std::nullopt;
  return fmt::format(
      "drift: at the repeated input value {:.4g} the output trends by {:.4g} "
      "({:.0f} % of the output range) over {} crossings",
      level, change, 100.0 * std::abs(change) / output_range, crossings);
}

std::optional<std::string> extrapolation(std::span<const double> fit_input,
                                         std::span<const double> held_input) {
  const auto [fit_low, fit_high] = std::minmax_element(fit_input.begin(), fit_input.end());
  const auto [held_low, held_high] = std::minmax_element(held_input.begin(), held_input.end());
  const double margin = kOutOfRange * (*fit_high - *fit_low);
  if (!(*held_low < *fit_low - margin || *held_high > *fit_high + margin)) return std::nullopt;
  return fmt::format(
      "extrapolation: the held-out input spans {:.4g}..{:.4g}, beyond the fitted "
      "input range {:.4g}..{:.4g}",
      *held_low, *held_high, *fit_low, *fit_high);
}

// The output range, or 0 when the looks cannot use the output (flat or not finite).
double usable_range(std::span<const double> output) {
  const double output_range = range_of(output);
  return output_range > 0.0 && std::isfinite(output_range) ? output_range : 0.0;
}

void note(RecordDiagnosis& diagnosis, bool& flag, std::optional<std::string> finding) {
  if (!finding) return;
  flag = true;
  diagnosis.findings.push_back(std::move(*finding));
}

}  // namespace

RecordDiagnosis diagnose_record(std::span<const double> input, std::span<const double> output,
                                const DataSplit& split) {
  require_same_size(input.size(), "input", output.size(), "output");
  if (split.validation_end > input.size() || split.fit_end > input.size() ||
      split.fit_size() == 0) {
    throw Error(
        fmt::format("record diagnosis: the split (fit {}..{}, held out {}..{}) lies "
                    "outside the {} samples",
                    split.fit_begin, split.fit_end, split.validation_begin, split.validation_end,
                    input.size()));
  }
  RecordDiagnosis diagnosis;
  const double output_range = usable_range(output);
  if (output_range == 0.0) return diagnosis;
  note(diagnosis, diagnosis.butterfly, butterfly(input, output, output_range));
  note(diagnosis, diagnosis.drift, drift(input, output, output_range));
  if (split.has_validation()) {
    note(diagnosis, diagnosis.extrapolation,
         extrapolation(input.subspan(split.fit_begin, split.fit_size()),
                       input.subspan(split.validation_begin, split.validation_size())));
  }
  return diagnosis;
}

RecordDiagnosis diagnose_held_out_record(std::span<const double> fit_input,
                                         std::span<const double> held_input,
                                         std::span<const double> held_output) {
  require_same_size(held_input.size(), "held-out input", held_output.size(), "held-out output");
  if (fit_input.empty() || held_input.empty()) {
    throw Error(fmt::format("record diagnosis: {} fit and {} held-out samples; both must be > 0",
                            fit_input.size(), held_input.size()));
  }
  RecordDiagnosis diagnosis;
  const double output_range = usable_range(held_output);
  if (output_range == 0.0) return diagnosis;
  note(diagnosis, diagnosis.butterfly, butterfly(held_input, held_output, output_range));
  note(diagnosis, diagnosis.drift, drift(held_input, held_output, output_range));
  note(diagnosis, diagnosis.extrapolation, extrapolation(fit_input, held_input));
  return diagnosis;
}

}  // namespace hyst
