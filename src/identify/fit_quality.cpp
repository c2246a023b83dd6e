#include "hyst/identify/fit_quality.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

constexpr double kBandRanges = 10.0;       // width of the admissible band in measured ranges
constexpr double kDegenerateRatio = 0.01;  // std(simulated) / std(measured) below: degenerate

double standard_deviation(std::span<const double> values) {
  double mean = 0.0;
  for (const double v : values)
    mean += v;
  mean /= static_cast<double>(values.size());
  double sum = 0.0;
  for (const double v : values)
    sum += (v - mean) * (v - mean);
  return std::sqrt(sum / static_cast<double>(values.size()));
}

}  // namespace

QualityVerdict judge_simulation(std::span<const double> measured, std::span<const double> simulated,
                                std::size_t judged_begin) {
  require_same_size(measured.size(), "measured", simulated.size(), "simulated");
  require_not_empty(measured.size(), "measured");
  if (judged_begin >= measured.size()) {
    throw Error(fmt::format("judged_begin = {} is not a sample of the {}-sample record",
                            judged_begin, measured.size()),
                "judged_begin");
  }
  const auto [lowest, highest] = std::minmax_element(measured.begin(), measured.end());
  const double range = *highest - *lowest;
  const double middle = 0.5 * (*highest + *lowest);
  for (std::size_t k = 0; k < simulated.size(); ++k) {
    if (!std::isfinite(simulated[k]) ||
        std::abs(simulated[k] - middle) > 0.5 * kBandRanges * range) {
      return {FitQuality::unstable,
              fmt::format("the simulation leaves the band of {:g} times the measured output range "
                          "at sample {} (simulated {:.4g}, measured {:.4g}..{:.4g})",
                          kBandRanges, k, simulated[k], *lowest, *highest)};
    }
  }
  const double measured_std = standard_deviation(measured.subspan(judged_begin));
  const double simulated_std = standard_deviation(simulated.subspan(judged_begin));
  if (measured_std > 0.0 && simulated_std < kDegenerateRatio * measured_std) {
    return {FitQuality::degenerate,
            fmt::format("the {} is nearly constant: its standard deviation is {:.2g} % of the "
                        "measured output's (below {:g} %)",
                        judged_begin > 0 ? "held-out prediction" : "simulation",
                        100.0 * simulated_std / measured_std, 100.0 * kDegenerateRatio)};
  }
  return {FitQuality::sound, ""};
}

}  // namespace hyst
