// Example 09: the Bouc-Wen nonlinear system identification benchmark (Noel & Schoukens 2016).
//
// 1. The published system, simulated from the official test inputs, reproduces the official test
//    outputs - if the input is interpolated band-limited between the samples (the data were made
//    that way), not held or linear.
// 2. Identification: the grey-box oscillator (m, c, k, alpha, beta gamma, beta delta) is fitted to
//    the estimation record uest/yest by simulation-error minimisation (Ceres, autodiff through
//    RK4).
// 3. Free-run simulation of the fitted model on the two test sets; the RMS error in metres is the
//    benchmark's figure of merit (best published multisine result 7.53e-6 m, gr-SS-NN).
//
// Default (ctest): 2 of the 4 estimation periods, 15 iterations. `--full`: all 4 periods, 60
// iterations - the figures of docs/results.md.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "hyst/identify/fit_bouc_wen_oscillator.hpp"
#include "hyst/io/mat_file.hpp"
#include "hyst/signals/band_limited.hpp"

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kFactor = 10;  // input upsampling: 7.5 kHz simulation grid

double rms(std::span<const double> a, std::span<const double> b) {
  double sum = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
    sum += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

std::vector<double> repeat(const std::vector<double>& period, std::size_t times) {
  std::vector<double> out;
  for (std::size_t i = 0; i < times; ++i)
    out.insert(out.end(), period.begin(), period.end());
  return out;
}

hyst::BoucWenOscillator at_fine_rate(hyst::BoucWenOscillator::Params p) {
  p.sample_time = 1.0 / 750.0 / kFactor;
  p.substeps = 1;
  return hyst::BoucWenOscillator(p);
}

struct TestErrors {
  double multisine_steady;  // third period of the periodic multisine
  double multisine_from_rest;
  double sinesweep_from_rest;
};

TestErrors test_errors(const hyst::BoucWenOscillator& model, const std::vector<double>& u_ms,
                       const std::vector<double>& y_ms, const std::vector<double>& u_ss,
                       const std::vector<double>& y_ss) {
  const auto fine_ms = repeat(hyst::upsample_periodic(u_ms, kFactor), 3);
  const auto sim_ms = hyst::simulate_bouc_wen_oscillator(model, fine_ms, kFactor);
  const auto sim_ss = hyst::simulate_bouc_wen_oscillator(
      model, hyst::upsample_band_limited(u_ss, kFactor), kFactor);
  const std::size_t n = u_ms.size();
  return {rms(std::span(sim_ms).subspan(2 * n, n), y_ms), rms(std::span(sim_ms).first(n), y_ms),
          rms(sim_ss, y_ss)};
}

}  // namespace

int main(int argc, char** argv) {
  const bool full = argc > 1 && std::strcmp(argv[1], "--full") == 0;
  const char* env = std::getenv("HYST_SHARED_DATA_DIR");
  const fs::path data =
      (env ? fs::path(env) : fs::path(__FILE__).parent_path() / "../../shared/data") /
      "boucwen_benchmark";
  const auto u_ms = hyst::io::read_mat_vector(data / "uval_multisine.mat", "uval_multisine");
  const auto y_ms = hyst::io::read_mat_vector(data / "yval_multisine.mat", "yval_multisine");
  const auto u_ss = hyst::io::read_mat_vector(data / "uval_sinesweep.mat", "uval_sinesweep");
  const auto y_ss = hyst::io::read_mat_vector(data / "yval_sinesweep.mat", "yval_sinesweep");
  const auto u_est = hyst::io::read_mat_vector(data / "uest_multisine.mat", "u");
  const auto y_est = hyst::io::read_mat_vector(data / "yest_multisine.mat", "y");

  // 1. The published parameters.
  const auto published =
      test_errors(at_fine_rate(hyst::BoucWenOscillator::benchmark()), u_ms, y_ms, u_ss, y_ss);
  std::printf(
      "published parameters: RMS difference to yval_multisine %.3g m (steady state), "
      "%.3g m (from rest); to yval_sinesweep %.3g m\n",
      published.multisine_steady, published.multisine_from_rest, published.sinesweep_from_rest);

  // 2. Fit on the estimation record: 4 identical periods of 8192 samples; the first period is
  //    simulated from rest and not compared (transient), the others are.
  constexpr std::size_t kPeriod = 8192;
  const std::size_t periods = full ? 4 : 2;
  const std::vector<double> one_period(u_est.begin(), u_est.begin() + kPeriod);
  const auto fine_input = repeat(hyst::upsample_periodic(one_period, kFactor), periods);
  const std::span<const double> output(y_est.data(), periods * kPeriod);
  const hyst::BoucWenOscillatorRecord record{fine_input, output, kFactor, kPeriod};
  hyst::BoucWenOscillatorFitOptions options;
  options.max_iterations = full ? 60 : 15;
  const auto fit = hyst::fit_bouc_wen_oscillator(std::span(&record, 1), options);
  std::printf("%s\n", fit.report.brief().c_str());
  const auto& p = fit.model.params();
  std::printf(
      "fitted: m = %.6g kg, c = %.6g N s/m, k = %.6g N/m, alpha = %.6g N/m, "
      "beta gamma = %.6g, beta delta = %.6g (published 2, 10, 5e4, 5e4, 800, -1100)\n",
      p.mass, p.damping, p.stiffness, p.alpha, p.beta * p.gamma, p.beta * p.delta);

  // 3. Free-run simulation on the test sets.
  const auto fitted = test_errors(fit.model, u_ms, y_ms, u_ss, y_ss);
  std::printf(
      "fitted model, test RMSE: multisine %.3g m (steady state), %.3g m (from rest); "
      "sine sweep %.3g m (from rest)\n",
      fitted.multisine_steady, fitted.multisine_from_rest, fitted.sinesweep_from_rest);
  std::printf("best published multisine RMSE 7.53e-6 m (gr-SS-NN): %.0fx better\n",
              7.53e-6 / fitted.multisine_steady);
  return fit.report.termination != hyst::Termination::failed && fitted.multisine_steady < 7.53e-6
             ? 0
             : 1;
}
