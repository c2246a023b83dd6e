#include "domain_warning.hpp"

#include <fmt/format.h>

#include "commands/commands.hpp"

namespace hyst::cli {

DomainCheck check_record_inputs(const std::optional<FittedDomain>& domain,
                                std::span<const double> input,
                                const std::optional<RecordTime>& time) {
  if (!domain) return {};
  if (!time) return hyst::check_record_inputs(*domain, input, std::nullopt);
  return hyst::check_record_inputs(*domain, input, time->axis.sample_time, time->axis.steps);
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
