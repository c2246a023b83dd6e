#include "hyst/actuator/transport_delay.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

TransportDelay::TransportDelay(double delay, double period) : delay_(delay), period_(period) {
  if (!std::isfinite(period) || !(period > 0.0)) {
    throw Error(fmt::format("delay sample period h = {} must be finite and > 0", period), "period");
  }
  if (!std::isfinite(delay) || delay < 0.0) {
    throw Error(fmt::format("transport delay T = {} must be finite and >= 0", delay), "delay");
  }
  const double samples = delay / period;
  if (samples > 1e7) {
    throw Error(fmt::format("transport delay T = {} is {} samples of h = {}, more than 1e7", delay,
                            samples, period),
                "delay");
  }
  const double nearest = std::round(samples);
  if (std::abs(samples - nearest) <= 1e-9 * std::max(1.0, samples)) {
    whole_ = static_cast<std::size_t>(nearest);
    fraction_ = 0.0;
  } else {
    whole_ = static_cast<std::size_t>(std::floor(samples));
    fraction_ = samples - static_cast<double>(whole_);
  }
}

TransportDelay::State TransportDelay::initial_state(double initial) const {
  return {std::vector<double>(whole_ + 2, initial), 0};
}

}  // namespace hyst
