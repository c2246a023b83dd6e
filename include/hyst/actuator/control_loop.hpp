#pragma once
//! \file
//! Position control of a hysteretic actuator, in the four configurations compared in the
//! literature (Minorowicz & Milecki 2022, section 4.3; reference actuator_msma.md sections 4-5):
//!
//!     open_loop        i_ref = i_ff                              no compensation
//!     feedforward      i_ref = H^-1[k_F i_ff]                    inverse model alone
//!     pid              i_ref = PID(r, y)                         feedback alone
//!     pid_feedforward  i_ref = H^-1[k_F PID(r, y, i_ff)]         feedback through the inverse
//!
//! with the static reference feedforward i_ff = k r / k_F (the current whose compensated force
//! holds the spring at r). The coil is driven by a current-controlled voltage amplifier
//! (CurrentDrive): the hysteresis sits between current and force, so the inverse's output is a
//! current reference that the drive must realise faster than the mechanics move (reference
//! actuator_msma.md section 4, option a). The PID output is the virtual current i_d [A] limited
//! to the current range; its anti-windup sees those limits. k, R, L and k_F here are the
//! controller's model values, which may differ from the plant's (model mismatch).

#include <algorithm>
#include <span>
#include <string_view>
#include <vector>

#include "hyst/actuator/actuator.hpp"
#include "hyst/actuator/force_compensator.hpp"
#include "hyst/control/pid.hpp"
#include "hyst/core/enum_names.hpp"

namespace hyst {

enum class ControlStrategy : unsigned char { open_loop, feedforward, pid, pid_feedforward };
inline constexpr ControlStrategy kControlStrategies[] = {
    ControlStrategy::open_loop, ControlStrategy::feedforward, ControlStrategy::pid,
    ControlStrategy::pid_feedforward};
constexpr EnumNames<ControlStrategy, 4> enumerator_names(ControlStrategy) {
  return {{
      {ControlStrategy::open_loop, "open_loop"},
      {ControlStrategy::feedforward, "feedforward"},
      {ControlStrategy::pid, "pid"},
      {ControlStrategy::pid_feedforward, "pid_feedforward"},
  }};
}
//! The inverse of to_string(); also accepts "pid+ff". hyst::Error for other text.
ControlStrategy control_strategy_from_string(std::string_view text);

//! Deadbeat current control of the coil through a voltage amplifier, designed on the coil model
//! (R, L) sampled at h: u[k] = sat(R (i_ref[k] - a i[k]) / (1 - a), u_min, u_max) with
//! a = exp(-R h/L), so that i[k+1] = i_ref[k] whenever the voltage does not saturate and the
//! model is right. i[k] is the measured coil current.
class CurrentDrive {
 public:
  //! hyst::Error for R, L, h not finite and > 0 or u_min >= u_max.
  CurrentDrive(double resistance, double inductance, double voltage_min, double voltage_max,
               double period);
  double voltage(double current_reference, double current) const noexcept {
    return std::clamp(gain_ * (current_reference - pole_ * current), voltage_min_, voltage_max_);
  }

 private:
  double pole_;
  double gain_;
  double voltage_min_;
  double voltage_max_;
};

//! The controller's side of the loop (model values, drive, PID).
struct LoopParams {
  double force_gain = 1.0;        //!< k_F [N/A] of the compensated law, > 0
  double model_stiffness = 1.0;   //!< k [N/m] for i_ff, > 0
  double model_resistance = 1.0;  //!< R [Ohm] of the current drive, > 0
  double model_inductance = 1.0;  //!< L [H] of the current drive, > 0
  double voltage_min = -1e300;    //!< supply limits [V]
  double voltage_max = 1e300;
  control::Pid::Params pid{};  //!< output limits are replaced by the current range
};

//! One run: every signal at every sample.
struct LoopTrace {
  std::vector<double> reference;          //!< r [m]
  std::vector<double> measured;           //!< y [m]
  std::vector<double> position;           //!< x [m] (undelayed, no noise)
  std::vector<double> current_reference;  //!< i_ref [A]
  std::vector<double> current;            //!< i [A]
  std::vector<double> force;              //!< F [N]
  std::vector<double> voltage;            //!< u [V]
  void resize(std::size_t samples);
};

//! hyst::Error naming the field for invalid k_F, k, R, voltage limits.
void validate_loop_params(const LoopParams& params);

template <class H>
class ControlLoop {
 public:
  struct State {
    typename Actuator<H>::State plant;
    typename InverseCompensator<H>::State compensator;
    control::Pid::State pid;
    double measured = 0.0;  //!< y[k-1], what the controller sees
    double current = 0.0;   //!< i[k-1], what the current drive sees
  };

