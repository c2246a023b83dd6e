#include "hyst/data/resampling.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/data/branches.hpp"
#include "hyst/io/limits.hpp"
#include "record_checks.hpp"

namespace hyst::data {
namespace {

//! Appends the points of one branch at the positions `position` (non-decreasing along the
//! branch, from positions[first] to positions[last]) given by m equal intervals; skips the
//! branch's first point when `skip_first` (it is the previous branch's last).
void append_branch(std::span<const double> position, std::span<const double> input,
                   std::span<const double> output, const Branch& branch, std::size_t intervals,
                   bool skip_first, ResampledRecord& out) {
  const double start = position[branch.first];
  const double end = position[branch.last];
  std::size_t j = branch.first;  // first sample with position >= target
  for (std::size_t i = skip_first ? 1 : 0; i <= intervals; ++i) {
    if (i == intervals) {  // the branch end, exactly
      out.input.push_back(input[branch.last]);
      out.output.push_back(output[branch.last]);
      break;
    }
    const double target =
        start + (end - start) * static_cast<double>(i) / static_cast<double>(intervals);
    while (j < branch.last && position[j] < target)
      ++j;
    if (j == branch.first || position[j] == target) {
      out.input.push_back(input[j]);
      out.output.push_back(output[j]);
      continue;
    }
    const double t = (target - position[j - 1]) / (position[j] - position[j - 1]);
    out.input.push_back(input[j - 1] + t * (input[j] - input[j - 1]));
    out.output.push_back(output[j - 1] + t * (output[j] - output[j - 1]));
  }
}

//! The intervals of a branch of `length`, after check_sample_count() bounded length / step.
std::size_t interval_count(double length, double step) {
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(length / step - 1e-12)));
}

//! The samples the branches of `lengths` ask for at `step`, added up as doubles before any
//! conversion to an integer (a step of 1e-17 would overflow it), against the stated limit.
void check_sample_count(const std::vector<double>& lengths, double step, std::string_view what) {
  double samples = 1.0;
  for (const double length : lengths)
    samples += std::max(1.0, std::ceil(length / step));
  if (!(samples <= io::limits::kMaxDerivedSamples)) {
    throw Error(fmt::format(
        "{} {} asks for {:.4g} samples (branch length / step, over all branches), more than the "
        "limit of {:.0f}; choose a larger step",
        what, step, samples, io::limits::kMaxDerivedSamples));
  }
}

}  // namespace

ResampledRecord resample_on_input_grid(std::span<const double> input,
                                       std::span<const double> output, double band,
                                       double input_step) {
  detail::require_record(input, output, 2);
  detail::require_positive(input_step, "input step");
  const auto found = branches(input, band);
  std::vector<double> lengths;
  for (const auto& branch : found)
    lengths.push_back(std::abs(input[branch.last] - input[branch.first]));
  check_sample_count(lengths, input_step, "input step");
  ResampledRecord out;
  std::vector<double> position(input.size());
  bool first_branch = true;
  for (const auto& branch : found) {
    // Position along the branch: the input, sign-flipped on descending branches so that it
    // grows along every branch.
    const double sense = branch.direction == Direction::ascending ? 1.0 : -1.0;
    for (std::size_t k = branch.first; k <= branch.last; ++k)
      position[k] = sense * input[k];
    const double length = std::abs(input[branch.last] - input[branch.first]);
    append_branch(position, input, output, branch, interval_count(length, input_step),
                  !first_branch, out);
    first_branch = false;
  }
  return out;
}

ResampledRecord resample_by_arc_length(std::span<const double> input,
                                       std::span<const double> output, double band, double step) {
  detail::require_record(input, output, 2);
  detail::require_positive(step, "arc length step");
  const auto [x_min, x_max] = std::minmax_element(input.begin(), input.end());
  const auto [y_min, y_max] = std::minmax_element(output.begin(), output.end());
  const double x_range = *x_max - *x_min;
  const double y_range = *y_max - *y_min;
  if (!(x_range > 0.0 && y_range > 0.0)) {
    throw Error(fmt::format(
        "arc length resampling scales input and output by their ranges, which must be > 0 "
        "(input range {}, output range {})",
        x_range, y_range));
  }
  const auto found = branches(input, band);
  // Branches share their end points, so the lengths are added up before the positions are set.
  std::vector<double> lengths;
  for (const auto& branch : found) {
    double length = 0.0;
    for (std::size_t k = branch.first + 1; k <= branch.last; ++k) {
      length +=
          std::hypot((input[k] - input[k - 1]) / x_range, (output[k] - output[k - 1]) / y_range);
    }
    lengths.push_back(length);
  }
  check_sample_count(lengths, step, "arc length step");
  ResampledRecord out;
  std::vector<double> position(input.size());
  bool first_branch = true;
  for (const auto& branch : found) {
    position[branch.first] = 0.0;
    for (std::size_t k = branch.first + 1; k <= branch.last; ++k) {
      position[k] = position[k - 1] + std::hypot((input[k] - input[k - 1]) / x_range,
                                                 (output[k] - output[k - 1]) / y_range);
    }
    append_branch(position, input, output, branch, interval_count(position[branch.last], step),
                  !first_branch, out);
    first_branch = false;
  }
  return out;
}

}  // namespace hyst::data
