#pragma once
// The generalized PI parameter sets and signals of the reference checks (pi_check.py,
// msma_synth.py, gpi_forms_check.py), shared by the GPI, inverse GPI and fit tests.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "hyst/models/generalized_prandtl_ishlinskii.hpp"

namespace hyst::test {

// pi_check.py: a = (2, 0.8, -0.1, 0.05), b = (2, 0.8, 0.25, 0.05), rho = 0.6, tau = 0.9,
// alpha = 0.12, m = 8. Operating range [-3, 3] (the IGPI inputs stay within +-2.2).
inline GpiParams pi_check_params() {
  return {.envelope = EnvelopeKind::tanh,
          .ascending = {2.0, 0.8, -0.1, 0.05},
          .descending = {2.0, 0.8, 0.25, 0.05},
          .density = GpiDensity::exponential,
          .rho = 0.6,
          .tau = 0.9,
          .alpha = 0.12,
          .m = 8,
          .input_min = -3.0,
          .input_max = 3.0,
          .initial_input = 0.0};
}

// [ASSUMED] MSMA-like set of msma_synth.py: current 0..8 A -> force N.
// a = (40, 0.8, -3.2, 40), b = (40, 0.8, -2.8, 40), rho = 0.143, tau = 0.1, alpha = 1, m = 10.
inline GpiParams msma_params() {
  return {.envelope = EnvelopeKind::tanh,
          .ascending = {40.0, 0.8, -3.2, 40.0},
          .descending = {40.0, 0.8, -2.8, 40.0},
          .density = GpiDensity::exponential,
          .rho = 0.143,
          .tau = 0.1,
          .alpha = 1.0,
          .m = 10,
          .input_min = 0.0,
          .input_max = 8.0,
          .initial_input = 0.0};
}

// pi_check.py desired output: y_d = 1.2 sin(2 pi k/1000)(0.55 + 0.45 cos(2 pi k/2500)), k < 4000.
inline std::vector<double> pi_check_gpi_target() {
  std::vector<double> y(4000);
  for (std::size_t k = 0; k < y.size(); ++k) {
    const double t = static_cast<double>(k);
    y[k] = 1.2 * std::sin(2 * std::numbers::pi * t / 1000) *
           (0.55 + 0.45 * std::cos(2 * std::numbers::pi * t / 2500));
  }
  return y;
}

// pi_check.py input for comparing the forward forms:
// v = 2 sin(2 pi k/1000)(0.6 + 0.4 cos(2 pi k/2300)), k < 4000.
inline std::vector<double> pi_check_gpi_input() {
  std::vector<double> v(4000);
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double t = static_cast<double>(k);
    v[k] = 2.0 * std::sin(2 * std::numbers::pi * t / 1000) *
           (0.6 + 0.4 * std::cos(2 * std::numbers::pi * t / 2300));
  }
  return v;
}

// msma_synth.py current: i = 4 - 4 cos(2 pi k/1000) (1 if k < 2000 else 0.5), k < 4000 [A].
inline std::vector<double> msma_current() {
  std::vector<double> i(4000);
  for (std::size_t k = 0; k < i.size(); ++k) {
    const double t = static_cast<double>(k);
    i[k] = 4.0 - 4.0 * std::cos(2 * std::numbers::pi * t / 1000) * (k < 2000 ? 1.0 : 0.5);
  }
  return i;
}

// msma_synth.py desired force: F_d = 50 + 25 sin(2 pi k/1000) (1 if k < 2000 else 0.4) [N].
inline std::vector<double> msma_force_target() {
  std::vector<double> f(4000);
  for (std::size_t k = 0; k < f.size(); ++k) {
    const double t = static_cast<double>(k);
    f[k] = 50.0 + 25.0 * std::sin(2 * std::numbers::pi * t / 1000) * (k < 2000 ? 1.0 : 0.4);
  }
  return f;
}

inline double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    worst = std::max(worst, std::abs(a[k] - b[k]));
  return worst;
}

// Samples where the output moves against the input by more than 1e-12 (pi_check.py's count).
inline int against_input_moves(const std::vector<double>& v, const std::vector<double>& y) {
  int count = 0;
  for (std::size_t k = 1; k < v.size(); ++k) {
    if ((v[k] - v[k - 1]) * (y[k] - y[k - 1]) < -1e-12) ++count;
  }
  return count;
}

}  // namespace hyst::test