  ControlLoop(Actuator<H> plant, const H& model, const LoopParams& params)
      : plant_(std::move(plant)),
        params_(checked(params)),
        compensator_(model, {params.force_gain, plant_.params().coil.current_min,
                             plant_.params().coil.current_max}),
        pid_(pid_params(params, plant_.params()), plant_.params().sample_time),
        drive_(params.model_resistance, params.model_inductance, params.voltage_min,
               params.voltage_max, plant_.params().sample_time) {}

  const Actuator<H>& plant() const { return plant_; }
  const InverseCompensator<H>& compensator() const { return compensator_; }
  const control::Pid& pid() const { return pid_; }
  const LoopParams& params() const { return params_; }

  State initial_state() const {
    State state{plant_.initial_state(), compensator_.initial_state(), pid_.initial_state()};
    state.measured = state.plant.delay.buffer.front();  // the position at rest
    state.current = state.plant.coil.current;
    return state;
  }

  //! One sample: controller on the last measurement, then the plant. No allocation.
  ActuatorSample step(State& state, ControlStrategy strategy, double reference,
                      double& current_reference, double& voltage) const noexcept {
    const double feedforward = reference * params_.model_stiffness / params_.force_gain;
    switch (strategy) {
      case ControlStrategy::open_loop:
        current_reference = feedforward;
        break;
      case ControlStrategy::feedforward:
        current_reference = compensator_.step(state.compensator, feedforward);
        break;
      case ControlStrategy::pid:
        current_reference = pid_.step(state.pid, reference, state.measured);
        break;
      case ControlStrategy::pid_feedforward:
        current_reference = compensator_.step(
            state.compensator, pid_.step(state.pid, reference, state.measured, feedforward));
        break;
    }
    voltage = drive_.voltage(current_reference, state.current);
    const ActuatorSample sample = plant_.step(state.plant, voltage);
    state.measured = sample.measured;
    state.current = sample.current;
    return sample;
  }

  //! The whole reference from `state`; `trace` is resized once, the loop does not allocate.
  void run(State& state, ControlStrategy strategy, std::span<const double> reference,
           LoopTrace& trace) const {
    trace.resize(reference.size());
    for (std::size_t k = 0; k < reference.size(); ++k) {
      trace.reference[k] = reference[k];
      const ActuatorSample sample =
          step(state, strategy, reference[k], trace.current_reference[k], trace.voltage[k]);
      trace.measured[k] = sample.measured;
      trace.position[k] = sample.position;
      trace.current[k] = sample.current;
      trace.force[k] = sample.force;
    }
  }

 private:
  static const LoopParams& checked(const LoopParams& params) {
    validate_loop_params(params);
    return params;
  }
  static control::Pid::Params pid_params(const LoopParams& params, const ActuatorParams& plant) {
    auto pid = params.pid;
    pid.output_min = plant.coil.current_min;
    pid.output_max = plant.coil.current_max;
    return pid;
  }

  Actuator<H> plant_;
  LoopParams params_;
  InverseCompensator<H> compensator_;
  control::Pid pid_;
  CurrentDrive drive_;
};

}  // namespace hyst
