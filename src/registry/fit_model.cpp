// Fitting through the registry with the preparation of the measured record (hyst/data), and the
// judgement of every fit that follows it: the simulation's quality (identify/fit_quality.hpp) and
// the yardstick of reference predictors (identify/reference_predictors.hpp).

#include <algorithm>
#include <exception>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/identify/data_split.hpp"
#include "hyst/identify/fit_quality.hpp"
#include "hyst/identify/fitted_domain.hpp"
#include "hyst/identify/reference_predictors.hpp"
#include "hyst/io/limits.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/registry/validation_rule.hpp"
#include "model_adapter.hpp"

namespace hyst {
namespace {

void add_steps(std::vector<std::string>& report, std::string_view prefix,
               const std::vector<std::string>& steps) {
  for (const auto& step : steps)
    report.push_back(fmt::format("{}{}", prefix, step));
}

// The records the fitter saw: the fit record (with its held-out part when a fraction is held out)
// and, when given, the separate validation record.
struct FittedRecords {
  std::span<const double> input;
  std::span<const double> output;
  std::span<const double> validation_input;
  std::span<const double> validation_output;
};

// Judges the fitted model's free run over the fit record (the held-out part, when there is one,
// for the degeneracy) and scores the reference predictors on the held-out samples. A check that
// cannot be made leaves the report as the fitter wrote it: the fit itself stands.
void judge_fit(FitOutcome& outcome, const FittedRecords& records, const FitRequest& request) {
  auto& report = outcome.report;
  if (report.termination == Termination::failed || !outcome.model) return;
  const std::size_t samples = records.input.size();
  const bool held_out_part = records.validation_input.empty() && request.validate_fraction > 0.0 &&
                             report.validation && report.validation->samples < samples;
  const std::size_t held_begin = held_out_part ? samples - report.validation->samples : 0;
  std::vector<double> simulated(samples);
  try {
    outcome.model->clone()->simulate(records.input, simulated);
  } catch (const Error& error) {
    // An output that overflows or runs away on the fit record's own input.
    report.take_verdict(FitQuality::unstable, error.what());
    simulated.clear();
  }
  try {
    if (!simulated.empty()) {
      const auto verdict = judge_simulation(records.output, simulated, held_begin);
      report.take_verdict(verdict.quality, verdict.reason);
    }
  } catch (const std::exception&) {
    report.take_verdict(FitQuality::unchecked, "");  // e.g. a record too short to judge
  }
  try {
    // The samples of a resampled record are not in time order: no ARX there.
    ReferenceOptions options;
    options.time_series = request.preprocessing.resample == data::ResampleMethod::none;
    if (held_out_part) {
      report.references = reference_predictions(records.input, records.output,
                                                {0, held_begin, held_begin, samples}, options);
    } else if (!records.validation_input.empty()) {
      // A separate record does not continue the fit record: the static references only, and
      // "last value held" holds the fit record's last output.
      std::vector<double> input(records.input.begin(), records.input.end());
      std::vector<double> output(records.output.begin(), records.output.end());
      input.insert(input.end(), records.validation_input.begin(), records.validation_input.end());
      output.insert(output.end(), records.validation_output.begin(),
                    records.validation_output.end());
      options.time_series = false;
      report.references =
          reference_predictions(input, output, {0, samples, samples, input.size()}, options);
    }
  } catch (const std::exception&) {
    report.references.clear();
  }
}

// The largest of the model's time constants [s] (the creep models' lags), if it has any.
std::optional<double> largest_time_constant(const DynamicModel& model) {
  const auto params = model.params();
  const auto found = params.find("time_constants");
  if (found == params.end() || !found->is_array() || found->empty()) return std::nullopt;
  double largest = 0.0;
  for (const auto& tau : *found)
    largest = std::max(largest, tau.get<double>());
  return largest;
}

// The domain of the samples the model was fitted on: the record without its held-out end, at
// the sample time of the fitted model when it has one (else of the fit options).
FittedDomain domain_of_fit_part(std::span<const double> input, std::span<const double> output,
                                const FitRequest& request, const DynamicModel& model) {
  std::optional<double> sample_time = model.sample_time();
  if (const auto it = request.options.find("sample_time");
      !sample_time && it != request.options.end() && it->is_number())
    sample_time = it->get<double>();
  FittedDomain domain;
  if (request.validate_fraction > 0.0 && request.validation_input.empty()) {
    const auto split = split_by_fraction(input.size(), request.validate_fraction);
    domain = fitted_domain(input.subspan(split.fit_begin, split.fit_size()),
                           output.subspan(split.fit_begin, split.fit_size()), sample_time);
  } else {
    domain = fitted_domain(input, output, sample_time);
  }
  domain.largest_time_constant = largest_time_constant(model);
  return domain;
}

}  // namespace

namespace detail {

FittedDomain records_domain(std::span<const FitRecord> records,
                            std::span<const double> sample_times, const DynamicModel& model) {
  std::vector<FittedDomain> parts;
  parts.reserve(records.size());
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto& record = records[r];
    std::optional<double> step =
        sample_times.empty() ? model.sample_time() : std::optional(sample_times[r]);
    if (step) *step /= static_cast<double>(std::max<std::size_t>(record.oversampling, 1));
    auto part = fitted_domain(record.input, record.input, step);
    const auto [low, high] = std::minmax_element(record.output.begin(), record.output.end());
    if (low != record.output.end()) {
      part.output_min = *low;
      part.output_max = *high;
    }
    parts.push_back(part);
  }
  auto domain = merged_domain(parts);
  domain.largest_time_constant = largest_time_constant(model);
  return domain;
}

}  // namespace detail

