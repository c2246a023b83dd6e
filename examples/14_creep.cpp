// Example 14: hysteresis with creep. A PI model with a logarithmic creep law (the drift of a
// piezo after a voltage step), its identification from one triangle at two rates (hysteresis and
// creep weights by one NNLS, each record at its own sample time), the prediction at a slower rate,
// its exact inverse as a feedforward that also cancels the drift, and the modified PI with creep
// for a saturating actuator, identified from the same two rates.
//
// Run: ./build/examples/example_14_creep

#include <cmath>
#include <cstdio>
#include <vector>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/error_metrics.hpp"
#include "hyst/identify/fit_modified_prandtl_ishlinskii_creep.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii_creep.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii_creep.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"

namespace {

// One period of a triangle 0 -> 1 -> -1 -> 0 at `frequency`, `samples` samples.
std::vector<double> triangle(double frequency, std::size_t samples, double* sample_time) {
  *sample_time = 1.0 / (frequency * static_cast<double>(samples));
  std::vector<double> v(samples);
  for (std::size_t k = 0; k < samples; ++k) {
    const double phase = static_cast<double>(k + 1) / static_cast<double>(samples);
    v[k] = phase < 0.25 ? 4 * phase : phase < 0.75 ? 2 - 4 * phase : 4 * phase - 4;
  }
  return v;
}

}  // namespace

