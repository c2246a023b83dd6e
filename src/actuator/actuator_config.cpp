#include "hyst/actuator/actuator_config.hpp"

#include <optional>
#include <variant>

#include <fmt/format.h>

#include "../detail/json_fields.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/io/limits.hpp"

namespace hyst {
namespace {

using detail::JsonFields;

Coil::Params coil_from_json(const nlohmann::json& value) {
  JsonFields fields(value, "coil");
  Coil::Params coil;
  coil.resistance = fields.number("resistance");
  coil.inductance = fields.number("inductance");
  coil.current_min = fields.number("current_min");
  coil.current_max = fields.number("current_max");
  coil.initial_current = fields.number_or("initial_current", coil.current_min);
  fields.finish();
  return coil;
}

Mechanics::Params mechanics_from_json(const nlohmann::json& value) {
  JsonFields fields(value, "mechanics");
  Mechanics::Params mechanics;
  mechanics.mass = fields.number("mass");
  mechanics.damping = fields.number("damping");
  mechanics.stiffness = fields.number("stiffness");
  fields.finish();
  return mechanics;
}

SensorNoise::Params noise_from_json(const nlohmann::json& value) {
  JsonFields fields(value, "noise");
  SensorNoise::Params noise;
  noise.standard_deviation = fields.number("standard_deviation");
  noise.seed = fields.count_or("seed", 1);
  fields.finish();
  return noise;
}

control::Pid::Params pid_from_json(const nlohmann::json& value) {
  JsonFields fields(value, "control.pid");
  control::Pid::Params pid;
  pid.kp = fields.number_or("kp", 0.0);
  pid.ki = fields.number_or("ki", 0.0);
  pid.kd = fields.number_or("kd", 0.0);
  pid.derivative_filter = fields.number_or("derivative_filter", 0.0);
  if (fields.has("anti_windup")) {
    pid.anti_windup = fields.parsed("anti_windup", control::anti_windup_from_string);
  }
  if (fields.has("tracking_time")) pid.tracking_time = fields.number("tracking_time");
  fields.finish();
  return pid;
}

ScenarioParams scenarios_from_json(const nlohmann::json& value) {
  JsonFields fields(value, "scenarios");
  ScenarioParams scenarios;
  scenarios.low = fields.number("low");
  scenarios.high = fields.number("high");
  scenarios.lead_in = fields.number_or("lead_in", scenarios.lead_in);
  scenarios.step_duration = fields.number_or("step_duration", scenarios.step_duration);
  if (fields.has("sine_frequencies"))
    scenarios.sine_frequencies = fields.numbers("sine_frequencies");
  scenarios.sine_periods = fields.number_or("sine_periods", scenarios.sine_periods);
  scenarios.triangle_loops = fields.count_or("triangle_loops", scenarios.triangle_loops);
  scenarios.triangle_rate = fields.number_or("triangle_rate", scenarios.triangle_rate);
  fields.finish();
  if (!(scenarios.low < scenarios.high)) {
    throw Error(fmt::format("scenarios.low = {} must be < scenarios.high = {}", scenarios.low,
                            scenarios.high));
  }
  if (!(scenarios.lead_in >= 0.0) || !(scenarios.step_duration > 0.0) ||
      !(scenarios.sine_periods > 0.0) || !(scenarios.triangle_rate > 0.0)) {
    throw Error(
        "scenarios: lead_in must be >= 0; step_duration, sine_periods and triangle_rate "
        "> 0");
  }
  return scenarios;
}

// Runs a block's validation, giving its error the JSON path of the object.
template <class Build>
void validate_at(std::string_view object_path, Build build) {
  try {
    build();
  } catch (const Error& error) {
    detail::rethrow_at(error, object_path);
  }
}

const nlohmann::json& required(JsonFields& fields, std::string_view key) {
  const auto* value = fields.raw(key);
  if (value == nullptr) throw Error(fmt::format("{}: missing field", fields.path_of(key)));
  return *value;
}

LoopParams loop_from_json(const nlohmann::json& value, const ActuatorParams& plant,
                          const AnyHysteresis& hysteresis,
                          std::optional<AnyHysteresis>& compensator_hysteresis) {
  JsonFields fields(value, "control");
  LoopParams loop;
  loop.force_gain = fields.number("force_gain");
  loop.voltage_min = fields.number("voltage_min");
  loop.voltage_max = fields.number("voltage_max");
  loop.model_stiffness = fields.number_or("model_stiffness", plant.mechanics.stiffness);
  loop.model_resistance = fields.number_or("model_resistance", plant.coil.resistance);
  loop.model_inductance = fields.number_or("model_inductance", plant.coil.inductance);
  if (const auto* model = fields.raw("compensator_hysteresis")) {
    compensator_hysteresis = hysteresis_from_json(*model, "control.compensator_hysteresis");
    if (compensator_hysteresis->index() != hysteresis.index()) {
      throw Error(
          "control.compensator_hysteresis: must be the same kind of model as hysteresis "
          "(and the same GPI envelope)");
    }
  }
  loop.pid = pid_from_json(required(fields, "pid"));
  fields.finish();
  validate_at("control", [&] { validate_loop_params(loop); });
  validate_at("control.pid", [&] { control::Pid(loop.pid, plant.sample_time); });
  return loop;
}

// A GPI is only checked (envelope ordering) on its operating range: the coil's current range
// must lie inside it.
void require_current_range_inside(const AnyHysteresis& hysteresis, const Coil::Params& coil) {
  std::visit(
      [&](const auto& model) {
        if constexpr (requires { model.params().input_min; }) {
          const auto& p = model.params();
          if (coil.current_min < p.input_min || coil.current_max > p.input_max) {
            throw Error(
                fmt::format("coil current range [{}, {}] must lie inside the GPI operating "
                            "range [{}, {}] (hysteresis.params.input_min/input_max)",
                            coil.current_min, coil.current_max, p.input_min, p.input_max));
          }
        }
      },
      hysteresis);
}

ActuatorConfig parse(const nlohmann::json& document) {
  JsonFields fields(document, "");
  const std::string name = fields.string("name");
  const std::string description = fields.string_or("description", "");
  ActuatorParams plant;
  plant.sample_time = fields.number("sample_time");
  plant.substeps = fields.count_or("substeps", 1);
  plant.delay = fields.number_or("delay", 0.0);
  plant.coil = coil_from_json(required(fields, "coil"));
  plant.mechanics = mechanics_from_json(required(fields, "mechanics"));
  if (const auto* noise = fields.raw("noise")) plant.noise = noise_from_json(*noise);
  validate_at("actuator", [&] { validate_actuator_timing(plant); });
  validate_at("coil", [&] { Coil(plant.coil, plant.sample_time); });
  validate_at("mechanics", [&] { Mechanics(plant.mechanics, plant.sample_time); });
  validate_at("delay", [&] { TransportDelay(plant.delay, plant.sample_time); });
  validate_at("noise", [&] { SensorNoise{plant.noise}; });
  AnyHysteresis hysteresis = hysteresis_from_json(required(fields, "hysteresis"), "hysteresis");
  require_current_range_inside(hysteresis, plant.coil);
  std::optional<AnyHysteresis> compensator;
  LoopParams loop = loop_from_json(required(fields, "control"), plant, hysteresis, compensator);
  ScenarioParams scenarios = scenarios_from_json(required(fields, "scenarios"));
  // The lead-in becomes a sample count (compare_strategies); bound it before any conversion.
  if (const double samples = scenarios.lead_in / plant.sample_time;
      !(samples <= io::limits::kMaxDerivedSamples)) {
    throw Error(fmt::format(
        "scenarios.lead_in = {} s is {:.4g} samples of h = {} s, more than the limit of {:.0f}",
        scenarios.lead_in, samples, plant.sample_time, io::limits::kMaxDerivedSamples));
  }
  fields.finish();
  return {name, description, plant, hysteresis, compensator.value_or(hysteresis), loop, scenarios};
}

}  // namespace

ActuatorConfig actuator_config_from_json(const nlohmann::json& document, std::string_view source) {
  try {
    return parse(document);
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", source, error.what()), error.field());
  }
}

ActuatorConfig load_actuator_config(const std::filesystem::path& path) {
  const nlohmann::json document = io::parse_json_text(io::read_file(path), path.string());
  return actuator_config_from_json(document, path.string());
}

}  // namespace hyst
