#include "hyst/actuator/comparison.hpp"

#include <cmath>
#include <variant>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/io/limits.hpp"
#include "hyst/plot/gnuplot.hpp"

namespace hyst {
namespace {

// The part of a trace from sample `first` on.
LoopTrace tail(const LoopTrace& trace, std::size_t first) {
  const auto cut = [first](const std::vector<double>& signal) {
    return std::vector<double>(signal.begin() + static_cast<std::ptrdiff_t>(first), signal.end());
  };
  return {
      cut(trace.reference), cut(trace.measured), cut(trace.position), cut(trace.current_reference),
      cut(trace.current),   cut(trace.force),    cut(trace.voltage)};
}

std::string cell(double value, double scale, int decimals) {
  if (std::isnan(value)) return "-";
  return fmt::format("{:.{}f}", value * scale, decimals);
}

std::vector<double> scaled(const std::vector<double>& values, double factor) {
  std::vector<double> result(values.size());
  for (std::size_t k = 0; k < values.size(); ++k)
    result[k] = values[k] * factor;
  return result;
}

}  // namespace

LoopTrace simulate_loop(const ActuatorConfig& config, ControlStrategy strategy,
                        const std::vector<double>& reference) {
  require_finite(reference, "reference");
  LoopTrace trace;
  // One dispatch per run; the loop inside is compiled for the concrete model.
  std::visit(
      [&](const auto& model) {
        using H = std::decay_t<decltype(model)>;
        const ControlLoop<H> loop(Actuator<H>(model, config.plant),
                                  std::get<H>(config.compensator_hysteresis), config.loop);
        auto state = loop.initial_state();
        loop.run(state, strategy, reference, trace);
      },
      config.hysteresis);
  return trace;
}

std::vector<control::Reference> scenario_references(const ActuatorConfig& config) {
  const auto& s = config.scenarios;
  const double h = config.plant.sample_time;
  std::vector<control::Reference> references;
  references.push_back(
      control::step_reference(s.low, s.high, 0.1 * s.step_duration, s.step_duration, h));
  const double middle = 0.5 * (s.low + s.high);
  const double amplitude = 0.5 * (s.high - s.low);
  for (double frequency : s.sine_frequencies) {
    for (double fraction : {1.0, 0.5}) {
      auto sine = control::sine_reference(middle, fraction * amplitude, frequency,
                                          s.sine_periods / frequency, h);
      sine.name = fmt::format("sine_{:g}Hz_{}", frequency, fraction == 1.0 ? "full" : "half");
      references.push_back(std::move(sine));
    }
  }
  references.push_back(
      control::triangle_reference(s.low, s.high, s.triangle_loops, s.triangle_rate, h));
  return references;
}

Comparison compare_strategies(const ActuatorConfig& config,
                              const std::vector<control::Reference>& references) {
  Comparison comparison{config.name, config.plant.sample_time, {}};
  // A count from two user-given numbers: checked as a double before it becomes an integer.
  const double lead_in_samples = config.scenarios.lead_in / config.plant.sample_time;
  if (!(lead_in_samples <= io::limits::kMaxDerivedSamples)) {
    throw Error(fmt::format(
        "scenarios.lead_in = {} s is {:.4g} samples of h = {} s, more than the limit of {:.0f}",
        config.scenarios.lead_in, lead_in_samples, config.plant.sample_time,
        io::limits::kMaxDerivedSamples));
  }
  const auto lead_in = static_cast<std::size_t>(std::llround(lead_in_samples));
  for (const auto& reference : references) {
    require_not_empty(reference.values.size(), "reference " + reference.name);
    std::vector<double> values(lead_in, reference.values.front());
    values.insert(values.end(), reference.values.begin(), reference.values.end());
    for (auto strategy : kControlStrategies) {
      ComparisonRun run{
          reference.name, strategy, {}, tail(simulate_loop(config, strategy, values), lead_in)};
      run.metrics =
          control::tracking_metrics(run.trace.reference, run.trace.measured, run.trace.voltage,
                                    config.plant.sample_time, reference.step);
      comparison.runs.push_back(std::move(run));
    }
  }
  return comparison;
}

std::string comparison_markdown(const Comparison& comparison) {
  std::string text = fmt::format(
      "| reference | strategy | RMS error [um] | max error [um] | settling time [ms] | "
      "overshoot [%] | RMS voltage [V] |\n|---|---|---:|---:|---:|---:|---:|\n");
  for (const auto& run : comparison.runs) {
    const auto& m = run.metrics;
    text += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", run.reference,
                        to_string(run.strategy), cell(m.rms_error, 1e6, 2),
                        cell(m.max_error, 1e6, 2), cell(m.settling_time, 1e3, 1),
                        cell(m.overshoot, 1.0, 1), cell(m.control_effort, 1.0, 2));
  }
  return text;
}

std::string comparison_csv(const Comparison& comparison) {
  std::string text =
      "reference,strategy,rms_error_m,max_error_m,settling_time_s,overshoot_percent,"
      "rms_voltage_V\n";
  for (const auto& run : comparison.runs) {
    const auto& m = run.metrics;
    text += fmt::format("{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", run.reference,
                        to_string(run.strategy), m.rms_error, m.max_error, m.settling_time,
                        m.overshoot, m.control_effort);
  }
  return text;
}

std::vector<std::filesystem::path> write_comparison_plots(const Comparison& comparison,
                                                          const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> written;
  std::size_t first = 0;
  while (first < comparison.runs.size()) {
    const std::string& name = comparison.runs[first].reference;
    std::size_t last = first;
    while (last < comparison.runs.size() && comparison.runs[last].reference == name)
      ++last;
    plot::Figure tracking{.title = fmt::format("{}: {} tracking", comparison.actuator, name),
                          .x_label = "t [s]",
                          .y_label = "position [um]"};
    plot::Figure error{
        .title = fmt::format("{}: {} tracking error r - y", comparison.actuator, name),
        .x_label = "t [s]",
        .y_label = "error [um]"};
    const auto& first_trace = comparison.runs[first].trace;
    std::vector<double> time(first_trace.reference.size());
    for (std::size_t k = 0; k < time.size(); ++k)
      time[k] = static_cast<double>(k) * comparison.sample_time;
    tracking.series.push_back({.label = "reference",
                               .x = time,
                               .y = scaled(first_trace.reference, 1e6),
                               .color = "black"});
    for (std::size_t r = first; r < last; ++r) {
      const auto& trace = comparison.runs[r].trace;
      const std::string label(to_string(comparison.runs[r].strategy));
      tracking.series.push_back({.label = label, .x = time, .y = scaled(trace.measured, 1e6)});
      std::vector<double> difference(trace.reference.size());
      for (std::size_t k = 0; k < difference.size(); ++k)
        difference[k] = 1e6 * (trace.reference[k] - trace.measured[k]);
      error.series.push_back({.label = label, .x = time, .y = std::move(difference)});
    }
    written.push_back(folder / fmt::format("tracking_{}.png", name));
    plot::write_png(tracking, written.back());
    written.push_back(folder / fmt::format("error_{}.png", name));
    plot::write_png(error, written.back());
    first = last;
  }
  return written;
}

}  // namespace hyst
