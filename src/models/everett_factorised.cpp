#include "hyst/models/everett_factorised.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/models/preisach_state.hpp"

namespace hyst {
namespace {

// 10-point Gauss-Legendre rule on [-1, 1] (nodes +-x_k, weights w_k).
constexpr std::array<double, 5> kGaussNodes{0.1488743389816312, 0.4333953941292472,
                                            0.6794095682990244, 0.8650633666889845,
                                            0.9739065285171717};
constexpr std::array<double, 5> kGaussWeights{0.2955242247147529, 0.2692667193099963,
                                              0.2190863625159820, 0.1494513491505806,
                                              0.0666713443086881};

constexpr std::size_t kPointsPerWidth = 256;
constexpr std::size_t kMinIntervals = 1024;
constexpr std::size_t kMaxIntervals = std::size_t{1} << 16;
constexpr std::size_t kDemagnetisingPairs = 64;

template <class Profile>
void validate(const typename FactorisedEverett<Profile>::Params& p) {
  const auto name = Profile::name;
  const auto finite = [&](double value, std::string_view field) {
    if (!std::isfinite(value)) {
      throw Error(fmt::format("{} Preisach {} = {} is not finite", name, field, value),
                  std::string(field));
    }
  };
  finite(p.lower, "lower");
  finite(p.upper, "upper");
  if (!(p.lower < p.upper)) {
    throw Error(fmt::format("{} Preisach upper = {} must be > lower = {}", name, p.upper, p.lower),
                "upper");
  }
  finite(p.saturation, "saturation");
  if (!(p.saturation > 0.0)) {
    throw Error(fmt::format("{} Preisach saturation = {} must be > 0", name, p.saturation),
                "saturation");
  }
  finite(p.alpha_centre, "alpha_centre");
  finite(p.alpha_width, "alpha_width");
  if (!(p.alpha_width > 0.0)) {
    throw Error(fmt::format("{} Preisach alpha_width = {} must be > 0", name, p.alpha_width),
                "alpha_width");
  }
  finite(p.beta_centre, "beta_centre");
  finite(p.beta_width, "beta_width");
  if (!(p.beta_width > 0.0)) {
    throw Error(fmt::format("{} Preisach beta_width = {} must be > 0", name, p.beta_width),
                "beta_width");
  }
}

}  // namespace

double GaussianProfile::density(double x) noexcept {
  return std::exp(-0.5 * x * x);
}
double GaussianProfile::integral(double x) noexcept {
  return std::sqrt(std::numbers::pi / 2) * std::erf(x / std::numbers::sqrt2);
}
double LorentzianProfile::density(double x) noexcept {
  return 1.0 / (1.0 + x * x);
}
double LorentzianProfile::integral(double x) noexcept {
  return std::atan(x);
}

template <class Profile>
FactorisedEverett<Profile>::FactorisedEverett(Params params) : params_(params) {
  validate<Profile>(params_);
  const Params& p = params_;
  f_at_lower_ = Profile::integral((p.lower - p.alpha_centre) / p.alpha_width);
  g_at_lower_ = Profile::integral((p.lower - p.beta_centre) / p.beta_width);

  const double range = p.upper - p.lower;
  const double wanted = std::ceil(static_cast<double>(kPointsPerWidth) * range /
                                  std::min(p.alpha_width, p.beta_width));
  intervals_ = static_cast<std::size_t>(
      std::clamp(wanted, static_cast<double>(kMinIntervals), static_cast<double>(kMaxIntervals)));
  const double step = range / static_cast<double>(intervals_);
  inverse_step_ = 1.0 / step;

  // H(t_m) = integral_lower^{t_m} f(a) G(a) da, accumulated with Neumaier's compensated sum.
  const auto integrand = [&](double a) {
    return Profile::density((a - p.alpha_centre) / p.alpha_width) * big_g(a);
  };
  const auto node = [&](std::size_t m) {
    return m == intervals_ ? p.upper : p.lower + static_cast<double>(m) * step;
  };
  nodes_.assign(kNodeStride * (intervals_ + 1), 0.0);
  double sum = 0.0;
  double compensation = 0.0;
  for (std::size_t m = 0; m <= intervals_; ++m) {
    const double t = node(m);
    double* n = &nodes_[kNodeStride * m];
    n[0] = sum + compensation;
    n[1] = step * integrand(t);
    n[2] = big_f(t);
    n[3] = step * Profile::density((t - p.alpha_centre) / p.alpha_width);
    n[4] = big_g(t);
    n[5] = step * Profile::density((t - p.beta_centre) / p.beta_width);
    if (m == intervals_) break;
    const double half = 0.5 * (node(m + 1) - t);
    const double centre = t + half;
    double piece = 0.0;
    for (std::size_t k = 0; k < kGaussNodes.size(); ++k) {
      piece += kGaussWeights[k] * (integrand(centre - half * kGaussNodes[k]) +
                                   integrand(centre + half * kGaussNodes[k]));
    }
    piece *= half;
    const double next = sum + piece;
    compensation += std::abs(sum) >= std::abs(piece) ? (sum - next) + piece : (piece - next) + sum;
    sum = next;
  }
  const double unscaled_total = nodes_[kNodeStride * intervals_];
  if (!(unscaled_total > 0.0) || !std::isfinite(unscaled_total)) {
    throw Error(
        fmt::format("{} Preisach density integrates to {} on the triangle lower = {} <= "
                    "beta <= alpha <= upper = {}: its centres (alpha_centre = {}, "
                    "beta_centre = {}) lie too far outside it for their widths",
                    Profile::name, unscaled_total, p.lower, p.upper, p.alpha_centre, p.beta_centre),
        "alpha_centre");
  }
  amplitude_ = p.saturation / unscaled_total;
}

template <class Profile>
double FactorisedEverett<Profile>::density(double alpha, double beta) const noexcept {
  const Params& p = params_;
  if (!(p.lower <= beta && beta <= alpha && alpha <= p.upper)) return 0.0;
  return amplitude_ * Profile::density((alpha - p.alpha_centre) / p.alpha_width) *
         Profile::density((beta - p.beta_centre) / p.beta_width);
}

template <class Profile>
std::vector<double> FactorisedEverett<Profile>::demagnetising_input() const {
  return preisach_midpoint_staircase(params_.lower, params_.upper, kDemagnetisingPairs);
}

template class FactorisedEverett<GaussianProfile>;
template class FactorisedEverett<LorentzianProfile>;

}  // namespace hyst
