#pragma once
// Validation of scalar model parameters with messages that name the model, the parameter (its
// symbol and its field) and the rule, e.g. "Bouc-Wen oscillator mass m = 0 must be > 0".

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::detail {

struct ParameterRules {
  std::string_view model;  // e.g. "Bouc-Wen oscillator"

  [[noreturn]] void fail(std::string_view label, std::string_view field, double value,
                         std::string_view rule) const {
    throw Error(fmt::format("{} {} = {} {}", model, label, value, rule), std::string(field));
  }
  void finite(double value, std::string_view label, std::string_view field) const {
    if (!std::isfinite(value)) fail(label, field, value, "is not finite");
  }
  void greater(double value, double bound, std::string_view label, std::string_view field) const {
    finite(value, label, field);
    if (!(value > bound)) fail(label, field, value, fmt::format("must be > {}", bound));
  }
  void at_least(double value, double bound, std::string_view label, std::string_view field) const {
    finite(value, label, field);
    if (!(value >= bound)) fail(label, field, value, fmt::format("must be >= {}", bound));
  }
  void below(double value, double bound, std::string_view label, std::string_view field) const {
    finite(value, label, field);
    if (!(value < bound)) fail(label, field, value, fmt::format("must be < {}", bound));
  }
  void count_in(std::size_t value, std::size_t low, std::size_t high, std::string_view label,
                std::string_view field) const {
    if (value < low || value > high) {
      throw Error(fmt::format("{} {} = {} must be in [{}, {}]", model, label, value, low, high),
                  std::string(field));
    }
  }
  //! The `tolerance` option of the adaptive integration: 0 (off) or in [1e-14, 1] (below, rounding
  //! errors exceed it and the step-size controller cannot meet it).
  void integration_tolerance(double value) const {
    at_least(value, 0.0, "tolerance", "tolerance");
    if (value != 0.0 && (value < 1e-14 || value > 1.0)) {
      fail("tolerance", "tolerance", value, "must be 0 (fixed RK4 sub-steps) or in [1e-14, 1]");
    }
  }
  //! A part of a composite model built from its parameters; its error is prefixed with the part's
  //! name: "modified PI pi: ...", field "pi.weights[0]".
  template <class Part>
  Part part(typename Part::Params params, std::string_view prefix) const {
    try {
      return Part(std::move(params));
    } catch (const Error& error) {
      throw Error(fmt::format("{} {}: {}", model, prefix, error.what()),
                  fmt::format("{}.{}", prefix, error.field()));
    }
  }
  //! Output limits low < high (either may be infinite: no limit on that side).
  void output_limits(double low, double high) const {
    if (!(low < high)) {
      throw Error(fmt::format("{} output_min = {} must be < output_max = {}", model, low, high),
                  "output_min");
    }
  }
};

}  // namespace hyst::detail
