#include "hyst/identify/compare.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "table_cells.hpp"

namespace hyst {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
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
    request.options = with_sample_time(entry, std::move(request.options), options.sample_time);
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
    // The free run judged where the ranking is made: on the held-out part.
    const auto verdict = judge_simulation(output, row.simulated, split.validation_begin);
    row.report->take_verdict(verdict.quality, verdict.reason);
    if (!std::all_of(row.simulated.begin(), row.simulated.end(),
                     [](double y) { return std::isfinite(y); })) {
      throw Error(fmt::format("unstable: {}", verdict.reason));
    }
    const auto held_out = std::span<const double>(row.simulated)
                              .subspan(split.validation_begin, split.validation_size());
    row.validation =
        error_metrics(output.subspan(split.validation_begin, split.validation_size()), held_out);
    row.ns_per_sample = simulation_ns_per_sample(*outcome.model, input, options.timing_seconds);
    if (row.report->domain) {
      row.held_out_domain = check_record_inputs(
          *row.report->domain, input.subspan(split.validation_begin, split.validation_size()),
          options.sample_time);
    }
    row.ok = true;
  } catch (const std::exception& error) {
    row.ok = false;
    row.error = error.what();
    row.simulated.clear();
  }
  return row;
}

using detail::csv_quoted;
using detail::markdown_cell;

std::string status_of(const ComparedModel& row) {
  if (!row.ok) return "failed";
  return std::string(row.report->status());
}

using detail::yes_no;

const ComparedModel* best_model(const ModelComparison& comparison) {
  const bool any = !comparison.ranking.empty() && comparison.ranking.front().ok;
  return any ? &comparison.ranking.front() : nullptr;
}

}  // namespace

