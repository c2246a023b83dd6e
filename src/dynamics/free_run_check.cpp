#include "hyst/dynamics/free_run_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace hyst {

std::vector<ChannelRange> channel_ranges(const PeriodicSignals& signals) {
  if (signals.channels == 0) return {};
  std::vector<ChannelRange> ranges(signals.channels, {std::numeric_limits<double>::infinity(),
                                                      -std::numeric_limits<double>::infinity()});
  for (std::size_t i = 0; i < signals.values.size(); ++i) {
    auto& range = ranges[i % signals.channels];
    range.minimum = std::min(range.minimum, signals.values[i]);
    range.maximum = std::max(range.maximum, signals.values[i]);
  }
  return ranges;
}

void count_runaway(const Eigen::MatrixXd& simulated, const std::vector<ChannelRange>& ranges,
                   std::size_t realisation, RunawayCount& count) {
  for (Eigen::Index n = 0; n < simulated.rows(); ++n)
    for (Eigen::Index c = 0; c < simulated.cols() && std::size_t(c) < ranges.size(); ++c) {
      const auto& range = ranges[std::size_t(c)];
      const double margin = kRunawayRangeWidths * (range.maximum - range.minimum);
      const double y = simulated(n, c);
      // Written so that NaN counts as run away.
      if (y >= range.minimum - margin && y <= range.maximum + margin) continue;
      if (count.samples == 0) {
        count.realisation = realisation;
        count.sample = std::size_t(n);
        count.channel = std::size_t(c);
      }
      ++count.samples;
    }
}

std::vector<std::string> free_run_warnings(const StateSpace& linear, const RunawayCount& runaway) {
  std::vector<std::string> warnings;
  const double radius = linear.spectral_radius();
  if (radius > kUnstablePoleMagnitude)
    warnings.push_back(fmt::format(
        "the linear block has a pole of magnitude {:.6g}, outside the unit circle: the model is "
        "unstable in free run",
        radius));
  if (runaway.samples > 0)
    warnings.push_back(fmt::format(
        "{} simulated samples ran away (beyond their channel's measured range by more than {:g} "
        "times its width), the first at realisation {}, sample {}, output {}",
        runaway.samples, kRunawayRangeWidths, runaway.realisation + 1, runaway.sample + 1,
        runaway.channel + 1));
  return warnings;
}

}  // namespace hyst