void require_fit_record_count(std::size_t count) {
  if (count > io::limits::kMaxFitRecords)
    throw Error(fmt::format("{} records, more than the limit of {} records of one fit", count,
                            io::limits::kMaxFitRecords),
                "records");
}

FitOutcome fit_model(const ModelEntry& entry, const FitRequest& request) {
  if (!entry.can_fit()) throw Error(fmt::format("model '{}' has no fitter", entry.name));
  // The record as prepared, or as given when there is nothing to prepare (no copy).
  const bool prepare = request.preprocessing.any();
  data::PreparedRecord prepared;
  if (prepare) prepared = data::preprocess(request.input, request.output, request.preprocessing);
  const std::span<const double> fit_input = prepare ? prepared.input : request.input;
  const std::span<const double> fit_output = prepare ? prepared.output : request.output;
  // The fitter sees the fit record alone (with its held-out fraction); a separate validation
  // record is predicted here, by the one rule every model follows (validation_rule.hpp).
  FitRequest fit_request = request;
  fit_request.input = fit_input;
  fit_request.output = fit_output;
  fit_request.validation_input = {};
  fit_request.validation_output = {};

  // Drift is an artefact of the measurement, so a separate validation record loses its drift
  // too; the choice of cycles and the resampling concern the fit alone. A held-out fraction is
  // the end of the prepared record and so prepared with it.
  std::vector<std::string> steps;
  const bool separate_record = !request.validation_input.empty();
  data::PreparedRecord validation;
  std::span<const double> validation_input = request.validation_input;
  std::span<const double> validation_output = request.validation_output;
  if (separate_record && prepare) {
    validation = data::prepare_validation(request.validation_input, request.validation_output,
                                          request.preprocessing);
    validation_input = validation.input;
    validation_output = validation.output;
    add_steps(steps, "fit record: ", prepared.steps);
    add_steps(steps, "validation record: ", validation.steps);
  } else if (request.validate_fraction > 0.0) {
    add_steps(steps, "fit and held-out validation part: ", prepared.steps);
  } else {
    steps = prepared.steps;
  }
  auto outcome = entry.fit(fit_request);
  outcome.report.preprocessing = std::move(steps);
  const bool fitted = outcome.model && outcome.report.termination != Termination::failed;
  if (separate_record && fitted) {
    outcome.report.validation = validate_on_record(*outcome.model, fit_input, validation_input,
                                                   validation_output, request.validation);
    outcome.report.validation_rule = describe(request.validation);
  } else if (request.validate_fraction > 0.0) {
    outcome.report.validation_rule =
        fmt::format("last {:.4g} % of the record, continued from the end of the fit part",
                    100.0 * request.validate_fraction);
  }
  judge_fit(outcome, {fit_input, fit_output, validation_input, validation_output}, request);
  outcome.report.domain = domain_of_fit_part(fit_input, fit_output, request, *outcome.model);
  return outcome;
}

}  // namespace hyst
