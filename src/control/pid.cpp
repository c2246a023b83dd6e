#include "hyst/control/pid.hpp"

#include <cmath>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/error.hpp"

namespace hyst::control {
namespace {

void require_gain(double value, const char* field) {
  if (!std::isfinite(value) || value < 0.0) {
    throw Error(fmt::format("PID {} = {} must be finite and >= 0", field, value), field);
  }
}

}  // namespace

// Its message lists the names with commas only ("known: a, b, c"), as it always has.
AntiWindup anti_windup_from_string(std::string_view text) {
  if (const auto mode = hyst::detail::find_named(text, enum_names<AntiWindup>)) return *mode;
  throw Error(fmt::format("unknown anti-windup '{}' (known: {})", text,
                          hyst::detail::names_list(enum_names<AntiWindup>, ", ")),
              "anti_windup");
}

Pid::Pid(const Params& params, double period) : params_(params), period_(period) {
  require_gain(params.kp, "kp");
  require_gain(params.ki, "ki");
  require_gain(params.kd, "kd");
  require_gain(params.derivative_filter, "derivative_filter");
  if (!std::isfinite(period) || !(period > 0.0)) {
    throw Error(fmt::format("PID period h = {} must be finite and > 0", period), "period");
  }
  if (std::isnan(params.output_min) || std::isnan(params.output_max) ||
      !(params.output_min < params.output_max)) {
    throw Error(fmt::format("PID output_min = {} must be < output_max = {}", params.output_min,
                            params.output_max),
                "output_min");
  }
  if (std::isnan(params.tracking_time)) {
    if (params.kp > 0.0 && params.ki > 0.0) {
      const double ti = params.kp / params.ki;
      tracking_time_ = params.kd > 0.0 ? std::sqrt(ti * params.kd / params.kp) : ti;
    } else {
      tracking_time_ = period;
    }
  } else if (!std::isfinite(params.tracking_time) || !(params.tracking_time > 0.0)) {
    throw Error(fmt::format("PID tracking_time = {} must be finite and > 0 (or not set)",
                            params.tracking_time),
                "tracking_time");
  } else {
    tracking_time_ = params.tracking_time;
  }
  derivative_memory_ = params.derivative_filter / (params.derivative_filter + period);
  derivative_gain_ = params.kd / (params.derivative_filter + period);
}

Pid::State Pid::start(double output, double reference, double measurement,
                      double feedforward) const {
  State state;
  state.previous_measurement = measurement;
  state.started = true;
  const double held = std::clamp(output, params_.output_min, params_.output_max);
  state.integral = held - params_.kp * (reference - measurement) - feedforward;
  return state;
}

}  // namespace hyst::control
