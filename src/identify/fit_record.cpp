#include "hyst/identify/fit_record.hpp"

#include <string>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

void check_fit_record(const FitRecord& record, std::string_view name, const FitRecordRules& rules) {
  const std::string input_name = fmt::format("{} input", name);
  const std::string output_name = fmt::format("{} output", name);
  if (record.oversampling < 1) {
    throw Error(fmt::format("{}: oversampling must be >= 1", name), "oversampling");
  }
  if (record.oversampling > 1 && !rules.oversampling) {
    throw Error(fmt::format("{}: oversampling = {}: this fit compares every input sample (1 only)",
                            name, record.oversampling),
                "oversampling");
  }
  if (record.skip > 0 && !rules.skip) {
    throw Error(
        fmt::format("{}: skip = {}: this fit compares every sample (0 only)", name, record.skip),
        "skip");
  }
  if (record.oversampling == 1) {
    require_same_size(record.input.size(), input_name, record.output.size(), output_name);
  } else {
    require_same_size(record.input.size(), input_name, record.output.size() * record.oversampling,
                      fmt::format("{} x oversampling {}", output_name, record.oversampling));
  }
  require_not_empty(record.input.size(), input_name);
  require_finite(record.input, input_name);
  require_finite(record.output, output_name);
  if (record.skip + rules.min_samples > record.output.size()) {
    throw Error(fmt::format("{}: {} output samples{} leave fewer than the {} this fit needs", name,
                            record.output.size(),
                            record.skip > 0 ? fmt::format(" after skip = {}", record.skip) : "",
                            rules.min_samples),
                record.skip > 0 ? "skip" : "output");
  }
}

}  // namespace hyst
