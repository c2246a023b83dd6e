#pragma once
//! \file
//! Running a saved model on a record with its own time axis. A model whose output depends on time
//! stores its sample time in seconds; on a record sampled at another step it is re-discretised
//! (continuous-time dynamics) or refused naming both sample times (discrete models such as the
//! NARX); a rate-independent model ignores time by design. A non-uniform record is stepped in
//! runs of equal steps, each at its own step, where the model allows it.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "hyst/core/enum_names.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst {

//! The names of model files and Python: "none", "continuous", "discrete".
constexpr EnumNames<TimeDependence, 3> enumerator_names(TimeDependence) {
  return {{
      {TimeDependence::none, "none"},
      {TimeDependence::continuous, "continuous"},
      {TimeDependence::discrete, "discrete"},
  }};
}

//! "rate independent", "continuous time" or "discrete (samples)", for people.
std::string_view time_dependence_name(TimeDependence dependence);

//! `model` at the sample time `seconds` of a record: the model itself (moved through) when it
//! ignores time or already has that sample time, else model.at_sample_time(seconds) with the
//! same state. hyst::Error for a discrete model at another sample time.
std::unique_ptr<DynamicModel> at_record_sample_time(std::unique_ptr<DynamicModel> model,
                                                    double seconds);

//! Runs `model` over `input`, sampled on `axis`, from its current state, as model.simulate()
//! does. The model is replaced by the one at the record's sample time (at_record_sample_time());
//! on a non-uniform axis each run of steps within 0.1 % of its first is stepped at that step, and
//! `model` ends at the last run's. Throws hyst::Error for a discrete model on another or a
//! non-uniform time axis (naming the first step that differs), mismatched lengths, or what
//! simulate() throws.
void simulate_on_time_axis(std::unique_ptr<DynamicModel>& model, const data::TimeAxis& axis,
                           std::span<const double> input, std::span<double> output);

//! One line for people when `model` depends on time but a record has no time axis: it is then
//! taken as sampled at the model's own sample time. Empty for a rate-independent model and for a
//! discrete one without a stated sample time (it counts samples of any spacing).
std::string untimed_record_note(const DynamicModel& model);

}  // namespace hyst
