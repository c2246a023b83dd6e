#include "hyst/data/preprocessing.hpp"

#include <algorithm>
#include <charconv>
#include <utility>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/error.hpp"
#include "hyst/data/corrections.hpp"
#include "hyst/data/cycles.hpp"
#include "hyst/data/resampling.hpp"
#include "hyst/data/reversal_points.hpp"
#include "record_checks.hpp"

namespace hyst::data {
namespace {

std::optional<std::size_t> whole_number(std::string_view text) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return {};
  return value;
}

//! remove_drift() on the output of `record`, described in one line.
std::string detrend(PreparedRecord& record, double band) {
  auto removal = remove_drift(record.input, record.output, band);
  record.output = std::move(removal.output);
  return fmt::format(
      "linear drift removed between {} cycle boundaries (band {:.4g}; largest closure error "
      "{:.4g} before)",
      removal.cycles + 1, band, removal.closure_error);
}

void check_options(const Preprocessing& options) {
  if (options.band < 0.0 || options.resample_step < 0.0) {
    throw Error(fmt::format("band = {} and resample step = {} must be >= 0 (0: automatic)",
                            options.band, options.resample_step));
  }
}

double band_of(std::span<const double> input, const Preprocessing& options) {
  return options.band > 0.0 ? options.band : default_band(input);
}

}  // namespace

CycleRange cycle_range_from_string(std::string_view text) {
  if (text == "all") return {};
  const auto dash = text.find('-');
  const auto first = whole_number(text.substr(0, dash));
  std::optional<std::size_t> last = first;
  if (dash != std::string_view::npos) {
    last = dash + 1 == text.size() ? std::optional<std::size_t>(0)
                                   : whole_number(text.substr(dash + 1));
  }
  if (!first || !last || *first == 0 || (*last != 0 && *last < *first)) {
    throw Error(fmt::format(
        "cycles '{}': expected N, N-M (1 <= N <= M), N- (from N to the last) or all", text));
  }
  return {*first, *last};
}

std::string to_string(const CycleRange& range) {
  if (range.first == 1 && range.last == 0) return "all";
  if (range.last == 0) return fmt::format("{}-", range.first);
  if (range.last == range.first) return fmt::format("{}", range.first);
  return fmt::format("{}-{}", range.first, range.last);
}

ResampleMethod resample_method_from_string(std::string_view text) {
  return hyst::detail::value_named(text, enum_names<ResampleMethod>, "resampling method");
}

PreparedRecord preprocess(std::span<const double> input, std::span<const double> output,
                          const Preprocessing& options) {
  detail::require_record(input, output, 2);
  check_options(options);
  PreparedRecord record{{input.begin(), input.end()}, {output.begin(), output.end()}, {}};
  if (!options.any()) return record;
  const double band = band_of(input, options);

  if (options.detrend) record.steps.push_back(detrend(record, band));
  if (options.cycles) {
    const auto found = cycles(record.input, band);
    const auto& range = *options.cycles;
    const std::size_t last = range.last == 0 ? found.size() : range.last;
    if (found.empty() || range.first > found.size() || last > found.size()) {
      throw Error(
          fmt::format("cycles {} requested but the record has {} complete cycles (band "
                      "{:.4g})",
                      to_string(range), found.size(), band));
    }
    const std::size_t from = found[range.first - 1].first;
    const std::size_t to = found[last - 1].last;
    for (auto* samples : {&record.input, &record.output}) {
      samples->erase(samples->begin() + static_cast<std::ptrdiff_t>(to) + 1, samples->end());
      samples->erase(samples->begin(), samples->begin() + static_cast<std::ptrdiff_t>(from));
    }
    record.steps.push_back(fmt::format("cycles {} of {} kept (samples {}..{})", to_string(range),
                                       found.size(), from, to));
  }
  if (options.resample != ResampleMethod::none) {
    const std::size_t before = record.input.size();
    const bool grid = options.resample == ResampleMethod::input_grid;
    double step = options.resample_step;
    if (step == 0.0) {
      const auto [lowest, highest] = std::minmax_element(record.input.begin(), record.input.end());
      step = grid ? (*highest - *lowest) / 100.0 : 0.01;
    }
    auto resampled = grid ? resample_on_input_grid(record.input, record.output, band, step)
                          : resample_by_arc_length(record.input, record.output, band, step);
    record.input = std::move(resampled.input);
    record.output = std::move(resampled.output);
    record.steps.push_back(fmt::format(
        "resampled per branch on {} of step {:.4g} ({} -> {} samples)",
        grid ? "an input grid" : "normalised arc length", step, before, record.input.size()));
  }
  return record;
}

PreparedRecord prepare_validation(std::span<const double> input, std::span<const double> output,
                                  const Preprocessing& options) {
  detail::require_record(input, output, 2);
  check_options(options);
  PreparedRecord record{{input.begin(), input.end()}, {output.begin(), output.end()}, {}};
  if (!options.detrend) return record;
  const double band = band_of(input, options);
  if (input.size() < 3 || cycles(input, band).empty()) {
    record.steps.push_back(
        fmt::format("drift not removed: no complete cycle (band {:.4g}) to measure it on", band));
  } else {
    record.steps.push_back(detrend(record, band));
  }
  return record;
}

}  // namespace hyst::data
