#include "hyst/actuator/control_loop.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
// Accepts the short spelling "pid+ff" too, which the message does not list; the message lists the
// names with commas only ("known: a, b, c"), as it always has.
ControlStrategy control_strategy_from_string(std::string_view text) {
  if (text == "pid+ff") return ControlStrategy::pid_feedforward;
  if (const auto strategy = detail::find_named(text, enum_names<ControlStrategy>)) return *strategy;
  throw Error(fmt::format("unknown control strategy '{}' (known: {})", text,
                          detail::names_list(enum_names<ControlStrategy>, ", ")),
              "strategy");
}

CurrentDrive::CurrentDrive(double resistance, double inductance, double voltage_min,
                           double voltage_max, double period)
    : voltage_min_(voltage_min), voltage_max_(voltage_max) {
  for (auto [value, field] :
       {std::pair{resistance, "model_resistance"}, std::pair{inductance, "model_inductance"},
        std::pair{period, "period"}}) {
    if (!std::isfinite(value) || !(value > 0.0)) {
      throw Error(fmt::format("current drive {} = {} must be finite and > 0", field, value), field);
    }
  }
  if (std::isnan(voltage_min) || std::isnan(voltage_max) || !(voltage_min < voltage_max)) {
    throw Error(fmt::format("current drive voltage_min = {} must be < voltage_max = {}",
                            voltage_min, voltage_max),
                "voltage_min");
  }
  pole_ = std::exp(-resistance * period / inductance);
  gain_ = resistance / -std::expm1(-resistance * period / inductance);
}

void LoopTrace::resize(std::size_t samples) {
  for (auto* signal :
       {&reference, &measured, &position, &current_reference, &current, &force, &voltage}) {
    signal->assign(samples, 0.0);
  }
}

void validate_loop_params(const LoopParams& params) {
  const auto positive = [](double value, const char* field) {
    if (!std::isfinite(value) || !(value > 0.0)) {
      throw Error(fmt::format("control {} = {} must be finite and > 0", field, value), field);
    }
  };
  positive(params.force_gain, "force_gain");
  positive(params.model_stiffness, "model_stiffness");
  positive(params.model_resistance, "model_resistance");
  positive(params.model_inductance, "model_inductance");
  if (std::isnan(params.voltage_min) || std::isnan(params.voltage_max) ||
      !(params.voltage_min < params.voltage_max)) {
    throw Error(fmt::format("control voltage_min = {} must be < voltage_max = {}",
                            params.voltage_min, params.voltage_max),
                "voltage_min");
  }
}

}  // namespace hyst
