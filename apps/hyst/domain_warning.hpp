#pragma once
// The commands' word on a record that leaves the domain its model was fitted on (the model
// file's info.domain, identify/fitted_domain.hpp): one warning line, or the error with --strict.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "hyst/identify/fitted_domain.hpp"
#include "record_time.hpp"

namespace hyst::cli {

//! The inputs of a record (check_inputs()) and their rates and holds at the record's time axis
//! (check_timing(); the model's own sample time without one); nothing without a domain.
DomainCheck check_record_inputs(const std::optional<FittedDomain>& domain,
                                std::span<const double> input,
                                const std::optional<RecordTime>& time);

//! Nothing when `check` is inside; else "hyst: warning: <model>: <what>: outside the domain the
//! model was fitted on: ..." (hyst::Error with that text and " (--strict)" when `strict`).
void report_domain(const DomainCheck& check, std::size_t samples, std::string_view model,
                   std::string_view what, bool strict);

}  // namespace hyst::cli
