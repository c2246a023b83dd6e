#include "hyst/identify/compare.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::vector<const ModelEntry*> chosen_models(const CompareOptions& options,
                                             const ModelRegistry& registry) {
  std::vector<const ModelEntry*> entries;
  if (options.models.empty()) {
    for (const auto& entry : registry.entries()) {
      if (entry.can_fit()) entries.push_back(&entry);
    }
  } else {
    for (const auto& name : options.models) {
      const auto& entry = registry.find(name);  // throws for an unknown name, listing the known
      if (!entry.can_fit()) {
        throw Error(fmt::format("compare: model '{}' has no fitter", name), "models");
      }
      if (std::find(entries.begin(), entries.end(), &entry) != entries.end()) {
        throw Error(fmt::format("compare: model '{}' is listed twice", name), "models");
      }
      entries.push_back(&entry);
    }
  }
  for (const auto& option : options.fit_options) {
    const std::string& name = option.first;  // clang 14 cannot capture a structured binding
    const bool compared = std::any_of(entries.begin(), entries.end(),
                                      [&](const ModelEntry* entry) { return entry->name == name; });
    if (!compared) {
      throw Error(fmt::format("compare: fit options given for '{}', which is not compared", name),
                  "fit_options");
    }
  }
  return entries;
}

// Nanoseconds per sample of the batch simulation of the whole record from the fitted state.
double simulation_ns_per_sample(const DynamicModel& fitted, std::span<const double> input,
                                double minimum_seconds) {
  std::vector<double> output(input.size());
  std::size_t runs = 0;
  const auto start = Clock::now();
  do {
    auto model = fitted.clone();
    model->simulate(input, output);
    ++runs;
  } while (seconds_since(start) < minimum_seconds);
  return 1e9 * seconds_since(start) / static_cast<double>(runs * input.size());
}

ComparedModel compare_one(const ModelEntry& entry, std::span<const double> input,
                          std::span<const double> output, const DataSplit& split,
                          const CompareOptions& options) {
  ComparedModel row;
  row.model = entry.name;
  try {
    FitRequest request;
    request.input = input.subspan(split.fit_begin, split.fit_size());
    request.output = output.subspan(split.fit_begin, split.fit_size());
    if (const auto found = options.fit_options.find(entry.name);
        found != options.fit_options.end()) {
      request.options = found->second;
    }
    const auto started = Clock::now();
    auto outcome = fit_model(entry, request);
    row.fit_seconds = seconds_since(started);
    row.report = outcome.report;
    row.parameters = outcome.model->parameter_count();
    if (outcome.report.termination == Termination::failed) {
      throw Error(fmt::format("the fit failed: {}", outcome.report.message));
    }
    row.simulated.resize(input.size());
    auto model = outcome.model->clone();
    model->simulate(input, row.simulated);
    const auto held_out = std::span<const double>(row.simulated)
                              .subspan(split.validation_begin, split.validation_size());
    row.validation =
        error_metrics(output.subspan(split.validation_begin, split.validation_size()), held_out);
    row.ns_per_sample = simulation_ns_per_sample(*outcome.model, input, options.timing_seconds);
    row.ok = true;
  } catch (const std::exception& error) {
    row.ok = false;
    row.error = error.what();
    row.simulated.clear();
  }
  return row;
}

std::string csv_quoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

std::string markdown_cell(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out;
}

std::string status_of(const ComparedModel& row) {
  if (!row.ok) return "failed";
  return std::string(to_string(row.report->termination));
}

}  // namespace

ModelComparison compare_models(std::span<const double> input, std::span<const double> output,
                               const CompareOptions& options, const ModelRegistry& registry) {
  require_same_size(input.size(), "input", output.size(), "output");
  if (!(options.validate_fraction > 0.0 && options.validate_fraction < 1.0)) {
    throw Error(fmt::format("compare: validate_fraction = {} must be > 0 and < 1",
                            options.validate_fraction),
                "validate_fraction");
  }
  if (!(options.timing_seconds >= 0.0) || !std::isfinite(options.timing_seconds)) {
    throw Error(
        fmt::format("compare: timing_seconds = {} must be finite and >= 0", options.timing_seconds),
        "timing_seconds");
  }
  if (input.size() < 2) {
    throw Error(fmt::format("compare: {} samples; a fit part and a validation part need at least "
                            "2",
                            input.size()),
                "input");
  }
  const auto entries = chosen_models(options, registry);
  ModelComparison comparison;
  comparison.split = split_by_fraction(input.size(), options.validate_fraction);
  for (const auto* entry : entries)
    comparison.ranking.push_back(compare_one(*entry, input, output, comparison.split, options));
  std::stable_sort(comparison.ranking.begin(), comparison.ranking.end(),
                   [](const ComparedModel& a, const ComparedModel& b) {
                     if (a.ok != b.ok) return a.ok;
                     return a.ok && a.validation.nrmse < b.validation.nrmse;
                   });
  return comparison;
}

std::string model_comparison_markdown(const ModelComparison& comparison) {
  std::string text = fmt::format(
      "Fit on samples {}..{}, ranked by free-run error on the held-out samples {}..{}.\n\n",
      comparison.split.fit_begin, comparison.split.fit_end - 1, comparison.split.validation_begin,
      comparison.split.validation_end - 1);
  text +=
      "| rank | model | validation NRMSE | validation RMSE | max error | parameters | fit time [s] "
      "| simulation [ns/sample] | status |\n"
      "|---:|---|---:|---:|---:|---:|---:|---:|---|\n";
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      text += fmt::format("| {} | {} | {:.4g} | {:.4g} | {:.4g} | {} | {:.3g} | {:.3g} | {} |\n",
                          ++rank, row.model, row.validation.nrmse, row.validation.rmse,
                          row.validation.max_error, row.parameters, row.fit_seconds,
                          row.ns_per_sample, status_of(row));
    } else {
      text += fmt::format("| - | {} | - | - | - | - | - | - | failed: {} |\n", row.model,
                          markdown_cell(row.error));
    }
  }
  return text;
}

std::string model_comparison_csv(const ModelComparison& comparison) {
  std::string text =
      "rank,model,status,validation_nrmse,validation_rmse,validation_max_error,parameters,"
      "fit_seconds,simulation_ns_per_sample,message\n";
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      text += fmt::format("{},{},{},{:.8g},{:.8g},{:.8g},{},{:.6g},{:.6g},{}\n", ++rank, row.model,
                          status_of(row), row.validation.nrmse, row.validation.rmse,
                          row.validation.max_error, row.parameters, row.fit_seconds,
                          row.ns_per_sample, csv_quoted(row.report->message));
    } else {
      text += fmt::format("-,{},failed,,,,,,,{}\n", row.model, csv_quoted(row.error));
    }
  }
  return text;
}

}  // namespace hyst
