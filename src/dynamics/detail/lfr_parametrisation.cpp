#include "lfr_parametrisation.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/dynamics/fit_hysteretic_lfr.hpp"

namespace hyst::detail {

std::vector<PrandtlIshlinskii> pi_blocks(const std::vector<std::vector<double>>& thresholds,
                                         const double* weights) {
  std::vector<PrandtlIshlinskii> blocks;
  for (const auto& r : thresholds) {
    std::vector<double> w{1.0};
    w.insert(w.end(), weights, weights + r.size() - 1);
    weights += r.size() - 1;
    blocks.emplace_back(PrandtlIshlinskii::Params{r, std::move(w), 0.0});
  }
  return blocks;
}

std::vector<WeightDerivative> pi_weight_derivatives(Eigen::Index channels, Eigen::Index plays,
                                                    Eigen::Index offset) {
  std::vector<WeightDerivative> result;
  for (Eigen::Index i = 0; i < channels; ++i)
    for (Eigen::Index l = 1; l < plays; ++l)
      result.push_back({offset++, i, l});
  return result;
}

void check_threshold_fractions(const std::vector<double>& r, const std::string& fit) {
  if (r.size() > kMaxThresholdFractions)
    throw Error(fmt::format("{}: {} threshold_fractions are above the limit of {}", fit, r.size(),
                            kMaxThresholdFractions),
                "threshold_fractions");
  if (r.empty() || r[0] != 0.0)
    throw Error(fit + ": threshold_fractions must start at 0", "threshold_fractions");
  for (std::size_t j = 1; j < r.size(); ++j)
    if (!std::isfinite(r[j]) || !(r[j] > r[j - 1]))
      throw Error(fmt::format("{}: threshold_fractions[{}] = {} must be finite and above the one "
                              "before",
                              fit, j, r[j]),
                  fmt::format("threshold_fractions[{}]", j));
}

}  // namespace hyst::detail
