// Control of a hysteretic MSMA actuator: open loop, inverse (IGPI) feedforward, PID, and PID with
// the feedforward, compared on steps, sines and a triangle with internal loops.
//
// The parameter set is the [ASSUMED] synthetic MSMA set of the reference (not measured values);
// the figures are simulated. Run: build/examples/example_06_actuator [config.json]

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hyst/actuator/actuator_config.hpp"
#include "hyst/actuator/comparison.hpp"
#include "hyst/actuator/linearised_plant.hpp"

int main(int argc, char** argv) {
  try {
    const std::string path =
        argc > 1 ? argv[1] : std::string(HYST_EXAMPLE_CONFIG_DIR) + "/msma_assumed.json";
    const auto config = hyst::load_actuator_config(path);
    fmt::print("{} - {}\n", config.name, config.description);

    const auto plant = hyst::LinearisedPlant::of(config.plant, config.loop.force_gain);
    fmt::print("linearised plant: DC gain {:.4g} m/V\n", plant.dc_gain());

    // One run: a 5 Hz sine between 0.2 and 0.8 mm under PID + inverse feedforward.
    std::vector<double> reference;
    for (double t = 0.0; t < 0.4; t += config.plant.sample_time)
      reference.push_back(5e-4 + 3e-4 * std::sin(2.0 * std::numbers::pi * 5.0 * t));
    const auto run = hyst::simulate_loop(config, hyst::ControlStrategy::pid_feedforward, reference);
    // Scored after the first 0.1 s: the run starts at rest at 0 A, far from the reference.
    const auto first = static_cast<std::size_t>(std::llround(0.1 / config.plant.sample_time));
    double squares = 0.0;
    for (std::size_t k = first; k < reference.size(); ++k)
      squares += std::pow(reference[k] - run.measured[k], 2);
    fmt::print("5 Hz sine, PID + feedforward: RMS error after 0.1 s {:.2f} um\n",
               1e6 * std::sqrt(squares / static_cast<double>(reference.size() - first)));

    // The comparison of the four strategies on the configuration's scenarios.
    const auto comparison = hyst::compare_strategies(config, hyst::scenario_references(config));
    fmt::print("{}", hyst::comparison_markdown(comparison));
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
}
