#include "hyst/models/everett_relay_grid.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

constexpr std::size_t kMaxLevels = 4096;

void validate_range(std::size_t levels, double lower, double upper, PreisachGridLayout layout) {
  if (levels == 0 || levels > kMaxLevels) {
    throw Error(fmt::format("Preisach levels N = {} must be in 1 .. {} (the Everett table has "
                            "(N+1)^2 entries)",
                            levels, kMaxLevels),
                "levels");
  }
  if (layout == PreisachGridLayout::endpoints && levels < 2) {
    throw Error("Preisach levels N = 1 must be >= 2 for the endpoints layout", "levels");
  }
  if (!std::isfinite(lower)) {
    throw Error(fmt::format("Preisach lower = {} is not finite", lower), "lower");
  }
  if (!std::isfinite(upper)) {
    throw Error(fmt::format("Preisach upper = {} is not finite", upper), "upper");
  }
  if (!(lower < upper)) {
    throw Error(fmt::format("Preisach upper = {} must be > lower = {}", upper, lower), "upper");
  }
}

}  // namespace

PreisachGridLayout preisach_grid_layout_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<PreisachGridLayout>, "Preisach grid layout",
                             "layout");
}

std::vector<double> preisach_thresholds(std::size_t levels, double lower, double upper,
                                        PreisachGridLayout layout) {
  validate_range(levels, lower, upper, layout);
  std::vector<double> c(levels);
  const double range = upper - lower;
  for (std::size_t k = 0; k < levels; ++k) {
    const auto kd = static_cast<double>(k);
    c[k] = layout == PreisachGridLayout::cell_centred
               ? lower + (kd + 0.5) * range / static_cast<double>(levels)
               : lower + range * kd / static_cast<double>(levels - 1);
  }
  for (std::size_t k = 1; k < levels; ++k) {
    if (!(c[k] > c[k - 1])) {
      throw Error(fmt::format("Preisach levels N = {} are too many for the range [{}, {}]: "
                              "neighbouring thresholds c[{}] and c[{}] are equal in double "
                              "precision",
                              levels, lower, upper, k - 1, k),
                  "levels");
    }
  }
  return c;
}

std::vector<double> uniform_relay_weights(std::size_t levels, double weight) {
  if (levels == 0 || levels > kMaxLevels) {
    throw Error(
        fmt::format("uniform relay weights: levels N = {} must be in 1 .. {}", levels, kMaxLevels));
  }
  if (!std::isfinite(weight) || weight < 0.0) {
    throw Error(fmt::format("uniform relay weight = {} must be finite and >= 0", weight));
  }
  return std::vector<double>(preisach_relay_count(levels), weight);
}

RelayGridEverett::RelayGridEverett(Params params) : params_(std::move(params)) {
  const std::size_t n = params_.levels;
  thresholds_ = preisach_thresholds(n, params_.lower, params_.upper, params_.layout);
  const auto& mu = params_.weights;
  if (mu.size() != preisach_relay_count(n)) {
    throw Error(fmt::format("Preisach has {} relay weights but N = {} levels need N(N+1)/2 = {}",
                            mu.size(), n, preisach_relay_count(n)),
                "weights");
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j <= i; ++j) {
      const std::size_t r = preisach_relay_index(i, j);
      if (!std::isfinite(mu[r])) {
        throw Error(fmt::format("Preisach relay weight mu[{}] (i = {}, j = {}) = {} is not finite",
                                r, i, j, mu[r]),
                    fmt::format("weights[{}]", r));
      }
      if (mu[r] < 0.0) {
        throw Error(fmt::format("Preisach relay weight mu[{}] (i = {}, j = {}) = {} must be >= 0",
                                r, i, j, mu[r]),
                    fmt::format("weights[{}]", r));
      }
    }
  }
  inverse_spacing_ =
      n > 1 ? static_cast<double>(n - 1) / (thresholds_[n - 1] - thresholds_[0]) : 0.0;
  diagonal_.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    diagonal_[k] = mu[preisach_relay_index(k, k)];

  // T(a, c) = T(a-1, c) + sum_{j=c}^{a-1} mu_{a-1, j} for c <= a-1, and 0 for c >= a.
  stride_ = n + 1;
  table_.assign(stride_ * stride_, 0.0);
  for (std::size_t a = 1; a <= n; ++a) {
    const std::size_t i = a - 1;
    double row_suffix = 0.0;
    for (std::size_t c = a; c-- > 0;) {
      row_suffix += mu[preisach_relay_index(i, c)];
      table_[a * stride_ + c] = table_[(a - 1) * stride_ + c] + row_suffix;
    }
  }
}

std::vector<double> RelayGridEverett::demagnetising_input() const {
  // s_k lies between c_{k-1} and c_k; rising to s_{N-k} switches up rows i <= N-k-1, falling to
  // s_k switches down columns j >= k. Alternating M_k = s_{N-k}, m_k = s_k leaves relay (i, j) at
  // +1 iff i + j <= N - 2.
  const std::size_t n = params_.levels;
  const auto separator = [this](std::size_t k) {
    return 0.5 * (thresholds_[k - 1] + thresholds_[k]);
  };
  std::vector<double> input;
  for (std::size_t k = 1; n - k > k - 1 && k < n; ++k) {
    input.push_back(separator(n - k));
    if (k >= n - k) break;
    input.push_back(separator(k));
  }
  return input;
}

}  // namespace hyst
