#include "hyst/models/everett_table.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/models/preisach_state.hpp"

namespace hyst {
namespace {

constexpr std::size_t kDemagnetisingPairs = 64;
constexpr double kWeightSlack = 1e-10;

}  // namespace

TabulatedEverett::TabulatedEverett(Params params) : params_(std::move(params)) {
  const auto& x = params_.levels;
  const auto& e = params_.values;
  if (x.size() < 2) {
    throw Error(
        fmt::format("tabulated Everett function has {} levels x; it needs at least 2", x.size()),
        "levels");
  }
  for (std::size_t a = 0; a < x.size(); ++a) {
    if (!std::isfinite(x[a])) {
      throw Error(fmt::format("tabulated Everett level x[{}] = {} is not finite", a, x[a]),
                  fmt::format("levels[{}]", a));
    }
    if (a > 0 && !(x[a] > x[a - 1])) {
      throw Error(fmt::format("tabulated Everett level x[{}] = {} must be > x[{}] = {}", a, x[a],
                              a - 1, x[a - 1]),
                  fmt::format("levels[{}]", a));
    }
  }
  k_ = x.size() - 1;
  stride_ = k_ + 1;
  const std::size_t expected = k_ * (k_ + 1) / 2;
  if (e.size() != expected) {
    throw Error(fmt::format("tabulated Everett function has {} values but K + 1 = {} levels need "
                            "K(K+1)/2 = {} (E(x_a, x_c) for c < a)",
                            e.size(), x.size(), expected),
                "values");
  }
  double largest = 0.0;
  for (std::size_t a = 1; a <= k_; ++a) {
    for (std::size_t c = 0; c < a; ++c) {
      const std::size_t index = everett_table_index(a, c);
      if (!std::isfinite(e[index])) {
        throw Error(fmt::format("tabulated Everett value E[{},{}] (values[{}]) = {} is not finite",
                                a, c, index, e[index]),
                    fmt::format("values[{}]", index));
      }
      largest = std::max(largest, std::abs(e[index]));
    }
  }
  grid_.assign(stride_ * stride_, 0.0);
  for (std::size_t a = 1; a <= k_; ++a) {
    for (std::size_t c = 0; c < a; ++c)
      grid_[a * stride_ + c] = e[everett_table_index(a, c)];
  }
  const auto at = [&](std::size_t a, std::size_t c) { return grid_[a * stride_ + c]; };
  const double slack = kWeightSlack * largest;
  for (std::size_t i = 0; i < k_; ++i) {
    const double diagonal = at(i + 1, i);
    if (diagonal < -slack) {
      throw Error(fmt::format("tabulated Everett cell weight mu({0}, {0}) = E[{1},{0}] = {2} must "
                              "be >= 0",
                              i, i + 1, diagonal),
                  fmt::format("values[{}]", everett_table_index(i + 1, i)));
    }
    for (std::size_t j = 0; j < i; ++j) {
      const double mu = at(i + 1, j) - at(i, j) - at(i + 1, j + 1) + at(i, j + 1);
      if (mu < -slack) {
        throw Error(fmt::format("tabulated Everett cell weight mu({0}, {1}) = E[{2},{1}] - "
                                "E[{0},{1}] - E[{2},{3}] + E[{0},{3}] = {4} must be >= 0",
                                i, j, i + 1, j + 1, mu),
                    fmt::format("values[{}]", everett_table_index(i + 1, j)));
      }
    }
  }
  inverse_width_.resize(k_);
  for (std::size_t i = 0; i < k_; ++i)
    inverse_width_[i] = 1.0 / (x[i + 1] - x[i]);
  total_ = at(k_, 0);
  inverse_spacing_ = static_cast<double>(k_) / (x[k_] - x[0]);
}

std::size_t TabulatedEverett::cell(double u) const noexcept {
  const auto& x = params_.levels;
  if (inverse_spacing_ > 0.0) {
    // Nearly uniform levels: guess, then step to the right cell (one step at most, unless the
    // levels are uneven, when the binary search below takes over).
    const double g = (u - x[0]) * inverse_spacing_;
    std::size_t i = g > 0.0 ? static_cast<std::size_t>(g) : 0;
    if (i >= k_) i = k_ - 1;
    if (u < x[i] && i > 0) --i;
    if (u > x[i + 1] && i + 1 < k_) ++i;
    if (x[i] <= u && u <= x[i + 1]) return i;
  }
  const auto above = std::upper_bound(x.begin(), x.end(), u);
  const auto i = static_cast<std::size_t>(above - x.begin());
  return i == 0 ? 0 : std::min(i - 1, k_ - 1);
}

TabulatedEverett::Stencil TabulatedEverett::stencil(double alpha, double beta) const noexcept {
  Stencil result;
  const double* x = params_.levels.data();
  const double a = std::clamp(alpha, x[0], x[k_]);
  const double b = std::clamp(beta, x[0], x[k_]);
  if (!(a > b)) return result;
  const std::size_t i = cell(a);
  const std::size_t j = cell(b);
  const double s = (a - x[i]) * inverse_width_[i];
  const double t = (b - x[j]) * inverse_width_[j];
  const auto add = [&](std::size_t level_a, std::size_t level_c, double weight) {
    if (level_a <= level_c) return;
    result.alpha_level[result.size] = level_a;
    result.beta_level[result.size] = level_c;
    result.weight[result.size] = weight;
    ++result.size;
  };
  if (i == j) {
    add(i + 1, i, s - t);
    return result;
  }
  add(i, j, (1 - s) * (1 - t));
  add(i, j + 1, (1 - s) * t);
  add(i + 1, j, s * (1 - t));
  add(i + 1, j + 1, s * t);
  return result;
}

std::vector<double> TabulatedEverett::demagnetising_input() const {
  return preisach_midpoint_staircase(lower(), upper(), kDemagnetisingPairs);
}

}  // namespace hyst
