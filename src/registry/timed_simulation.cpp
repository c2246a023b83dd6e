#include "hyst/registry/timed_simulation.hpp"

#include <cmath>
#include <cstddef>
#include <optional>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "model_adapter.hpp"

namespace hyst {

namespace detail {

void require_sample_time(std::string_view model, double seconds) {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) {
    throw Error(
        fmt::format("model '{}': the sample time {} s must be finite and > 0", model, seconds),
        "sample_time");
  }
}

void require_own_sample_time(std::string_view model, std::optional<double> own, double seconds) {
  if (!own || data::same_sample_time(*own, seconds)) return;
  throw Error(fmt::format("model '{}' was identified at the sample time {:.6g} s but the record "
                          "is sampled at {:.6g} s: a discrete model holds at its own sample time "
                          "only (resample the record to {:.6g} s, or fit the model at {:.6g} s)",
                          model, *own, seconds, *own, seconds),
              "sample_time");
}

}  // namespace detail

std::string_view time_dependence_name(TimeDependence dependence) {
  switch (dependence) {
    case TimeDependence::none:
      return "rate independent";
    case TimeDependence::continuous:
      return "continuous time";
    case TimeDependence::discrete:
      return "discrete (samples)";
  }
  return "unknown";
}

std::unique_ptr<DynamicModel> at_record_sample_time(std::unique_ptr<DynamicModel> model,
                                                    double seconds) {
  detail::require_sample_time(model->name(), seconds);
  if (model->time_dependence() == TimeDependence::none) return model;
  const std::optional<double> own = model->sample_time();
  // Re-discretising at the same step would only round the decays differently.
  if (own && *own == seconds) return model;
  return model->at_sample_time(seconds);
}

void simulate_on_time_axis(std::unique_ptr<DynamicModel>& model, const data::TimeAxis& axis,
                           std::span<const double> input, std::span<double> output) {
  if (input.size() != output.size()) {
    throw Error(fmt::format("input has {} samples but output has {}", input.size(), output.size()));
  }
  if (axis.uniform() || model->time_dependence() == TimeDependence::none) {
    model = at_record_sample_time(std::move(model), axis.sample_time);
    model->simulate(input, output);
    return;
  }
  if (axis.steps.size() != input.size()) {
    throw Error(fmt::format("the time axis has {} samples but the input has {}", axis.steps.size(),
                            input.size()));
  }
  if (model->time_dependence() == TimeDependence::discrete) {
    std::size_t k = 1;
    while (k < input.size() && data::same_sample_time(axis.steps[k], axis.steps[0]))
      ++k;
    if (k < input.size()) {
      throw Error(fmt::format("model '{}' is discrete (identified in samples) and the record is "
                              "not uniformly sampled: the step before sample {} is {:.6g} s, "
                              "before sample 1 {:.6g} s (resample the record to a uniform time "
                              "grid first)",
                              model->name(), k, axis.steps[k], axis.steps[0]),
                  "time");
    }
  }
  std::size_t begin = 0;
  while (begin < input.size()) {
    const double step = axis.steps[begin];
    std::size_t end = begin + 1;
    while (end < input.size() && data::same_sample_time(axis.steps[end], step))
      ++end;
    model = at_record_sample_time(std::move(model), step);
    model->simulate(input.subspan(begin, end - begin), output.subspan(begin, end - begin));
    begin = end;
  }
}

std::string untimed_record_note(const DynamicModel& model) {
  if (model.time_dependence() == TimeDependence::none) return {};
  const std::optional<double> own = model.sample_time();
  // A discrete model fitted without a time axis (its file states none) counts samples of any
  // spacing, as documented: nothing to say.
  if (!own) return {};
  return fmt::format(
      "the record has no time axis (--time COLUMN or --sample-time SECONDS): it "
      "is taken as sampled at the model's sample time {:.6g} s",
      *own);
}

}  // namespace hyst
