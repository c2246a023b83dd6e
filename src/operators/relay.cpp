#include "hyst/operators/relay.hpp"

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {

Relay::Relay(double alpha, double beta) : alpha_(alpha), beta_(beta) {
  require_finite(alpha, "relay alpha");
  require_finite(beta, "relay beta");
  if (alpha < beta) {
    throw Error(fmt::format("relay thresholds alpha = {} and beta = {} must satisfy alpha >= beta",
                            alpha, beta));
  }
}

Relay::State Relay::make_state(double output) const {
  if (output != 1.0 && output != -1.0) {
    throw Error(fmt::format("relay state = {} must be -1 or +1", output));
  }
  return State{output};
}

}  // namespace hyst
