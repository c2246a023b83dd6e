// Example 10: Jiles-Atherton B(H) loops with minor loops.
//
// For each measured material the model is fitted to the largest loop (Ceres, steady-state loop)
// and predicts the nested smaller loops it never saw. Then the fitted Mn-Zn ferrite model is
// driven by an arbitrary field history with asymmetric minor loops, and the tangent dB/dH (what a
// finite-element or circuit solver needs) is printed along it.
//
// Default (ctest): Mn-Zn ferrite, original variant, at most 40 iterations. `--full`: all three
// materials and both variants, up to 200 iterations - the table of docs/results.md.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hyst/identify/fit_jiles_atherton.hpp"
#include "hyst/io/mat_file.hpp"

namespace fs = std::filesystem;

namespace {

std::string fmt_status(const hyst::FitReport& report) {
  char text[96];
  std::snprintf(text, sizeof text, "%s, %.1f s",
                std::string(hyst::to_string(report.termination)).c_str(), report.seconds);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  const bool full = argc > 1 && std::strcmp(argv[1], "--full") == 0;
  const char* env = std::getenv("HYST_SHARED_DATA_DIR");
  const fs::path data =
      (env ? fs::path(env) : fs::path(__FILE__).parent_path() / "../../shared/data") /
      "bh_loops_jamodel";
  std::vector<std::string> materials{"MnZn_ferrite"};
  std::vector<hyst::JilesAthertonVariant> variants{hyst::JilesAthertonVariant::original};
  if (full) {
    materials = {"MnZn_ferrite", "M130_27s", "amorf"};
    variants.push_back(hyst::JilesAthertonVariant::venkataraman);
  }
  std::printf(
      "| material | variant | loop, H amplitude | role | NRMSE | fit status, time |\n"
      "|---|---|---|---|---:|---|\n");
  bool ok = true;
  std::optional<hyst::JilesAtherton> ferrite;
  for (const auto& material : materials) {
    const auto h = hyst::io::read_mat_columns(data / ("H_" + material + ".mat"), "HmeasT");
    const auto b = hyst::io::read_mat_columns(data / ("B_" + material + ".mat"), "BmeasT");
    for (auto variant : variants) {
      const std::vector<hyst::BhLoop> largest{{h.back(), b.back()}};
      std::vector<hyst::BhLoop> smaller;
      for (std::size_t j = 0; j + 1 < h.size(); ++j)
        smaller.push_back({h[j], b[j]});
      hyst::JilesAthertonFitOptions options;
      options.variant = variant;
      options.max_iterations = full ? 200 : 40;
      const auto fit = hyst::fit_jiles_atherton(largest, smaller, options);
      ok = ok && fit.report.termination != hyst::Termination::failed;
      for (std::size_t j = h.size(); j-- > 0;) {
        const auto simulated = hyst::simulate_bh_loop(fit.model, h[j]);
        const auto metrics = hyst::error_metrics(b[j], simulated);
        double amplitude = 0.0;
        for (double value : h[j])
          amplitude = std::max(amplitude, std::abs(value));
        std::printf("| %s | %s | %zu of %zu, %.0f A/m | %s | %.2f %% | %s |\n", material.c_str(),
                    std::string(hyst::to_string(variant)).c_str(), j + 1, h.size(), amplitude,
                    j + 1 == h.size() ? "fit" : "predicted", metrics.nrmse_percent,
                    j + 1 == h.size() ? fmt_status(fit.report).c_str() : "");
      }
      const auto& p = fit.model.params();
      std::printf(
          "|   | parameters | M_s = %.4g A/m, a = %.4g A/m, k = %.4g A/m, c = %.3g, "
          "alpha = %.3g | | | |\n",
          p.ms, p.a, p.k, p.c, p.alpha);
      if (material == "MnZn_ferrite" && !ferrite) ferrite.emplace(fit.model);
    }
  }

  // Arbitrary H(t) with asymmetric minor loops, from the demagnetised state.
  const auto& model = *ferrite;
  auto state = model.initial_state();
  const double path[] = {80, -80, 80, 20, 50, 20, -10, 30, -80};
  double h_now = 0.0;
  std::printf(
      "\nferrite model along H = 0 -> 80 -> -80 -> 80 -> 20 -> 50 -> 20 -> -10 -> 30 -> "
      "-80 A/m:\n");
  for (double target : path) {
    for (int i = 1; i <= 50; ++i)
      model.step(state, h_now + (target - h_now) * i / 50.0);
    h_now = target;
    std::printf("  H = %6.1f A/m: B = %+.4f T, dB/dH = %.4g H/m (mu_r,diff = %.0f)\n", h_now,
                model.flux_density(state), model.tangent(state), model.tangent(state) / hyst::kMu0);
  }
  return ok ? 0 : 1;
}
