// The hysteretic actuator under control: inverse compensation, closed loop against the linear
// model, anti-windup under saturation, model mismatch, configurations, no allocation.

#include <algorithm>
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/line_fit.hpp"
#include "hyst/actuator/actuator_config.hpp"
#include "hyst/actuator/comparison.hpp"
#include "hyst/actuator/control_loop.hpp"
#include "hyst/actuator/force_compensator.hpp"
#include "hyst/actuator/linearised_plant.hpp"
#include "hyst/control/references.hpp"
#include "hyst/control/tracking_metrics.hpp"
#include "hyst/io/atomic_file.hpp"
#include "loop_allocations.hpp"

namespace hyst {
namespace {

using Gpi = GeneralizedPrandtlIshlinskii<TanhEnvelope>;

const std::string kConfigDir = HYST_EXAMPLE_CONFIG_DIR;

ActuatorConfig msma() {
  return load_actuator_config(kConfigDir + "/msma_assumed.json");
}

using test::line_fit_max_residual;

TEST(InverseCompensator, MakesTheForceLinearInTheVirtualCurrent) {
  // GPI[IGPI[k_F i_d]] over a triangle with internal loops: the uncompensated force has loops
  // about 23 N wide, the compensated one lies on the line k_F i_d.
  const auto config = msma();
  const auto& model = std::get<Gpi>(config.hysteresis);
  const InverseCompensator<Gpi> compensator(model, {9.5, 0.0, 8.0});
  auto compensator_state = compensator.initial_state();
  auto model_state = model.initial_state();
  const auto demand = control::triangle_reference(0.5, 7.5, 4, 100.0, 1e-3).values;
  std::vector<double> compensated(demand.size());
  std::vector<double> uncompensated(demand.size());
  auto raw_state = model.initial_state();
  for (std::size_t k = 0; k < demand.size(); ++k) {
    compensated[k] = model.step(model_state, compensator.step(compensator_state, demand[k]));
    uncompensated[k] = model.step(raw_state, demand[k]);
  }
  double slope = 0.0;
  double intercept = 0.0;
  const double residual = line_fit_max_residual(demand, compensated, slope, intercept);
  EXPECT_NEAR(slope, 9.5, 1e-9);
  EXPECT_NEAR(intercept, 0.0, 1e-9);
  EXPECT_LT(residual, 1e-9);
  double raw_slope = 0.0;
  double raw_intercept = 0.0;
  EXPECT_GT(line_fit_max_residual(demand, uncompensated, raw_slope, raw_intercept), 5.0);
}

TEST(InverseCompensator, WorksForPiAndPreisachToo) {
  const PrandtlIshlinskii pi({{0.0, 1.0, 2.0}, {2.0, 0.5, 0.25}, 0.0});
  const InverseCompensator<PrandtlIshlinskii> pi_compensator(pi, {2.0, 0.0, 10.0});
  auto pi_state = pi.initial_state();
  auto pi_inverse = pi_compensator.initial_state();
  // Relay grid on [0, 10], uniform weights, offset so that the virgin (negative saturation)
  // output is 0: the force then spans [0, 2 S] over the current range.
  Preisach::Params preisach_params;
  preisach_params.everett = {
      .levels = 20, .lower = 0.0, .upper = 10.0, .weights = std::vector<double>(210, 1.0)};
  const double low = Preisach(preisach_params).output(Preisach(preisach_params).initial_state());
  preisach_params.offset = -low;
  const Preisach preisach(preisach_params);
  const double gain = -2.0 * low / 10.0;
  const InverseCompensator<Preisach> preisach_compensator(preisach, {gain, 0.0, 10.0});
  auto preisach_state = preisach.initial_state();
  auto preisach_inverse = preisach_compensator.initial_state();
  const auto demand = control::triangle_reference(1.0, 9.0, 3, 50.0, 1e-3).values;
  for (double d : demand) {
    EXPECT_NEAR(pi.step(pi_state, pi_compensator.step(pi_inverse, d)), 2.0 * d, 1e-9);
    // The relay grid is piecewise constant: the numerical inverse is exact to one relay step.
    const double force =
        preisach.step(preisach_state, preisach_compensator.step(preisach_inverse, d));
    EXPECT_NEAR(force, gain * d, 2.0 * gain * 10.0 / 20.0);
  }
}

// The loop of a configuration with the hysteresis and compensator of type Gpi.
ControlLoop<Gpi> gpi_loop(const ActuatorConfig& config) {
  return ControlLoop<Gpi>(Actuator<Gpi>(std::get<Gpi>(config.hysteresis), config.plant),
                          std::get<Gpi>(config.compensator_hysteresis), config.loop);
}

// The same PID and current drive on the linearised plant G(s) (exact discretisation).
std::vector<double> linear_closed_loop(const ActuatorConfig& config,
                                       const std::vector<double>& reference) {
  const auto plant = LinearisedPlant::of(config.plant, config.loop.force_gain);
  const auto discrete = plant.discretise(config.plant.sample_time);
  auto pid_params = config.loop.pid;
  pid_params.output_min = config.plant.coil.current_min;
  pid_params.output_max = config.plant.coil.current_max;
  const control::Pid pid(pid_params, config.plant.sample_time);
  const CurrentDrive drive(config.loop.model_resistance, config.loop.model_inductance,
                           config.loop.voltage_min, config.loop.voltage_max,
                           config.plant.sample_time);
  auto state = discrete.initial_state();
  auto pid_state = pid.initial_state();
  double y = 0.0;
  std::vector<double> output(reference.size());
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const double feedforward = reference[k] * config.loop.model_stiffness / config.loop.force_gain;
    const double current = pid.step(pid_state, reference[k], y, feedforward);
    y = discrete.step(state, drive.voltage(current, state.x(0)));
    output[k] = y;
  }
  return output;
}

TEST(ClosedLoop, TracksAStepAsTheLinearModelPredicts) {
  const auto config = msma();
  const double h = config.plant.sample_time;
  const auto step = control::step_reference(3e-4, 6e-4, 0.05, 0.25, h);
  const auto linear = linear_closed_loop(config, step.values);
  const auto loop = gpi_loop(config);
  auto state = loop.initial_state();
  LoopTrace trace;
  loop.run(state, ControlStrategy::pid_feedforward, step.values, trace);
  const std::vector<double> zero(step.values.size(), 0.0);
  const auto predicted = control::tracking_metrics(step.values, linear, zero, h, step.step);
  const auto actual = control::tracking_metrics(step.values, trace.measured, zero, h, step.step);
  std::printf("linear model: overshoot %.2f %%, settling %.2f ms; actuator: %.2f %%, %.2f ms\n",
              predicted.overshoot, 1e3 * predicted.settling_time, actual.overshoot,
              1e3 * actual.settling_time);
  ASSERT_TRUE(std::isfinite(predicted.settling_time));
  ASSERT_TRUE(std::isfinite(actual.settling_time));
  EXPECT_NEAR(actual.overshoot, predicted.overshoot, 5.0);
  EXPECT_LT(actual.settling_time, 1.5 * predicted.settling_time + 5e-3);
  // Stable: settled at the end within 0.1 % of the step.
  EXPECT_NEAR(trace.measured.back(), 6e-4, 3e-7);
  EXPECT_NEAR(linear.back(), 6e-4, 3e-7);
}

// A PID whose output is the coil voltage, limited to [0, u_max], on the MSMA actuator: the
// overshoot of a step from 0.1 mm to 0.55 mm.
double voltage_loop_overshoot(double voltage_max, control::AntiWindup mode) {
  const auto config = msma();
  const double h = config.plant.sample_time;
  const Actuator<Gpi> actuator(std::get<Gpi>(config.hysteresis), config.plant);
  const control::Pid pid(
      {.kp = 5e3, .ki = 1e6, .output_min = 0.0, .output_max = voltage_max, .anti_windup = mode}, h);
  const auto step = control::step_reference(1e-4, 5.5e-4, 0.05, 0.3, h);
  auto state = actuator.initial_state();
  auto pid_state = pid.initial_state();
  double y = state.delay.buffer.front();
  std::vector<double> output(step.values.size());
  for (std::size_t k = 0; k < output.size(); ++k) {
    y = actuator.step(state, pid.step(pid_state, step.values[k], y)).measured;
    output[k] = y;
  }
  const std::vector<double> zero(output.size(), 0.0);
  return control::tracking_metrics(step.values, output, zero, h, step.step).overshoot;
}

TEST(ClosedLoop, AntiWindupPreventsTheOvershootOfSaturation) {
  // With 10 V available the loop never saturates (the steady state needs about 8 V); with 9 V
  // it saturates during the rise, and without anti-windup the integral wound up meanwhile adds
  // overshoot. Either anti-windup removes that excess.
  const double unsaturated = voltage_loop_overshoot(10.0, control::AntiWindup::none);
  const double none = voltage_loop_overshoot(9.0, control::AntiWindup::none);
  const double back = voltage_loop_overshoot(9.0, control::AntiWindup::back_calculation);
  const double clamping = voltage_loop_overshoot(9.0, control::AntiWindup::clamping);
  std::printf(
      "overshoot: unsaturated %.2f %%; saturated: none %.2f %%, back-calculation %.2f %%, "
      "clamping %.2f %%\n",
      unsaturated, none, back, clamping);
  EXPECT_EQ(voltage_loop_overshoot(10.0, control::AntiWindup::back_calculation), unsaturated);
  EXPECT_GT(none, unsaturated + 5.0);
  EXPECT_LT(back, unsaturated);
  EXPECT_LT(clamping, unsaturated);
}

double rms_error(const ActuatorConfig& config, ControlStrategy strategy,
                 const control::Reference& reference) {
  const auto trace = simulate_loop(config, strategy, reference.values);
  const std::vector<double> zero(reference.values.size(), 0.0);
  return control::tracking_metrics(reference.values, trace.measured, zero, config.plant.sample_time,
                                   std::nullopt)
      .rms_error;
}

TEST(ClosedLoop, FeedforwardStillHelpsWithAMismatchedModel) {
  // The plant's parameters are 10 % off the controller's model: stronger force (rho), softer
  // spring, higher resistance, heavier mass.
  auto config = msma();
  auto plant_gpi = std::get<Gpi>(config.hysteresis).params();
  plant_gpi.rho *= 1.1;
  config.hysteresis = Gpi(plant_gpi);
  config.plant.mechanics.stiffness *= 0.9;
  config.plant.mechanics.mass *= 1.1;
  config.plant.coil.resistance *= 1.1;
  const double h = config.plant.sample_time;
  for (const auto& reference : {control::sine_reference(5e-4, 3e-4, 10.0, 0.3, h),
                                control::triangle_reference(1.5e-4, 8.5e-4, 4, 0.01, h)}) {
    const double pid = rms_error(config, ControlStrategy::pid, reference);
    const double combined = rms_error(config, ControlStrategy::pid_feedforward, reference);
    std::printf("%s: RMS error PID %.3g m, PID + feedforward %.3g m\n", reference.name.c_str(), pid,
                combined);
    EXPECT_LT(combined, 0.8 * pid) << reference.name;
  }
}

TEST(Comparison, RanksTheStrategiesOnTheMsmaActuator) {
  const auto config = msma();
  const auto comparison = compare_strategies(config, scenario_references(config));
  std::printf("%s", comparison_markdown(comparison).c_str());
  ASSERT_EQ(comparison.runs.size(), 4u * scenario_references(config).size());
  for (std::size_t r = 0; r < comparison.runs.size(); r += 4) {
    const auto& open = comparison.runs[r].metrics;
    const auto& combined = comparison.runs[r + 3].metrics;
    EXPECT_LT(combined.rms_error, open.rms_error) << comparison.runs[r].reference;
  }
}

TEST(NoAllocation, ClosedLoopStep) {
  auto config = msma();
  config.plant.noise = {1e-7, 3};  // the noise generator too
  const auto loop = gpi_loop(config);
  test::expect_closed_loop_does_not_allocate(loop, 100000);
}

TEST(ActuatorConfig, LoadsBothPresets) {
  const auto config = msma();
  EXPECT_EQ(config.name, "msma_assumed");
  EXPECT_NE(config.description.find("[ASSUMED]"), std::string::npos);
  EXPECT_EQ(hysteresis_name(config.hysteresis), "gpi");
  EXPECT_EQ(config.plant.coil.resistance, 2.0);
  const auto piezo = load_actuator_config(kConfigDir + "/piezo_stack.json");
  EXPECT_EQ(hysteresis_name(piezo.hysteresis), "pi");
  const auto reference = control::step_reference(2e-6, 20e-6, 0.01, 0.05, piezo.plant.sample_time);
  const auto trace = simulate_loop(piezo, ControlStrategy::pid_feedforward, reference.values);
  EXPECT_NEAR(trace.measured.back(), 20e-6, 0.02 * 18e-6);
}

TEST(ActuatorConfig, PreisachForceChosenByName) {
  // The MSMA actuator with a Preisach force instead: 210 relays of +-0.181 N on 0..8 A plus an
  // offset of 38 N span 0..76 N; the numerical inverse is the feedforward.
  auto document = nlohmann::json::parse(io::read_file(kConfigDir + "/msma_assumed.json"));
  document["hysteresis"] = {{"model", "preisach"},
                            {"params",
                             {{"levels", 20},
                              {"lower", 0.0},
                              {"upper", 8.0},
                              {"weights", std::vector<double>(210, 76.0 / 420.0)},
                              {"offset", 38.0}}}};
  const auto config = actuator_config_from_json(document, "preisach.json");
  EXPECT_EQ(hysteresis_name(config.hysteresis), "preisach");
  const auto step = control::step_reference(3e-4, 6e-4, 0.05, 0.3, config.plant.sample_time);
  const auto closed = simulate_loop(config, ControlStrategy::pid_feedforward, step.values);
  const auto open = simulate_loop(config, ControlStrategy::open_loop, step.values);
  // The relay grid quantises the force to 76/210 N steps (about 5 um); the PID's integral
  // dithers between them, so the last 50 ms are compared on average.
  const auto mean_tail = [](const std::vector<double>& y) {
    return std::accumulate(y.end() - 500, y.end(), 0.0) / 500.0;
  };
  EXPECT_NEAR(mean_tail(closed.measured), 6e-4, 3e-6);
  EXPECT_GT(std::abs(mean_tail(open.measured) - 6e-4), 1e-5);
}

TEST(ActuatorConfig, ErrorsNameTheSourceAndField) {
  auto document = nlohmann::json::parse(io::read_file(kConfigDir + "/msma_assumed.json"));
  auto broken = document;
  broken["coil"]["resistance"] = -2.0;
  EXPECT_HYST_ERROR(actuator_config_from_json(broken, "a.json"),
                    "a.json: coil.resistance: coil resistance R = -2");
  broken = document;
  broken["mechanics"]["masss"] = 1.0;
  EXPECT_HYST_ERROR(actuator_config_from_json(broken, "a.json"), "mechanics.masss: unknown field");
  broken = document;
  broken["hysteresis"]["model"] = "nonsense";
  EXPECT_HYST_ERROR(actuator_config_from_json(broken, "a.json"), "unknown model 'nonsense'");
  broken = document;
  broken["hysteresis"]["params"]["rho"] = -1.0;
  EXPECT_HYST_ERROR(actuator_config_from_json(broken, "a.json"), "hysteresis.params.rho");
  broken = document;
  broken["control"]["pid"]["anti_windup"] = "sometimes";
  EXPECT_HYST_ERROR(actuator_config_from_json(broken, "a.json"), "control.pid.anti_windup");
  broken = document;
  broken.erase("mechanics");
  EXPECT_HYST_ERROR(actuator_config_from_json(broken, "a.json"), "mechanics: missing field");
  broken = document;
  broken["coil"]["current_max"] = 9.0;
  EXPECT_HYST_ERROR(actuator_config_from_json(broken, "a.json"),
                    "coil current range [0, 9] must lie inside the GPI operating range [0, 8]");
  broken = document;
  broken["control"]["compensator_hysteresis"] = {
      {"model", "pi"}, {"params", {{"thresholds", {0.0}}, {"weights", {1.0}}}}};
  EXPECT_HYST_ERROR(actuator_config_from_json(broken, "a.json"), "same kind of model");
}

TEST(References, ShapesAndErrors) {
  const auto step = control::step_reference(1.0, 2.0, 0.5, 1.0, 0.25);
  EXPECT_EQ(step.values, (std::vector<double>{1.0, 1.0, 2.0, 2.0, 2.0}));
  const auto triangle = control::triangle_reference(0.0, 1.0, 2, 1.0, 0.125);
  // Turning points 0, 1, 1/6, 5/6, 0.
  EXPECT_NEAR(*std::max_element(triangle.values.begin(), triangle.values.end()), 1.0, 1e-15);
  EXPECT_NEAR(triangle.values.back(), 0.0, 1e-15);
  EXPECT_HYST_ERROR(control::step_reference(1.0, 2.0, 2.0, 1.0, 0.25), "step time");
  EXPECT_HYST_ERROR(control::triangle_reference(1.0, 0.0, 2, 1.0, 0.1), "low");
  EXPECT_HYST_ERROR(control::sine_reference(0.0, 1.0, 1.0, 1.0, 0.0), "sample time");
}

TEST(References, FromCsv) {
  const auto folder = std::filesystem::temp_directory_path() / "hyst_test_references";
  std::filesystem::create_directories(folder);
  io::write_file_atomically(folder / "r.csv", "t,x\n0,1\n0.5,2\n1.0,4\n");
  const auto reference = control::reference_from_csv(folder / "r.csv", 0.5);
  EXPECT_EQ(reference.values, (std::vector<double>{1.0, 2.0, 4.0}));  // the last column
  EXPECT_EQ(reference.name, "r");
  EXPECT_HYST_ERROR(control::reference_from_csv(folder / "r.csv", 0.25), "data row 2");
  std::filesystem::remove_all(folder);
}

TEST(TrackingMetrics, FromAHandMadeResponse) {
  // Step 0 -> 1 at t = 1 (h = 1): y overshoots to 1.2, enters the 2 % band at k = 5.
  const std::vector<double> r{0, 1, 1, 1, 1, 1, 1, 1};
  const std::vector<double> y{0, 0, 0.8, 1.2, 1.05, 1.01, 0.995, 1.0};
  const std::vector<double> u{0, 2, 2, 2, 2, 2, 2, 2};
  const auto metrics = control::tracking_metrics(r, y, u, 1.0, control::StepEvent{1.0, 0.0, 1.0});
  EXPECT_NEAR(metrics.max_error, 1.0, 1e-15);
  EXPECT_NEAR(metrics.overshoot, 20.0, 1e-12);
  EXPECT_NEAR(metrics.settling_time, 4.0, 1e-15);
  EXPECT_NEAR(metrics.control_effort, std::sqrt(28.0 / 8.0), 1e-15);
  double squares = 1.0 + 0.04 + 0.04 + 0.0025 + 0.0001 + 0.000025;
  EXPECT_NEAR(metrics.rms_error, std::sqrt(squares / 8.0), 1e-15);
}

}  // namespace
}  // namespace hyst