std::vector<const ModelEntry*> compared_models(
    const std::vector<std::string>& models,
    const std::map<std::string, nlohmann::json>& fit_options, const ModelRegistry& registry) {
  std::vector<const ModelEntry*> entries;
  if (models.empty()) {
    for (const auto& entry : registry.entries()) {
      if (entry.can_fit()) entries.push_back(&entry);
    }
  } else {
    for (const auto& name : models) {
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
  for (const auto& option : fit_options) {
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
  if (!(options.no_fit_percent > 0.0) || !std::isfinite(options.no_fit_percent)) {
    throw Error(
        fmt::format("compare: no_fit_percent = {} must be finite and > 0", options.no_fit_percent),
        "no_fit_percent");
  }
  if (input.size() < 2) {
    throw Error(fmt::format("compare: {} samples; a fit part and a validation part need at least "
                            "2",
                            input.size()),
                "input");
  }
  const auto entries = compared_models(options.models, options.fit_options, registry);
  ModelComparison comparison;
  comparison.split = split_by_fraction(input.size(), options.validate_fraction);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (options.progress) options.progress({"models", k, entries.size(), entries[k]->name});
    comparison.ranking.push_back(
        compare_one(*entries[k], input, output, comparison.split, options));
  }
  if (options.progress) options.progress({"models", entries.size(), entries.size(), {}});
  std::stable_sort(comparison.ranking.begin(), comparison.ranking.end(),
                   [](const ComparedModel& a, const ComparedModel& b) {
                     if (a.ok != b.ok) return a.ok;
                     return a.ok && a.validation.nrmse_percent < b.validation.nrmse_percent;
                   });
  // The yardstick; data the references cannot use (NaN, a constant output) leaves it empty, and
  // every model then failed on the same data.
  try {
    ReferenceOptions reference;
    reference.time_series = options.time_series;
    comparison.references = reference_predictions(input, output, comparison.split, reference);
  } catch (const Error&) {
    comparison.references.clear();
  }
  const auto* yardstick = best_reference(comparison.references);
  for (auto& row : comparison.ranking) {
    row.beats_yardstick =
        row.ok && (yardstick == nullptr ||
                   row.validation.nrmse_percent < yardstick->validation->nrmse_percent);
  }
  comparison.no_fit_percent = options.no_fit_percent;
  if (const auto* best = best_model(comparison);
      best != nullptr && best->validation.nrmse_percent > options.no_fit_percent) {
    comparison.no_fit = diagnose_record(input, output, comparison.split);
  }
  return comparison;
}

std::string yardstick_line(const ModelComparison& comparison) {
  const auto* best = best_reference(comparison.references);
  if (best == nullptr) return "Yardstick: no reference predictor could be made on this record.";
  std::string scores;
  for (const auto& reference : comparison.references) {
    if (!scores.empty()) scores += ", ";
    scores += reference.validation
                  ? fmt::format("{} {:.4g} %", reference.name, reference.validation->nrmse_percent)
                  : fmt::format("{} not made ({})", reference.name, reference.error);
  }
  std::string losers;
  for (const auto& row : comparison.ranking) {
    if (row.ok && !row.beats_yardstick) losers += (losers.empty() ? "" : ", ") + row.model;
  }
  return fmt::format(
      "Yardstick (reference predictors fitted on the fit part, NRMSE on the held-out part): {}. "
      "Best reference: {}, NRMSE {:.4g} %. {}",
      scores, best->name, best->validation->nrmse_percent,
      losers.empty() ? std::string("Every fitted model beats it.")
                     : fmt::format("Models that do not beat it: {}.", losers));
}

std::string no_fit_line(const ModelComparison& comparison) {
  const auto* best = best_model(comparison);
  if (!comparison.no_fit || best == nullptr) return "";
  std::string seen;
  for (const auto& finding : comparison.no_fit->findings)
    seen += (seen.empty() ? "" : "; ") + finding;
  return fmt::format(
      "No model describes this record: the best held-out NRMSE is {:.4g} % ({}), above {:g} %. "
      "{}",
      best->validation.nrmse_percent, best->model, comparison.no_fit_percent,
      seen.empty() ? std::string("None of the looks at the data (butterfly, drift, "
                                 "extrapolation) finds the cause.")
                   : fmt::format("Seen: {}.", seen));
}

std::string held_out_domain_line(const ModelComparison& comparison) {
  std::vector<std::pair<std::string, DomainCheck>> checks;
  for (const auto& row : comparison.ranking)
    if (row.ok) checks.emplace_back(row.model, row.held_out_domain);
  const auto message = models_domain_message(checks, comparison.split.validation_size());
  if (message.empty()) return {};
  return fmt::format(
      "The held-out part leaves the domain the models were fitted on (their scores there "
      "measure extrapolation): {}.",
      message);
}

std::string model_comparison_markdown(const ModelComparison& comparison) {
  std::string text = fmt::format(
      "Fit on samples {}..{}, ranked by free-run error on the held-out samples {}..{}.\n\n",
      comparison.split.fit_begin, comparison.split.fit_end - 1, comparison.split.validation_begin,
      comparison.split.validation_end - 1);
  text +=
      "Time split: the held-out part follows the fit part in the same record, so the ranking "
      "measures extrapolation (in time and to any input range the fit part did not reach); rank "
      "on separate records for the range itself (hyst compare --fit-records/--validate-records "
      "or --leave-one-out).\n\n";
  if (const auto verdict = no_fit_line(comparison); !verdict.empty()) text += verdict + "\n\n";
  text += yardstick_line(comparison) + "\n\n";
  if (const auto domain = held_out_domain_line(comparison); !domain.empty())
    text += domain + "\n\n";
  text +=
      "| rank | model | validation NRMSE [%] | validation RMSE | max error | beats yardstick | "
      "parameters | fit time [s] | simulation [ns/sample] | status |\n"
      "|---:|---|---:|---:|---:|---|---:|---:|---:|---|\n";
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      text +=
          fmt::format("| {} | {} | {:.4g} | {:.4g} | {:.4g} | {} | {} | {:.3g} | {:.3g} | {} |\n",
                      ++rank, row.model, row.validation.nrmse_percent, row.validation.rmse,
                      row.validation.max_error, yes_no(row.beats_yardstick), row.parameters,
                      row.fit_seconds, row.ns_per_sample, status_of(row));
    } else {
      text += fmt::format("| - | {} | - | - | - | - | - | - | - | failed: {} |\n", row.model,
                          markdown_cell(row.error));
    }
  }
  return text;
}

std::string model_comparison_csv(const ModelComparison& comparison) {
  std::string text =
      "rank,model,status,validation_nrmse_percent,validation_rmse,validation_max_error,"
      "beats_yardstick,parameters,fit_seconds,simulation_ns_per_sample,message\n";
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      text +=
          fmt::format("{},{},{},{:.8g},{:.8g},{:.8g},{},{},{:.6g},{:.6g},{}\n", ++rank, row.model,
                      status_of(row), row.validation.nrmse_percent, row.validation.rmse,
                      row.validation.max_error, yes_no(row.beats_yardstick), row.parameters,
                      row.fit_seconds, row.ns_per_sample,
                      csv_quoted(row.report->quality_note.empty() ? row.report->message
                                                                  : row.report->quality_note));
    } else {
      text += fmt::format("-,{},failed,,,,,,,,{}\n", row.model, csv_quoted(row.error));
    }
  }
  for (const auto& reference : comparison.references) {
    if (reference.validation) {
      text += fmt::format("reference,{},reference,{:.8g},{:.8g},{:.8g},,,,,\n",
                          csv_quoted("reference: " + reference.name),
                          reference.validation->nrmse_percent, reference.validation->rmse,
                          reference.validation->max_error);
    } else {
      text += fmt::format("reference,{},failed,,,,,,,,{}\n",
                          csv_quoted("reference: " + reference.name), csv_quoted(reference.error));
    }
  }
  return text;
}

}  // namespace hyst
