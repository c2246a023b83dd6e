#pragma once
// The commands' word on a record that leaves the domain its model was fitted on (the model
// file's info.domain, identify/fitted_domain.hpp): one warning line, or the error with --strict.

#include <cstddef>
#include <string>
#include <string_view>

#include "hyst/identify/fitted_domain.hpp"

namespace hyst::cli {

//! Nothing when `check` is inside; else "hyst: warning: <model>: <what>: outside the domain the
//! model was fitted on: ..." (hyst::Error with that text and " (--strict)" when `strict`).
void report_domain(const DomainCheck& check, std::size_t samples, std::string_view model,
                   std::string_view what, bool strict);

}  // namespace hyst::cli
