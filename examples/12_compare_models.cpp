// Example 12: which model fits? Several models fitted to the same record and ranked on the same
// held-out part, then the black-box NARX model on the Bouc-Wen identification benchmark.
//
// 1. A record of a saturating hysteretic system (a Bouc-Wen model driven by a random walk) is
//    given to hyst::compare_models(): PI, Bouc-Wen and NARX are fitted on its first 75 % and
//    ranked by the free-run NRMSE on the last 25 %. The generating model comes out first.
// 2. The NARX model with play-operator regressors on the Bouc-Wen benchmark (Noel & Schoukens
//    2016): fitted on the estimation record uest/yest, run in free run on the two official test
//    sets, RMS error in metres next to the published black-box results (gr-SS-NN 7.53e-6 m,
//    PNLSS 1.34e-5 m on the multisine test).
//
// Default (ctest): 4 lags, 6 neurons, 15 + 5 iterations. `--full` (10 lags, 12 neurons, 100
// one-step + 60 simulation-error iterations; about 6 minutes): the figures of docs/results.md.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <span>
#include <vector>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/compare.hpp"
#include "hyst/identify/fit_narx.hpp"
#include "hyst/io/mat_file.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "hyst/signals/generators.hpp"

namespace fs = std::filesystem;

namespace {

double rms(std::span<const double> a, std::span<const double> b) {
  double sum = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
    sum += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

std::vector<double> repeat(std::span<const double> period, std::size_t times) {
  std::vector<double> out;
  for (std::size_t i = 0; i < times; ++i)
    out.insert(out.end(), period.begin(), period.end());
  return out;
}

void rank_models() {
  const hyst::BoucWen system(
      {.a = 1.0, .beta = 0.6, .gamma = 0.3, .n = 1.0, .stiffness = 2.0, .alpha_k = 0.3});
  const auto v = hyst::signals::generate(
      hyst::signals::TimeGrid{1600, 1.0},
      hyst::signals::RandomWalk{
          .max_step = 0.15, .lower = -2.0, .upper = 2.0, .start = 0.0, .seed = 12});
  auto state = system.initial_state();
  const auto y = hyst::simulate(system, state, v);

  hyst::CompareOptions options;
  options.models = {"pi", "bouc_wen", "narx"};
  options.fit_options["narx"] = {{"hidden_sizes", {6}}, {"max_iterations", 30}};
  const auto comparison = hyst::compare_models(v, y, options);
  std::printf("%s\n", hyst::model_comparison_markdown(comparison).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const bool full = argc > 1 && std::strcmp(argv[1], "--full") == 0;
  rank_models();

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

  // The estimation record is 4 periods of one multisine in steady state: their mean output has
  // half the noise of one period. The fit record is that mean period repeated; its last repeat
  // is the early-stopping part (the same input again: it checks the free run, it is not new
  // excitation - the test sets are).
  constexpr std::size_t kPeriod = 8192;
  std::vector<double> mean_output(kPeriod, 0.0);
  for (std::size_t p = 0; p < 4; ++p) {
    for (std::size_t k = 0; k < kPeriod; ++k)
      mean_output[k] += 0.25 * y_est[p * kPeriod + k];
  }
  const std::size_t repeats = full ? 3 : 2;
  const auto u = repeat(std::span(u_est).first(kPeriod), repeats);
  const auto y = repeat(mean_output, repeats);
  hyst::NarxFitOptions options;
  options.input_lags = full ? 10 : 4;
  options.output_lags = full ? 10 : 4;
  options.plays = 4;
  options.hidden_sizes = {full ? std::size_t{12} : std::size_t{6}};
  options.max_iterations = full ? 100 : 15;
  options.simulation_iterations = full ? 60 : 5;
  options.patience = 25;
  options.early_stopping_fraction = 1.0 / static_cast<double>(repeats);
  const auto fit = hyst::fit_narx(u, y, options);
  std::printf("%s\n", fit.report.brief().c_str());

  // Free run: the multisine in steady state (third of three periods from rest), the sine sweep
  // from rest.
  auto state = fit.model.initial_state();
  const auto sim_ms = hyst::simulate(fit.model, state, repeat(u_ms, 3));
  state = fit.model.initial_state();
  const auto sim_ss = hyst::simulate(fit.model, state, u_ss);
  const double multisine = rms(std::span(sim_ms).subspan(2 * u_ms.size(), u_ms.size()), y_ms);
  const double sinesweep = rms(sim_ss, y_ss);
  std::printf(
      "NARX (%zu weights), free-run test RMSE: multisine %.3g m, sine sweep %.3g m\n"
      "published black-box multisine RMSE: gr-SS-NN 7.53e-6 m, PNLSS 1.34e-5 m\n",
      fit.model.params().weights.size(), multisine, sinesweep);
  return std::isfinite(multisine) && std::isfinite(sinesweep) ? 0 : 1;
}
