#pragma once
//! \file
//! An actuator with its controller and test scenarios, read from a JSON file:
//!
//!     {"name": "msma_assumed", "description": "...",
//!      "sample_time": 1e-4, "substeps": 1, "delay": 1e-3,
//!      "coil": {"resistance": 2.0, "inductance": 0.015, "current_min": 0, "current_max": 8},
//!      "hysteresis": {"model": "gpi", "params": {...model-file params...}},
//!      "mechanics": {"mass": 0.05, "damping": 40, "stiffness": 7.6e4},
//!      "noise": {"standard_deviation": 0, "seed": 1},                        (optional)
//!      "control": {"force_gain": 9.5, "voltage_min": -48, "voltage_max": 48,
//!                  "model_stiffness": 7.6e4, "model_resistance": 2.0,       (optional: plant's)
//!                  "model_inductance": 0.015,                               (optional: plant's)
//!                  "compensator_hysteresis": {...},                          (optional: plant's)
//!                  "pid": {"kp": ..., "ki": ..., "kd": ..., "derivative_filter": ...,
//!                          "anti_windup": "back_calculation", "tracking_time": ...}},
//!      "scenarios": {"low": 2e-4, "high": 8e-4, "lead_in": 0.05, "step_duration": 0.15,
//!                    "sine_frequencies": [2, 10], "sine_periods": 2,
//!                    "triangle_loops": 4, "triangle_rate": 0.02}}
//!
//! Unknown fields are errors; every message names the source and the field path
//! ("a.json: coil.resistance: coil resistance R = -2 must be finite and > 0").

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "hyst/actuator/actuator.hpp"
#include "hyst/actuator/control_loop.hpp"
#include "hyst/actuator/hysteretic_force.hpp"

namespace hyst {

//! The standard references of a comparison, in position units [m].
struct ScenarioParams {
  double low = 0.0;            //!< lower position of steps, sines and triangles
  double high = 1.0;           //!< upper position, > low
  double lead_in = 0.05;       //!< [s] hold of the first value before every reference (not scored)
  double step_duration = 0.1;  //!< [s] step from low to high at t = 0
  std::vector<double> sine_frequencies{1.0};  //!< [Hz], each at full and half amplitude
  double sine_periods = 2.0;                  //!< periods per sine
  std::size_t triangle_loops = 4;             //!< internal reversals of the triangle
  double triangle_rate = 1.0;                 //!< [m/s]
};

struct ActuatorConfig {
  std::string name;
  std::string description;
  ActuatorParams plant;
  AnyHysteresis hysteresis;
  AnyHysteresis compensator_hysteresis;  //!< the controller's model (same kind as hysteresis)
  LoopParams loop;
  ScenarioParams scenarios;
};

//! Parses and validates (every block is built once); `source` prefixes messages.
ActuatorConfig actuator_config_from_json(const nlohmann::json& document, std::string_view source);
//! Reads a config file; hyst::Error names the file, and the line and column for bad JSON.
ActuatorConfig load_actuator_config(const std::filesystem::path& path);

}  // namespace hyst