int main() {
  // 1. A "true" actuator: a PI whose displacement creeps 2 % per decade after a step, from 10 ms
  //    to 1000 s, sampled at 1 ms.
  const hyst::PrandtlIshlinskii::Params pi{{0.0, 0.2, 0.4, 0.6}, {1.0, 0.4, 0.3, 0.2}, 0.0};
  const hyst::PrandtlIshlinskiiCreep actuator(
      hyst::pi_logarithmic_creep(pi, 0.02, 0.01, 5, 3, 1e-3));
  auto state = actuator.initial_state();
  // The instantaneous response, the PI's: 1 + 0.4 * 0.8 + 0.3 * 0.6 + 0.2 * 0.4.
  const double y0 = 1.58;
  double y = 0.0;
  std::printf("step to 1 V:  t [s]   y        y(0+) (1 + 0.02 log10(t / 0.01))\n");
  for (std::size_t k = 1; k <= 100000; ++k) {
    y = actuator.step(state, 1.0);
    if (k == 100 || k == 1000 || k == 10000 || k == 100000) {
      const double t = static_cast<double>(k) * 1e-3;
      std::printf("              %-7g %.5f  %.5f\n", t, y,
                  y0 * (1.0 + 0.02 * std::log10(t / 0.01)));
    }
  }

  // 2. Identification on one triangle period at 1 Hz and at 0.1 Hz (400 samples each), from the
  //    periodic steady state; prediction at 0.01 Hz.
  double ts_fast = 0.0;
  double ts_slow = 0.0;
  double ts_slowest = 0.0;
  const auto fast = triangle(1.0, 400, &ts_fast);
  const auto slow = triangle(0.1, 400, &ts_slow);
  const auto slowest = triangle(0.01, 400, &ts_slowest);
  auto measure = [&](const std::vector<double>& v, double ts) {
    const auto at_rate = actuator.at_sample_time(ts);
    auto periodic = at_rate.periodic_state(v);
    return hyst::simulate(at_rate, periodic, v);
  };
  const auto y_fast = measure(fast, ts_fast);
  const auto y_slow = measure(slow, ts_slow);
  const auto y_slowest = measure(slowest, ts_slowest);
  const std::vector<hyst::FitRecord> records{{fast, y_fast}, {slow, y_slow}};
  hyst::PiCreepFitOptions options;
  options.operators = 8;
  options.lags = 6;
  options.sample_times = {ts_fast, ts_slow};
  options.initial_state = hyst::PiFitOptions::InitialState::periodic;
  const auto fit = hyst::fit_prandtl_ishlinskii_creep(records, options);
  std::printf("\nfit: %s\n", fit.report.brief().c_str());
  const auto slowest_model = fit.model.at_sample_time(ts_slowest);
  auto periodic = slowest_model.periodic_state(slowest);
  const double predicted =
      hyst::error_metrics(y_slowest, hyst::simulate(slowest_model, periodic, slowest))
          .nrmse_percent;
  options.lags = 0;  // the rate-independent PI, fitted the same way
  const auto pi_fit = hyst::fit_prandtl_ishlinskii_creep(records, options);
  const auto pi_model = pi_fit.model.at_sample_time(ts_slowest);
  periodic = pi_model.periodic_state(slowest);
  const double pi_predicted =
      hyst::error_metrics(y_slowest, hyst::simulate(pi_model, periodic, slowest)).nrmse_percent;
  std::printf("0.01 Hz predicted: NRMSE %.3f %% with creep, %.3f %% without\n", predicted,
              pi_predicted);

  // 3. Feedforward for a held position: the inverse with creep keeps it; the inverse of the
  //    hysteresis alone lets it drift by the creep.
  const hyst::InversePrandtlIshlinskiiCreep inverse(actuator);
  const hyst::InversePrandtlIshlinskii hysteresis_only(actuator.hysteresis());
  auto inverse_state = inverse.initial_state();
  auto plain_state = hysteresis_only.initial_state();
  auto actuator_a = actuator.initial_state();
  auto actuator_b = actuator.initial_state();
  double drift_with = 0.0;
  double drift_without = 0.0;
  for (std::size_t k = 0; k < 60000; ++k) {
    const double desired = 0.8;
    drift_with =
        std::abs(actuator.step(actuator_a, inverse.step(inverse_state, desired)) - desired);
    drift_without =
        std::abs(actuator.step(actuator_b, hysteresis_only.step(plain_state, desired)) - desired);
  }
  std::printf("holding 0.8 for 60 s: error %.2e with the creep inverse, %.4f with the PI inverse\n",
              drift_with, drift_without);

  // 4. A saturating actuator: the same hysteresis and creep followed by dead zones that halve the
  //    slope above 1.2 and below -1.2 (the modified PI with creep). Fitted on the two rates by the
  //    modified fit, it predicts the slow rate; the PI with creep cannot follow the saturation.
  hyst::ModifiedPrandtlIshlinskiiCreep::Params saturating;
  saturating.pi_creep = actuator.params();
  saturating.dead_zone = {{-1.2, 0.0, 1.2}, {-0.5, 1.0, -0.5}};
  const hyst::ModifiedPrandtlIshlinskiiCreep saturating_actuator(saturating);
  auto measure_saturating = [&](const std::vector<double>& v, double ts) {
    const auto at_rate = saturating_actuator.at_sample_time(ts);
    auto periodic_state = at_rate.periodic_state(v);
    return hyst::simulate(at_rate, periodic_state, v);
  };
  const auto s_fast = measure_saturating(fast, ts_fast);
  const auto s_slow = measure_saturating(slow, ts_slow);
  const auto s_slowest = measure_saturating(slowest, ts_slowest);
  const std::vector<hyst::FitRecord> saturating_records{{fast, s_fast}, {slow, s_slow}};
  hyst::ModifiedPiCreepFitOptions modified_options;
  modified_options.operators = 8;
  modified_options.lags = 6;
  modified_options.sample_times = {ts_fast, ts_slow};
  modified_options.initial_state = hyst::PiFitOptions::InitialState::periodic;
  const auto modified_fit =
      hyst::fit_modified_prandtl_ishlinskii_creep(saturating_records, modified_options);
  std::printf("\nsaturating actuator, modified PI with creep: %s\n",
              modified_fit.report.brief().c_str());
  const auto modified_slowest = modified_fit.model.at_sample_time(ts_slowest);
  auto modified_periodic = modified_slowest.periodic_state(slowest);
  const double modified_predicted =
      hyst::error_metrics(s_slowest, hyst::simulate(modified_slowest, modified_periodic, slowest))
          .nrmse_percent;
  options.lags = 6;
  const auto unsaturated_fit = hyst::fit_prandtl_ishlinskii_creep(saturating_records, options);
  const auto unsaturated_slowest = unsaturated_fit.model.at_sample_time(ts_slowest);
  periodic = unsaturated_slowest.periodic_state(slowest);
  const double unsaturated_predicted =
      hyst::error_metrics(s_slowest, hyst::simulate(unsaturated_slowest, periodic, slowest))
          .nrmse_percent;
  std::printf("0.01 Hz predicted: NRMSE %.3f %% modified PI with creep, %.3f %% PI with creep\n",
              modified_predicted, unsaturated_predicted);
  // Its inverse: the dead zones undone, then the inverse with creep.
  const hyst::InverseModifiedPrandtlIshlinskiiCreep modified_inverse(saturating_actuator);
  auto modified_inverse_state = modified_inverse.initial_state();
  auto saturating_state = saturating_actuator.initial_state();
  double modified_hold = 0.0;
  for (std::size_t k = 0; k < 60000; ++k) {
    modified_hold =
        std::abs(saturating_actuator.step(saturating_state,
                                          modified_inverse.step(modified_inverse_state, 1.5)) -
                 1.5);
  }
  std::printf("holding 1.5 (in the saturation) for 60 s: error %.2e\n", modified_hold);

  const bool ok = std::abs(y - y0 * (1.0 + 0.02 * std::log10(100.0 / 0.01))) < 0.002 &&
                  predicted < 1.0 && pi_predicted > 2.0 * predicted && drift_with < 1e-9 &&
                  drift_without > 0.01 && modified_predicted < 1.0 &&
                  unsaturated_predicted > 1.5 * modified_predicted && modified_hold < 1e-9;
  return ok ? 0 : 1;
}
