#pragma once
// Periodic experiments for the dynamics tests: random-phase multisines and systems simulated by
// direct recursion (independent of hyst::StateSpace), in periodic steady state.

#include <cmath>
#include <complex>
#include <cstdint>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "hyst/dynamics/best_linear_approximation.hpp"

namespace hyst::test {

// One period of sum_k cos(2 pi k n / N + phi_k) over lines 1..max_line, random phases.
inline std::vector<double> random_phase_multisine(std::size_t samples, std::size_t max_line,
                                                  std::mt19937_64& random) {
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  std::vector<double> out(samples, 0.0);
  for (std::size_t k = 1; k <= max_line; ++k) {
    const double phi = phase(random);
    for (std::size_t n = 0; n < samples; ++n)
      out[n] += std::cos(2.0 * std::numbers::pi * double(k * n) / double(samples) + phi);
  }
  return out;
}

// A discrete MIMO system advanced one sample by `step(x, u) -> y` (x updated in place).
using SystemStep = std::function<Eigen::VectorXd(Eigen::VectorXd& x, const Eigen::VectorXd& u)>;

// `realisations` random-phase multisines on every input (independent phases), `periods` periods
// recorded after `settle` periods from rest; `noise` adds white Gaussian noise of that standard
// deviation to the outputs.
inline PeriodicExperiment periodic_experiment(const SystemStep& step, std::size_t states,
                                              std::size_t inputs, std::size_t outputs,
                                              std::size_t samples, std::size_t max_line,
                                              std::size_t realisations, std::size_t periods,
                                              std::uint64_t seed, double noise = 0.0,
                                              std::size_t settle = 20) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gauss(0.0, noise > 0.0 ? noise : 1.0);
  PeriodicExperiment e;
  e.input = {samples, inputs, realisations, periods, {}};
  e.output = {samples, outputs, realisations, periods, {}};
  e.input.values.resize(samples * inputs * realisations * periods);
  e.output.values.resize(samples * outputs * realisations * periods);
  for (std::size_t r = 0; r < realisations; ++r) {
    std::vector<std::vector<double>> u(inputs);
    for (auto& channel : u)
      channel = random_phase_multisine(samples, max_line, random);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(Eigen::Index(states));
    Eigen::VectorXd input = Eigen::VectorXd::Zero(Eigen::Index(inputs));
    for (std::size_t p = 0; p < settle + periods; ++p)
      for (std::size_t n = 0; n < samples; ++n) {
        for (std::size_t c = 0; c < inputs; ++c)
          input[Eigen::Index(c)] = u[c][n];
        const Eigen::VectorXd y = step(x, input);
        if (p < settle) continue;
        for (std::size_t c = 0; c < inputs; ++c)
          e.input(n, c, r, p - settle) = u[c][n];
        for (std::size_t c = 0; c < outputs; ++c)
          e.output(n, c, r, p - settle) = y[Eigen::Index(c)] + (noise > 0.0 ? gauss(random) : 0.0);
      }
  }
  return e;
}

// Two decoupled first-order lags with cross-coupling: y1 = x1 + 0.5 u2, y2 = x2,
// x1+ = a1 x1 + u1, x2+ = a2 x2 + u1 + u2. Its response in closed form below.
inline constexpr double kPole1 = 0.9;
inline constexpr double kPole2 = -0.5;
inline Eigen::VectorXd two_lags(Eigen::VectorXd& x, const Eigen::VectorXd& u) {
  Eigen::VectorXd y(2);
  y << x[0] + 0.5 * u[1], x[1];
  const Eigen::VectorXd next =
      (Eigen::VectorXd(2) << kPole1 * x[0] + u[0], kPole2 * x[1] + u[0] + u[1]).finished();
  x = next;
  return y;
}
inline Eigen::MatrixXcd two_lags_response(std::complex<double> z) {
  Eigen::MatrixXcd g(2, 2);
  g << 1.0 / (z - kPole1), 0.5, 1.0 / (z - kPole2), 1.0 / (z - kPole2);
  return g;
}

}  // namespace hyst::test
