#include "hyst/models/butterfly_strain.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "detail/parameter_rules.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

constexpr std::string_view kButterfly = "butterfly strain model";

Preisach polarisation_of(const ButterflyStrain::Params& p) {
  try {
    return Preisach(p.polarisation);
  } catch (const Error& error) {
    throw Error(fmt::format("{} polarisation: {}", kButterfly, error.what()), error.field());
  }
}

void validate_map(const ButterflyStrain::Params& p) {
  const detail::ParameterRules rules{kButterfly};
  rules.finite(p.field_coefficient, "field coefficient d", "field_coefficient");
  rules.finite(p.offset, "offset", "offset");
  const auto& q = p.polarisation_coefficients;
  rules.count_in(q.size(), 1, 16, "polarisation coefficients q_n", "polarisation_coefficients");
  for (std::size_t n = 0; n < q.size(); ++n) {
    rules.finite(q[n], fmt::format("polarisation coefficient q_{}", n + 1),
                 fmt::format("polarisation_coefficients[{}]", n));
  }
}

}  // namespace

ButterflyStrain::ButterflyStrain(Params params)
    : params_(std::move(params)), polarisation_(polarisation_of(params_)) {
  validate_map(params_);
}

ButterflyStrain::State ButterflyStrain::periodic_state(std::span<const double> period) const {
  if (period.empty()) throw Error(fmt::format("{}: the period has no samples", kButterfly));
  State state = initial_state();
  for (std::size_t k = 0; k < period.size(); ++k) {
    if (!std::isfinite(period[k])) {
      throw Error(fmt::format("{}: period[{}] = {} is not finite", kButterfly, k, period[k]),
                  "input");
    }
    polarisation_.step(state, period[k]);
  }
  return state;
}

}  // namespace hyst
