#include "hyst/identify/fitted_domain.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"

namespace hyst {
namespace {

// The samples of `values` beyond [low, high] widened by kDomainMargin of its width (NaN too).
DomainCheck beyond(std::span<const double> values, double low, double high, std::string_view what) {
  const double margin = kDomainMargin * (high - low);
  DomainExcursion below{fmt::format("{} below the fitted range [{:.6g}, {:.6g}]", what, low, high),
                        0, 0};
  DomainExcursion above{fmt::format("{} above the fitted range [{:.6g}, {:.6g}]", what, low, high),
                        0, 0};
  for (std::size_t k = 0; k < values.size(); ++k) {
    const double v = values[k];
    if (v >= low - margin && v <= high + margin) continue;
    auto& side = v > high ? above : below;  // NaN counts below
    if (side.samples++ == 0) side.first = k;
  }
  DomainCheck check;
  for (auto* side : {&below, &above})
    if (side->samples > 0) check.excursions.push_back(std::move(*side));
  return check;
}

}  // namespace

FittedDomain fitted_domain(std::span<const double> input, std::span<const double> output,
                           std::optional<double> sample_time) {
  require_same_size(input.size(), "input", output.size(), "output");
  require_not_empty(input.size(), "input");
  FittedDomain domain;
  const auto [input_low, input_high] = std::minmax_element(input.begin(), input.end());
  const auto [output_low, output_high] = std::minmax_element(output.begin(), output.end());
  domain.input_min = *input_low;
  domain.input_max = *input_high;
  domain.output_min = *output_low;
  domain.output_max = *output_high;
  domain.samples = input.size();
  domain.sample_time = sample_time;
  // A hold: the samples since the input last changed direction (steps of zero keep it).
  int direction = 0;
  std::size_t run = 1;
  domain.longest_hold_samples = 1;
  for (std::size_t k = 1; k < input.size(); ++k) {
    const double step = input[k] - input[k - 1];
    domain.largest_input_step = std::max(domain.largest_input_step, std::abs(step));
    const int now = step > 0.0 ? 1 : step < 0.0 ? -1 : direction;
    run = now != direction && direction != 0 ? 2 : run + 1;  // a reversal at k - 1
    direction = now;
    domain.longest_hold_samples = std::max(domain.longest_hold_samples, run);
  }
  return domain;
}

std::string DomainCheck::message(std::size_t record_samples) const {
  std::string text;
  for (const auto& e : excursions)
    text += fmt::format(
        "{}{} of {} samples: {} by more than {:g} % of its width (first at sample "
        "{})",
        text.empty() ? "" : "; ", e.samples, record_samples, e.what, 100.0 * kDomainMargin,
        e.first);
  return text;
}

DomainCheck check_inputs(const FittedDomain& domain, std::span<const double> input) {
  return beyond(input, domain.input_min, domain.input_max, "inputs");
}

DomainCheck check_targets(const FittedDomain& domain, std::span<const double> targets) {
  return beyond(targets, domain.output_min, domain.output_max, "targets");
}

}  // namespace hyst
