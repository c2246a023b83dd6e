#include "hyst/identify/fitted_domain.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

// The samples of `values` beyond [low, high] widened by kDomainMargin of its width (NaN too).
DomainCheck beyond(std::span<const double> values, double low, double high, std::string_view what) {
  const double margin = kDomainMargin * (high - low);
  const auto side_text = [&](std::string_view side) {
    return fmt::format("{} {} the fitted range [{:.6g}, {:.6g}] by more than {:g} % of its width",
                       what, side, low, high, 100.0 * kDomainMargin);
  };
  DomainExcursion below{side_text("below"), 0, 0};
  DomainExcursion above{side_text("above"), 0, 0};
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

std::optional<double> FittedDomain::duration() const {
  if (!sample_time) return std::nullopt;
  return static_cast<double>(samples) * *sample_time;
}

std::optional<double> FittedDomain::largest_input_rate() const {
  if (!sample_time) return std::nullopt;
  return largest_input_step / *sample_time;
}

std::optional<double> FittedDomain::longest_hold() const {
  if (!sample_time) return std::nullopt;
  return static_cast<double>(longest_hold_samples) * *sample_time;
}

DomainCheck check_timing(const FittedDomain& domain, std::span<const double> input,
                         std::optional<double> sample_time, std::span<const double> steps) {
  DomainCheck check;
  if (!domain.sample_time) return check;
  const double uniform_step = sample_time.value_or(*domain.sample_time);
  if (!steps.empty() && steps.size() != input.size())
    throw Error(fmt::format("check_timing: {} steps for {} inputs", steps.size(), input.size()));
  const double fastest = domain.largest_input_step / *domain.sample_time;
  DomainExcursion rates{
      fmt::format("input rates above the fitted largest {:.6g} per s by more than {:g} %", fastest,
                  100.0 * kDomainMargin),
      0, 0};
  // A hold as long as the fit record's own was seen, whatever the lags; beyond both it and the
  // slowest lag, the creep that follows is what no fit record showed.
  DomainExcursion holds;
  std::optional<double> hold_limit;
  if (domain.largest_time_constant) {
    hold_limit = std::max(*domain.largest_time_constant, *domain.longest_hold());
    holds.what = fmt::format(
        "holds (time without a reversal) longer than the longest fitted one ({:.6g} s) and the "
        "largest time constant ({:.6g} s)",
        *domain.longest_hold(), *domain.largest_time_constant);
  }
  int direction = 0;
  double held = 0.0;  // [s] since the last reversal
  for (std::size_t k = 1; k < input.size(); ++k) {
    const double step = steps.empty() ? uniform_step : steps[k];
    const double change = input[k] - input[k - 1];
    if (std::abs(change) / step > fastest * (1.0 + kDomainMargin)) {
      if (rates.samples++ == 0) rates.first = k;
    }
    const int now = change > 0.0 ? 1 : change < 0.0 ? -1 : direction;
    // As fitted_domain() counts a run: the reversal's sample and this one begin a new one.
    held = now != direction && direction != 0 ? 2.0 * step : (k == 1 ? 2.0 * step : held + step);
    direction = now;
    if (hold_limit && held > *hold_limit * (1.0 + kDomainMargin)) {
      if (holds.samples++ == 0) holds.first = k;
    }
  }
  if (rates.samples > 0) check.excursions.push_back(std::move(rates));
  if (holds.samples > 0) check.excursions.push_back(std::move(holds));
  return check;
}

void DomainCheck::append(DomainCheck other) {
  excursions.insert(excursions.end(), std::make_move_iterator(other.excursions.begin()),
                    std::make_move_iterator(other.excursions.end()));
}

DomainCheck check_record_inputs(const FittedDomain& domain, std::span<const double> input,
                                std::optional<double> sample_time, std::span<const double> steps) {
  DomainCheck check = check_inputs(domain, input);
  check.append(check_timing(domain, input, sample_time, steps));
  return check;
}

std::string DomainCheck::message(std::size_t record_samples) const {
  std::string text;
  for (const auto& e : excursions)
    text += fmt::format("{}{} of {} samples: {} (first at sample {})", text.empty() ? "" : "; ",
                        e.samples, record_samples, e.what, e.first);
  return text;
}

DomainCheck check_inputs(const FittedDomain& domain, std::span<const double> input) {
  return beyond(input, domain.input_min, domain.input_max, "inputs");
}

DomainCheck check_targets(const FittedDomain& domain, std::span<const double> targets) {
  return beyond(targets, domain.output_min, domain.output_max, "targets");
}

std::string models_domain_message(
    std::span<const std::pair<std::string, DomainCheck>> checks_by_model,
    std::size_t record_samples) {
  // (message, models) in the order the messages first appear.
  std::vector<std::pair<std::string, std::string>> groups;
  for (const auto& [model, check] : checks_by_model) {
    if (check.inside()) continue;
    const auto message = check.message(record_samples);
    const auto group = std::find_if(groups.begin(), groups.end(),
                                    [&](const auto& g) { return g.first == message; });
    if (group == groups.end()) {
      groups.emplace_back(message, model);
    } else {
      group->second += ", " + model;
    }
  }
  std::string text;
  for (const auto& [message, models] : groups)
    text += fmt::format("{}{}: {}", text.empty() ? "" : "; ", models, message);
  return text;
}

FittedDomain merged_domain(std::span<const FittedDomain> parts) {
  if (parts.empty()) throw Error("merged_domain: no fit record");
  FittedDomain merged = parts.front();
  merged.samples = 0;
  for (const auto& part : parts) {
    merged.input_min = std::min(merged.input_min, part.input_min);
    merged.input_max = std::max(merged.input_max, part.input_max);
    merged.output_min = std::min(merged.output_min, part.output_min);
    merged.output_max = std::max(merged.output_max, part.output_max);
    merged.samples += part.samples;
    merged.largest_input_step = std::max(merged.largest_input_step, part.largest_input_step);
    merged.longest_hold_samples = std::max(merged.longest_hold_samples, part.longest_hold_samples);
    if (part.largest_time_constant) {
      merged.largest_time_constant =
          std::max(merged.largest_time_constant.value_or(0.0), *part.largest_time_constant);
    }
  }
  const bool timed = std::all_of(parts.begin(), parts.end(), [](const FittedDomain& part) {
    return part.sample_time.has_value();
  });
  if (!timed) {
    merged.sample_time.reset();
    return merged;
  }
  // In steps of the smallest sample time: the rate, hold and duration in seconds carry over.
  double step = *parts.front().sample_time;
  for (const auto& part : parts)
    step = std::min(step, *part.sample_time);
  double rate = 0.0, hold = 0.0, duration = 0.0;
  for (const auto& part : parts) {
    rate = std::max(rate, *part.largest_input_rate());
    hold = std::max(hold, *part.longest_hold());
    duration += *part.duration();
  }
  merged.sample_time = step;
  merged.largest_input_step = rate * step;
  merged.longest_hold_samples = static_cast<std::size_t>(std::llround(hold / step));
  merged.samples = static_cast<std::size_t>(std::llround(duration / step));
  return merged;
}

}  // namespace hyst
