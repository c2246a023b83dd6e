#include "hyst/models/envelopes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

std::string field(const EnvelopeLabel& label, std::size_t index) {
  return fmt::format("{}[{}]", label.curve, index);
}

// Size and finiteness, common to every kind.
void validate_common(std::span<const double> c, std::size_t expected, EnvelopeKind kind,
                     const EnvelopeLabel& label) {
  if (c.size() != expected) {
    throw Error(fmt::format("{} {} envelope has {} coefficients but a {} envelope needs {} "
                            "({}0..{}{})",
                            label.model, label.curve, c.size(), to_string(kind), expected,
                            label.letter, label.letter, expected - 1),
                std::string(label.curve));
  }
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!std::isfinite(c[i])) {
      throw Error(fmt::format("{} {} envelope ({}) coefficient {}{} = {} is not finite",
                              label.model, label.curve, to_string(kind), label.letter, i, c[i]),
                  field(label, i));
    }
  }
}

// c0 c1 > 0: a strictly increasing saturating envelope.
void validate_slope(std::span<const double> c, EnvelopeKind kind, const EnvelopeLabel& label) {
  if (c[0] == 0.0) {
    throw Error(fmt::format("{} {} envelope ({}) coefficient {}0 = 0 must be nonzero (it is the "
                            "half-range of the envelope; convention {}0 > 0)",
                            label.model, label.curve, to_string(kind), label.letter, label.letter),
                field(label, 0));
  }
  if (!(c[0] * c[1] > 0.0)) {
    throw Error(fmt::format("{} {} envelope ({}) coefficient {}1 = {} must have the sign of {}0 = "
                            "{}: {}0 {}1 > 0 makes the envelope strictly increasing",
                            label.model, label.curve, to_string(kind), label.letter, c[1],
                            label.letter, c[0], label.letter, label.letter),
                field(label, 1));
  }
}

}  // namespace

EnvelopeKind envelope_kind_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<EnvelopeKind>, "envelope", "envelope");
}

void LinearEnvelope::validate(std::span<const double> c, const EnvelopeLabel& label) {
  validate_common(c, coefficient_count, kind, label);
  if (!(c[0] > 0.0)) {
    throw Error(fmt::format("{} {} envelope (linear) slope {}0 = {} must be > 0 (strictly "
                            "increasing envelope)",
                            label.model, label.curve, label.letter, c[0]),
                field(label, 0));
  }
}

void TanhEnvelope::validate(std::span<const double> c, const EnvelopeLabel& label) {
  validate_common(c, coefficient_count, kind, label);
  validate_slope(c, kind, label);
}

void ArctanEnvelope::validate(std::span<const double> c, const EnvelopeLabel& label) {
  validate_common(c, coefficient_count, kind, label);
  validate_slope(c, kind, label);
}

template <Envelope E>
void check_envelope_ordering(const double* ascending, const double* descending, double input_min,
                             double input_max, std::string_view model) {
  if (!std::isfinite(input_min)) {
    throw Error(fmt::format("{} operating range input_min = {} is not finite (the envelope "
                            "ordering gamma_l <= gamma_r is checked on [input_min, input_max])",
                            model, input_min),
                "input_min");
  }
  if (!std::isfinite(input_max)) {
    throw Error(fmt::format("{} operating range input_max = {} is not finite (the envelope "
                            "ordering gamma_l <= gamma_r is checked on [input_min, input_max])",
                            model, input_max),
                "input_max");
  }
  if (!(input_min < input_max)) {
    throw Error(fmt::format("{} operating range input_min = {} must be < input_max = {}", model,
                            input_min, input_max),
                "input_max");
  }
  constexpr std::size_t intervals = kEnvelopeOrderingGrid - 1;
  for (std::size_t k = 0; k <= intervals; ++k) {
    const double v = k == intervals ? input_max
                                    : input_min + (input_max - input_min) * static_cast<double>(k) /
                                                      static_cast<double>(intervals);
    const double lower = E::value(ascending, v);
    const double upper = E::value(descending, v);
    const double slack = 1e-12 * std::max({1.0, std::abs(lower), std::abs(upper)});
    if (!(lower <= upper + slack)) {
      throw Error(fmt::format("{} envelopes violate the ordering gamma_l(v) <= gamma_r(v) at v = "
                              "{}: gamma_l = {} > gamma_r = {}; the ascending envelope must not "
                              "lie above the descending one on the operating range [{}, {}] "
                              "(swapped envelopes?)",
                              model, v, lower, upper, input_min, input_max),
                  "descending");
    }
  }
}

template void check_envelope_ordering<LinearEnvelope>(const double*, const double*, double, double,
                                                      std::string_view);
template void check_envelope_ordering<TanhEnvelope>(const double*, const double*, double, double,
                                                    std::string_view);
template void check_envelope_ordering<ArctanEnvelope>(const double*, const double*, double, double,
                                                      std::string_view);

}  // namespace hyst
