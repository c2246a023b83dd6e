#pragma once
//! \file
//! A hysteretic electromagnetic actuator, the composition of the blocks
//!
//!     u [V] -> Coil -> i [A] -> H (hysteresis) -> F [N] -> Mechanics -> x [m]
//!           -> TransportDelay (T) -> SensorNoise -> measured position y [m]
//!
//! One step() is one sample period h, held voltage. Inside it, `substeps` sub-periods each
//! (1) update the current by the coil's exact zero-order hold, (2) evaluate F = H[i]
//! (rate independent, exact at the sub-samples), (3) update the mechanics by their exact zero-order
//! hold with F held. The error of holding F is O(h / substeps) (reference actuator_msma.md
//! section 3: use h <= tau_e/50 or sub-steps). The delay sits on the measured output (sensor and
//! processing latency), which leaves the linearised transfer function unchanged.
//! H is any model with State, initial_state(), output(State) and a noexcept step(); the
//! generalized Prandtl-Ishlinskii model with tanh envelopes by default.
//! Source: Minorowicz & Milecki (2022), Materials 15:4400, section 4.3 and Fig. 11.

#include <cstddef>

#include "hyst/actuator/coil.hpp"
#include "hyst/actuator/mechanics.hpp"
#include "hyst/actuator/sensor_noise.hpp"
#include "hyst/actuator/transport_delay.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"

namespace hyst {

//! Parameters of every linear block of an actuator, with the sample period.
struct ActuatorParams {
  double sample_time = 1e-4;  //!< h [s], > 0
  std::size_t substeps = 1;   //!< sub-periods per sample, 1..1000
  Coil::Params coil{};
  Mechanics::Params mechanics{};
  double delay = 0.0;  //!< T [s], >= 0
  SensorNoise::Params noise{};
};

//! What one actuator sample produced.
struct ActuatorSample {
  double current = 0.0;   //!< i [A] at the end of the period
  double force = 0.0;     //!< F [N]
  double position = 0.0;  //!< x [m], undelayed
  double measured = 0.0;  //!< y [m]: delayed, with noise
};

//! Checks sample_time and substeps (hyst::Error naming the field); the blocks check the rest.
void validate_actuator_timing(const ActuatorParams& params);

template <class H = GeneralizedPrandtlIshlinskii<>>
class Actuator {
 public:
  using Hysteresis = H;
  struct State {
    Coil::State coil;
    typename H::State hysteresis;
    Mechanics::State mechanics;
    TransportDelay::State delay;
    SensorNoise::State noise;
  };

  //! Validates every block; throws hyst::Error naming the field.
  Actuator(H hysteresis, const ActuatorParams& params)
      : params_(checked(params)),
        coil_(params.coil, sub_period(params)),
        hysteresis_(std::move(hysteresis)),
        mechanics_(params.mechanics, sub_period(params)),
        delay_(params.delay, params.sample_time),
        noise_(params.noise) {}

  const ActuatorParams& params() const { return params_; }
  const Coil& coil() const { return coil_; }
  const H& hysteresis() const { return hysteresis_; }
  const Mechanics& mechanics() const { return mechanics_; }
  const TransportDelay& delay() const { return delay_; }
  const SensorNoise& noise() const { return noise_; }

  //! At rest: the coil at its initial current, the hysteresis in its initial state, the mass at
  //! rest under that state's force, the delay line filled with that position.
  State initial_state() const {
    State state{coil_.initial_state(), hysteresis_.initial_state(), {}, {}, noise_.initial_state()};
    state.mechanics = mechanics_.state_at_rest(hysteresis_.output(state.hysteresis));
    state.delay = delay_.initial_state(state.mechanics.position);
    return state;
  }

  //! One sample period with the coil voltage held. No allocation, no virtual call.
  ActuatorSample step(State& state, double voltage) const noexcept {
    ActuatorSample sample;
    for (std::size_t s = 0; s < params_.substeps; ++s) {
      sample.current = coil_.step(state.coil, voltage);
      sample.force = hysteresis_.step(state.hysteresis, sample.current);
      sample.position = mechanics_.step(state.mechanics, sample.force);
    }
    sample.measured = noise_.step(state.noise, delay_.step(state.delay, sample.position));
    return sample;
  }

 private:
  static const ActuatorParams& checked(const ActuatorParams& params) {
    validate_actuator_timing(params);
    return params;
  }
  static double sub_period(const ActuatorParams& params) {
    return params.sample_time / static_cast<double>(params.substeps);
  }

  ActuatorParams params_;
  Coil coil_;
  H hysteresis_;
  Mechanics mechanics_;
  TransportDelay delay_;
  SensorNoise noise_;
};

}  // namespace hyst
