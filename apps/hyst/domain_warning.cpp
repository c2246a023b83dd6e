#include "domain_warning.hpp"

#include <fmt/format.h>

#include "commands/commands.hpp"

namespace hyst::cli {

DomainCheck check_record_inputs(const std::optional<FittedDomain>& domain,
                                std::span<const double> input,
                                const std::optional<RecordTime>& time) {
  if (!domain) return {};
  DomainCheck check = check_inputs(*domain, input);
  const auto timing = time ? check_timing(*domain, input, time->axis.sample_time, time->axis.steps)
                           : check_timing(*domain, input, std::nullopt);
  check.excursions.insert(check.excursions.end(), timing.excursions.begin(),
                          timing.excursions.end());
  return check;
}

void report_domain(const DomainCheck& check, std::size_t samples, std::string_view model,
                   std::string_view what, bool strict) {
  if (check.inside()) return;
  const auto message = fmt::format("{}: {}: outside the domain the model was fitted on: {}", model,
                                   what, check.message(samples));
  if (strict) throw Error(message + " (--strict)");
  warn(message);
}

}  // namespace hyst::cli
