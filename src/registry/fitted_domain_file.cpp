#include "hyst/registry/fitted_domain_file.hpp"

#include <fmt/format.h>

#include "../detail/json_fields.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/json_text.hpp"

namespace hyst {

nlohmann::json fitted_domain_json(const FittedDomain& domain) {
  nlohmann::json json = {{"input_min", domain.input_min},
                         {"input_max", domain.input_max},
                         {"output_min", domain.output_min},
                         {"output_max", domain.output_max},
                         {"samples", domain.samples},
                         {"largest_input_step", domain.largest_input_step},
                         {"longest_hold_samples", domain.longest_hold_samples}};
  if (domain.sample_time) {
    json["sample_time"] = *domain.sample_time;
    json["duration"] = *domain.duration();
    json["largest_input_rate"] = *domain.largest_input_rate();
    json["longest_hold"] = *domain.longest_hold();
  }
  if (domain.largest_time_constant) json["largest_time_constant"] = *domain.largest_time_constant;
  return json;
}

std::optional<FittedDomain> fitted_domain_of(const nlohmann::json& document,
                                             std::string_view source) {
  if (!document.is_object() || !document.contains("info") || !document.at("info").is_object() ||
      !document.at("info").contains("domain"))
    return std::nullopt;
  try {
    detail::JsonFields fields(document.at("info").at("domain"), "info.domain");
    FittedDomain domain;
    domain.input_min = fields.number("input_min");
    domain.input_max = fields.number("input_max");
    domain.output_min = fields.number("output_min");
    domain.output_max = fields.number("output_max");
    domain.samples = fields.count("samples");
    domain.largest_input_step = fields.number("largest_input_step");
    domain.longest_hold_samples = fields.count("longest_hold_samples");
    if (fields.has("sample_time")) domain.sample_time = fields.number("sample_time");
    if (fields.has("largest_time_constant"))
      domain.largest_time_constant = fields.number("largest_time_constant");
    // Derived from the fields above, written for people and scripts.
    for (const char* derived : {"duration", "largest_input_rate", "longest_hold"})
      if (fields.has(derived)) static_cast<void>(fields.number(derived));
    fields.finish();
    if (!(domain.input_min <= domain.input_max) || !(domain.output_min <= domain.output_max))
      throw Error("info.domain: a minimum above its maximum");
    return domain;
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", source, error.what()));
  }
}

std::optional<FittedDomain> load_fitted_domain(const std::filesystem::path& path) {
  return fitted_domain_of(io::parse_json_text(io::read_file(path), path.string()), path.string());
}

}  // namespace hyst
