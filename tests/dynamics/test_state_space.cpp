// The discrete MIMO state-space model against values found another way: zero-order holds in
// closed form and by Runge-Kutta integration, a simulation by hand, periodic states by running
// many periods, frequency responses in closed form, by a dense solve and by the DFT of the
// periodic response, poles placed by construction; step() without allocation; every validation
// message.

#include "hyst/dynamics/state_space.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"
#include "../support/expect_error.hpp"

namespace hyst::state_space_test {
namespace {

using Complex = std::complex<double>;
using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd random_matrix(Eigen::Index rows, Eigen::Index cols, std::mt19937_64& random) {
  std::normal_distribution<double> gauss;
  MatrixXd m(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i)
      m(i, j) = gauss(random);
  return m;
}

// The poles r_i exp(+-j theta_i) of a random stable model of even order.
std::vector<Complex> pole_pairs(std::size_t pairs, std::mt19937_64& random) {
  std::uniform_real_distribution<double> radius(0.5, 0.95);
  std::uniform_real_distribution<double> angle(0.1, 3.0);
  std::vector<Complex> poles;
  for (std::size_t i = 0; i < pairs; ++i)
    poles.push_back(std::polar(radius(random), angle(random)));
  return poles;
}

// A = Q blockdiag(r_i R(theta_i)) Q^T with a random orthogonal Q: the poles are known, the matrix
// dense. B, C, D random.
StateSpace random_stable_model(const std::vector<Complex>& pole_pairs, Eigen::Index inputs,
                               Eigen::Index outputs, std::mt19937_64& random,
                               double sample_time = 1e-3) {
  const auto n = Eigen::Index(2 * pole_pairs.size());
  MatrixXd blocks = MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < Eigen::Index(pole_pairs.size()); ++i) {
    const Complex p = pole_pairs[std::size_t(i)];
    blocks.block(2 * i, 2 * i, 2, 2) << p.real(), -p.imag(), p.imag(), p.real();
  }
  const MatrixXd q = random_matrix(n, n, random).householderQr().householderQ();
  return StateSpace({q * blocks * q.transpose(), random_matrix(n, inputs, random),
                     random_matrix(outputs, n, random), random_matrix(outputs, inputs, random),
                     sample_time});
}

MatrixXd random_input(Eigen::Index samples, Eigen::Index inputs, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  return random_matrix(samples, inputs, random);
}

double max_abs_difference(const MatrixXd& a, const MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

// ---------------------------------------------------------------- zero-order hold

TEST(StateSpaceZoh, FirstOrderMatchesTheClosedForm) {
  // dx/dt = -a x + b u: A = exp(-a Ts), B = b (1 - exp(-a Ts)) / a.
  const double a = 2.5;
  const double b = 3.0;
  const double ts = 0.1;
  const auto model = StateSpace::from_continuous(
      MatrixXd::Constant(1, 1, -a), MatrixXd::Constant(1, 1, b), MatrixXd::Constant(1, 1, 1.0),
      MatrixXd::Constant(1, 1, 0.25), ts);
  EXPECT_NEAR(model.params().a(0, 0), std::exp(-a * ts), 1e-15);
  EXPECT_NEAR(model.params().b(0, 0), b * (1.0 - std::exp(-a * ts)) / a, 1e-15);
  EXPECT_EQ(model.params().c(0, 0), 1.0);
  EXPECT_EQ(model.params().d(0, 0), 0.25);
  EXPECT_EQ(model.sample_time(), ts);
}

// x'' + 2 zeta w x' + w^2 x = u, state (x, x').
struct Oscillator {
  double w = 30.0;
  double zeta = 0.05;
  MatrixXd ac() const { return (MatrixXd(2, 2) << 0.0, 1.0, -w * w, -2.0 * zeta * w).finished(); }
  MatrixXd bc() const { return (MatrixXd(2, 1) << 0.0, 1.0).finished(); }
};

TEST(StateSpaceZoh, OscillatorMatchesTheClosedForm) {
  // Poles -s +- j wd: exp(Ac t) = e^(-s t) (cos(wd t) I + sin(wd t) / wd (Ac + s I)), and
  // B = Ac^-1 (A - I) Bc with Ac^-1 = [[-2 s, -1], [w^2, 0]] / w^2.
  const Oscillator o;
  const double ts = 0.01;
  const double s = o.zeta * o.w;
  const double wd = o.w * std::sqrt(1.0 - o.zeta * o.zeta);
  const MatrixXd identity = MatrixXd::Identity(2, 2);
  const MatrixXd a = std::exp(-s * ts) * (std::cos(wd * ts) * identity +
                                          std::sin(wd * ts) / wd * (o.ac() + s * identity));
  const MatrixXd ac_inverse =
      (MatrixXd(2, 2) << -2.0 * s, -1.0, o.w * o.w, 0.0).finished() / (o.w * o.w);
  const MatrixXd b = ac_inverse * (a - identity) * o.bc();
  const auto model =
      StateSpace::from_continuous(o.ac(), o.bc(), identity, MatrixXd::Zero(2, 1), ts);
  EXPECT_LT(max_abs_difference(model.params().a, a), 1e-14);
  EXPECT_LT(max_abs_difference(model.params().b, b), 1e-16);  // B is of order 1e-4
}

// Classical RK4 of dx/dt = Ac x + Bc u over one sample with u held.
VectorXd rk4_over_sample(const Oscillator& o, VectorXd x, double u, double ts, int substeps) {
  const double h = ts / substeps;
  const MatrixXd ac = o.ac();
  const VectorXd bu = o.bc() * u;
  const auto f = [&](const VectorXd& v) -> VectorXd { return ac * v + bu; };
  for (int i = 0; i < substeps; ++i) {
    const VectorXd k1 = f(x);
    const VectorXd k2 = f(x + 0.5 * h * k1);
    const VectorXd k3 = f(x + 0.5 * h * k2);
    const VectorXd k4 = f(x + h * k3);
    x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return x;
}

TEST(StateSpaceZoh, OscillatorMatchesRungeKuttaUnderAHeldInput) {
  const Oscillator o;
  const double ts = 0.01;
  const MatrixXd u = random_input(60, 1, 3);
  const auto model = StateSpace::from_continuous(o.ac(), o.bc(), MatrixXd::Identity(2, 2),
                                                 MatrixXd::Zero(2, 1), ts);
  const MatrixXd y = model.simulate(u);
  VectorXd x = VectorXd::Zero(2);
  double scale = 0.0;
  double worst = 0.0;
  for (Eigen::Index k = 0; k < u.rows(); ++k) {
    worst = std::max(worst, (y.row(k).transpose() - x).cwiseAbs().maxCoeff());
    scale = std::max(scale, x.cwiseAbs().maxCoeff());
    x = rk4_over_sample(o, x, u(k, 0), ts, 200);
  }
  EXPECT_GT(scale, 1e-3);
  EXPECT_LT(worst, 1e-11 * scale);
}

TEST(StateSpaceZoh, IntegratorNeedsNoInverseOfAc) {
  // dx/dt = u1 + 2 u2 (Ac = 0, singular): A = 1, B = Ts [1, 2].
  const auto model =
      StateSpace::from_continuous(MatrixXd::Zero(1, 1), (MatrixXd(1, 2) << 1.0, 2.0).finished(),
                                  MatrixXd::Ones(1, 1), MatrixXd::Zero(1, 2), 0.5);
  EXPECT_DOUBLE_EQ(model.params().a(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(model.params().b(0, 0), 0.5);
  EXPECT_DOUBLE_EQ(model.params().b(0, 1), 1.0);
  EXPECT_EQ(model.inputs(), 2u);
  EXPECT_EQ(model.outputs(), 1u);
}

// ---------------------------------------------------------------- simulate

// A = [[0.5, 0.1], [0, 0.8]], B = [[1, 0], [0.5, 1]], C = [[1, 2], [0, -1]], D = diag(0.1, 0.2).
StateSpace two_state_example() {
  return StateSpace({(MatrixXd(2, 2) << 0.5, 0.1, 0.0, 0.8).finished(),
                     (MatrixXd(2, 2) << 1.0, 0.0, 0.5, 1.0).finished(),
                     (MatrixXd(2, 2) << 1.0, 2.0, 0.0, -1.0).finished(),
                     (MatrixXd(2, 2) << 0.1, 0.0, 0.0, 0.2).finished(), 1.0});
}

TEST(StateSpaceSimulate, HandComputedTwoStateExample) {
  // u0 = (1, 0): y0 = D u0 = (0.1, 0),            x1 = B u0 = (1, 0.5)
  // u1 = (0, 1): y1 = (1 + 1, -0.5) + (0, 0.2),   x2 = (0.55, 0.4) + (0, 1) = (0.55, 1.4)
  // u2 = (2, -1): y2 = (0.55 + 2.8, -1.4) + (0.2, -0.2), x3 = (0.415, 1.12) + (2, 0)
  const auto model = two_state_example();
  const MatrixXd u = (MatrixXd(3, 2) << 1.0, 0.0, 0.0, 1.0, 2.0, -1.0).finished();
  auto state = model.initial_state();
  const MatrixXd y = model.simulate(u, state);
  const MatrixXd expected = (MatrixXd(3, 2) << 0.1, 0.0, 2.0, -0.3, 3.55, -1.6).finished();
  EXPECT_LT(max_abs_difference(y, expected), 1e-14);
  EXPECT_LT(max_abs_difference(state.x, (VectorXd(2) << 2.415, 1.12).finished()), 1e-14);
  EXPECT_EQ(model.simulate(u), y);  // from rest
}

TEST(StateSpaceSimulate, ContinuesFromTheGivenState) {
  std::mt19937_64 random(4);
  const auto model = random_stable_model(pole_pairs(3, random), 2, 3, random);
  const MatrixXd u = random_input(100, 2, 5);
  auto whole = model.initial_state();
  const MatrixXd y = model.simulate(u, whole);
  auto parts = model.initial_state();
  const MatrixXd first = model.simulate(u.topRows(40), parts);
  const MatrixXd second = model.simulate(u.bottomRows(60), parts);
  EXPECT_EQ(first, y.topRows(40));
  EXPECT_EQ(second, y.bottomRows(60));
  EXPECT_EQ(parts.x, whole.x);
  EXPECT_EQ(model.simulate(MatrixXd(0, 2)).rows(), 0);
}

TEST(StateSpaceSimulate, StaticGainWithoutStates) {
  const MatrixXd d = (MatrixXd(2, 3) << 1.0, 2.0, 3.0, -1.0, 0.5, 0.0).finished();
  const StateSpace model({MatrixXd(0, 0), MatrixXd(0, 3), MatrixXd(2, 0), d, 0.1});
  EXPECT_EQ(model.order(), 0u);
  const MatrixXd u = random_input(7, 3, 6);
  EXPECT_LT(max_abs_difference(model.simulate(u), u * d.transpose()), 1e-15);
  EXPECT_EQ(model.periodic_state(u).size(), 0);
  EXPECT_LT(max_abs_difference(model.simulate_periodic(u), u * d.transpose()), 1e-15);
}

// ---------------------------------------------------------------- periodic state

TEST(StateSpacePeriodic, StateReturnsAfterOnePeriod) {
  std::mt19937_64 random(7);
  const auto model = random_stable_model(pole_pairs(4, random), 2, 2, random);
  const MatrixXd u = random_input(50, 2, 8);
  const VectorXd x0 = model.periodic_state(u);
  auto state = model.make_state(x0);
  model.simulate(u, state);
  EXPECT_LT((state.x - x0).cwiseAbs().maxCoeff(), 1e-12 * x0.cwiseAbs().maxCoeff());
}

TEST(StateSpacePeriodic, EqualsTheStateAfterManyPeriods) {
  // Spectral radius <= 0.95: after 40 periods of 50 samples the transient is 0.95^2000 ~ 1e-45.
  std::mt19937_64 random(9);
  const auto model = random_stable_model(pole_pairs(3, random), 1, 2, random);
  const MatrixXd u = random_input(50, 1, 10);
  auto state = model.initial_state();
  for (int period = 0; period < 40; ++period)
    model.simulate(u, state);
  const VectorXd x0 = model.periodic_state(u);
  EXPECT_LT((state.x - x0).cwiseAbs().maxCoeff(), 1e-12 * x0.cwiseAbs().maxCoeff());
}

TEST(StateSpacePeriodic, SimulatePeriodicIsTheSteadyState) {
  std::mt19937_64 random(11);
  const auto model = random_stable_model(pole_pairs(2, random), 2, 1, random);
  const MatrixXd u = random_input(30, 2, 12);
  auto state = model.make_state(model.periodic_state(u));
  const MatrixXd first = model.simulate(u, state);
  const MatrixXd second = model.simulate(u, state);
  EXPECT_EQ(model.simulate_periodic(u), first);
  EXPECT_LT(max_abs_difference(first, second), 1e-12 * first.cwiseAbs().maxCoeff());
}

TEST(StateSpacePeriodic, IntegratorHasNoUniquePeriodicState) {
  const StateSpace integrator({MatrixXd::Ones(1, 1), MatrixXd::Ones(1, 1), MatrixXd::Ones(1, 1),
                               MatrixXd::Zero(1, 1), 1.0});
  const MatrixXd ramp = MatrixXd::Ones(8, 1);  // a mean: no periodic state
  EXPECT_HYST_ERROR(integrator.periodic_state(ramp),
                    "state space: no unique periodic state for a period of 8 samples: I - A^8 is "
                    "singular");
  EXPECT_HYST_ERROR(integrator.periodic_state(ramp), "an integrator's pole at z = 1");
  MatrixXd zero_mean = MatrixXd::Ones(8, 1);  // every constant is periodic: none is unique
  zero_mean.bottomRows(4) *= -1.0;
  EXPECT_HYST_ERROR(integrator.simulate_periodic(zero_mean), "no unique periodic state");
}

TEST(StateSpacePeriodic, UndampedOscillationWithWholeCyclesHasNone) {
  // A rotation by 2 pi / 10: over 20 samples, two whole turns, A^20 = I up to rounding.
  const double t = 2.0 * std::numbers::pi / 10.0;
  const MatrixXd a =
      (MatrixXd(2, 2) << std::cos(t), -std::sin(t), std::sin(t), std::cos(t)).finished();
  const StateSpace model(
      {a, MatrixXd::Ones(2, 1), MatrixXd::Ones(1, 2), MatrixXd::Zero(1, 1), 1.0});
  EXPECT_HYST_ERROR(model.periodic_state(random_input(20, 1, 13)), "root of unity z^20 = 1");
  EXPECT_NO_THROW(model.periodic_state(random_input(23, 1, 13)));  // no whole number of turns
}

TEST(StateSpacePeriodic, RejectsAnEmptyPeriod) {
  EXPECT_HYST_ERROR(two_state_example().periodic_state(MatrixXd(0, 2)),
                    "state space: the period has no sample");
}

// ---------------------------------------------------------------- frequency response

TEST(StateSpaceFrequencyResponse, FirstOrderClosedForm) {
  // G(z) = b / (z - a) + d with c = 1.
  const double a = 0.8;
  const double b = 0.3;
  const double d = -0.2;
  const double ts = 0.5;
  const StateSpace model({MatrixXd::Constant(1, 1, a), MatrixXd::Constant(1, 1, b),
                          MatrixXd::Constant(1, 1, 1.0), MatrixXd::Constant(1, 1, d), ts});
  const std::vector<double> f{0.0, 0.01, 0.1, 0.37, 0.9, 1.0, -0.2};
  const auto g = model.frequency_response(f);
  ASSERT_EQ(g.size(), f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Complex z = std::polar(1.0, 2.0 * std::numbers::pi * f[i] * ts);
    ASSERT_EQ(g[i].rows(), 1);
    ASSERT_EQ(g[i].cols(), 1);
    EXPECT_LT(std::abs(g[i](0, 0) - (b / (z - a) + d)), 1e-15) << "f = " << f[i];
  }
  EXPECT_NEAR(g[0](0, 0).real(), b / (1.0 - a) + d, 1e-15);  // the static gain
  EXPECT_TRUE(model.frequency_response({}).empty());
}

TEST(StateSpaceFrequencyResponse, MatchesADenseSolve) {
  // The Hessenberg solve (row swaps included) against C (zI - A)^-1 B + D by a dense LU.
  std::mt19937_64 random(14);
  const auto model = random_stable_model(pole_pairs(20, random), 3, 2, random, 2e-4);
  const auto& p = model.params();
  std::vector<double> f;
  for (int i = 0; i <= 50; ++i)
    f.push_back(50.0 * i);  // up to the Nyquist frequency, 2500 Hz
  const auto g = model.frequency_response(f);
  const auto n = p.a.rows();
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Complex z = std::polar(1.0, 2.0 * std::numbers::pi * f[i] * p.sample_time);
    const Eigen::MatrixXcd shifted = z * Eigen::MatrixXcd::Identity(n, n) - p.a.cast<Complex>();
    const Eigen::MatrixXcd expected =
        p.c.cast<Complex>() * shifted.partialPivLu().solve(p.b.cast<Complex>()) +
        p.d.cast<Complex>();
    EXPECT_LT((g[i] - expected).norm(), 1e-12 * expected.norm()) << "f = " << f[i];
  }
}

TEST(StateSpaceFrequencyResponse, MimoMatchesTheDftOfThePeriodicResponse) {
  // A cosine at line k of an N-sample period on input j: in periodic steady state, the DFT of
  // the outputs at line k divided by the input's (N / 2) is column j of G at f = k / (N Ts).
  std::mt19937_64 random(15);
  const double ts = 1e-3;
  const auto model = random_stable_model(pole_pairs(3, random), 2, 3, random, ts);
  const Eigen::Index samples = 64;
  for (const Eigen::Index line : {1, 5, 17, 31}) {
    const double f = double(line) / (double(samples) * ts);
    const Eigen::MatrixXcd g = model.frequency_response(std::vector<double>{f})[0];
    for (Eigen::Index j = 0; j < 2; ++j) {
      MatrixXd u = MatrixXd::Zero(samples, 2);
      for (Eigen::Index n = 0; n < samples; ++n)
        u(n, j) = std::cos(2.0 * std::numbers::pi * double(line * n) / double(samples));
      const MatrixXd y = model.simulate_periodic(u);
      Eigen::VectorXcd dft = Eigen::VectorXcd::Zero(3);
      for (Eigen::Index n = 0; n < samples; ++n)
        dft += y.row(n).transpose().cast<Complex>() *
               std::polar(1.0, -2.0 * std::numbers::pi * double(line * n) / double(samples));
      const Eigen::VectorXcd measured = dft / (double(samples) / 2.0);
      EXPECT_LT((measured - g.col(j)).norm(), 1e-10 * g.col(j).norm())
          << "line " << line << ", input " << j;
    }
  }
}

TEST(StateSpaceFrequencyResponse, StaticGainIsD) {
  const MatrixXd d = (MatrixXd(1, 2) << 3.0, -4.0).finished();
  const StateSpace model({MatrixXd(0, 0), MatrixXd(0, 2), MatrixXd(1, 0), d, 1.0});
  const auto g = model.frequency_response(std::vector<double>{0.0, 0.25});
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[1], d.cast<Complex>());
}

// ---------------------------------------------------------------- poles

TEST(StateSpacePoles, AreThoseOfTheBlocksAfterASimilarity) {
  std::mt19937_64 random(16);
  const auto pairs = pole_pairs(5, random);
  const auto model = random_stable_model(pairs, 1, 1, random);
  const Eigen::VectorXcd poles = model.poles();
  ASSERT_EQ(poles.size(), 10);
  double radius = 0.0;
  for (const Complex p : pairs) {
    radius = std::max(radius, std::abs(p));
    for (const Complex expected : {p, std::conj(p)}) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Complex found : poles)
        nearest = std::min(nearest, std::abs(found - expected));
      EXPECT_LT(nearest, 1e-12) << expected;
    }
  }
  EXPECT_NEAR(model.spectral_radius(), radius, 1e-12);
  EXPECT_TRUE(model.is_stable());
}

TEST(StateSpacePoles, StabilityAndSpectralRadius) {
  const auto diagonal = [](double p1, double p2) {
    return StateSpace({(MatrixXd(2, 2) << p1, 0.0, 0.0, p2).finished(), MatrixXd::Ones(2, 1),
                       MatrixXd::Ones(1, 2), MatrixXd::Zero(1, 1), 1.0});
  };
  EXPECT_DOUBLE_EQ(diagonal(0.5, -0.9).spectral_radius(), 0.9);
  EXPECT_TRUE(diagonal(0.5, -0.9).is_stable());
  EXPECT_FALSE(diagonal(0.5, -1.01).is_stable());
  EXPECT_FALSE(diagonal(1.0, 0.0).is_stable());  // an integrator: on the circle, not inside
  const StateSpace gain(
      {MatrixXd(0, 0), MatrixXd(0, 1), MatrixXd(1, 0), MatrixXd::Ones(1, 1), 1.0});
  EXPECT_EQ(gain.poles().size(), 0);
  EXPECT_EQ(gain.spectral_radius(), 0.0);
  EXPECT_TRUE(gain.is_stable());
}

// ---------------------------------------------------------------- step

TEST(StateSpaceStep, CounterSeesEigenAllocations) {
  const auto model = two_state_example();
  const MatrixXd u = MatrixXd::Ones(3, 2);
  const long before = test::allocation_count();
  const MatrixXd y = model.simulate(u);  // its result, at least, is on the heap
  EXPECT_GE(test::allocation_count() - before, test::counts_malloc() ? 1 : 0);
  EXPECT_EQ(y.rows(), 3);
}

TEST(StateSpaceStep, DoesNotAllocateAndEqualsSimulate) {
  std::mt19937_64 random(17);
  const auto model = random_stable_model(pole_pairs(14, random), 3, 3, random);
  const MatrixXd u = random_input(10'000, 3, 18);
  const MatrixXd expected = model.simulate(u);
  const MatrixXd u_by_sample = u.transpose();
  MatrixXd y(3, u.rows());
  auto state = model.initial_state();
  const long before = test::allocation_count();
  for (Eigen::Index k = 0; k < u.rows(); ++k)
    model.step(state, {u_by_sample.col(k).data(), 3}, {y.col(k).data(), 3});
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_EQ(y.transpose(), expected);
}

TEST(StateSpaceStep, StaticGainStepIsDTimesU) {
  const StateSpace model({MatrixXd(0, 0), MatrixXd(0, 2), MatrixXd(1, 0),
                          (MatrixXd(1, 2) << 2.0, -1.0).finished(), 1.0});
  auto state = model.initial_state();
  const double u[2] = {3.0, 4.0};
  double y[1] = {99.0};
  model.step(state, u, y);
  EXPECT_EQ(y[0], 2.0);
}

// ---------------------------------------------------------------- validation

StateSpace::Params valid_params() {
  return two_state_example().params();
}

TEST(StateSpaceValidation, RejectsWrongSizes) {
  auto p = valid_params();
  p.a = MatrixXd::Zero(2, 3);
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: A is 2 x 3; it must be square");
  p = valid_params();
  p.b = MatrixXd::Zero(3, 2);
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: B has 3 rows, A has 2");
  p = valid_params();
  p.c = MatrixXd::Zero(2, 4);
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: C has 4 columns, A has 2");
  p = valid_params();
  p.d = MatrixXd::Zero(1, 2);
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: D has 1 rows, C has 2");
  p = valid_params();
  p.d = MatrixXd::Zero(2, 3);
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: D has 3 columns, B has 2");
  p = valid_params();
  p.b = MatrixXd::Zero(2, 0);
  p.d = MatrixXd::Zero(2, 0);
  EXPECT_HYST_ERROR(StateSpace{p},
                    "state space: D is 2 x 0; the model needs at least one input and one output");
  p = valid_params();
  p.c = MatrixXd::Zero(0, 2);
  p.d = MatrixXd::Zero(0, 2);
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: D is 0 x 2");
  const auto n = Eigen::Index(StateSpace::max_order + 1);
  p = {MatrixXd::Zero(n, n), MatrixXd::Zero(n, 1), MatrixXd::Zero(1, n), MatrixXd::Zero(1, 1), 1.0};
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: order n = 501 is above the limit of 500 states");
}

TEST(StateSpaceValidation, NamesTheFieldOfTheError) {
  auto p = valid_params();
  p.b = MatrixXd::Zero(3, 2);
  try {
    StateSpace model(p);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "b");
  }
  p = valid_params();
  p.c(1, 0) = std::numeric_limits<double>::infinity();
  try {
    StateSpace model(p);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "c[1][0]");
  }
}

TEST(StateSpaceValidation, RejectsNonFiniteEntriesAndSampleTimes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto p = valid_params();
  p.a(1, 0) = nan;
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: A(1, 0) = nan is not finite");
  p = valid_params();
  p.b(0, 1) = inf;
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: B(0, 1) = inf is not finite");
  p = valid_params();
  p.c(1, 1) = -inf;
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: C(1, 1) = -inf is not finite");
  p = valid_params();
  p.d(0, 0) = nan;
  EXPECT_HYST_ERROR(StateSpace{p}, "state space: D(0, 0) = nan is not finite");
  for (const double ts : {0.0, -1e-3, nan, inf}) {
    p = valid_params();
    p.sample_time = ts;
    EXPECT_HYST_ERROR(StateSpace{p}, "state space: sample time Ts = ");
    EXPECT_HYST_ERROR(StateSpace{p}, " must be finite and > 0");
  }
}

TEST(StateSpaceValidation, RejectsBadContinuousModels) {
  const MatrixXd one = MatrixXd::Ones(1, 1);
  EXPECT_HYST_ERROR(StateSpace::from_continuous(MatrixXd::Zero(1, 2), one, one, one, 1.0),
                    "state space: Ac is 1 x 2; it must be square");
  EXPECT_HYST_ERROR(StateSpace::from_continuous(one, MatrixXd::Ones(2, 1), one, one, 1.0),
                    "state space: Bc has 2 rows, Ac has 1");
  EXPECT_HYST_ERROR(StateSpace::from_continuous(-one, one, one, one, 0.0),
                    "state space: sample time Ts = 0 must be finite and > 0");
  EXPECT_HYST_ERROR(
      StateSpace::from_continuous(
          MatrixXd::Constant(1, 1, std::numeric_limits<double>::quiet_NaN()), one, one, one, 1.0),
      "state space: Ac(0, 0) = nan is not finite");
  EXPECT_HYST_ERROR(StateSpace::from_continuous(MatrixXd::Constant(1, 1, 1e3), one, one, one, 1.0),
                    "state space: exp(Ac Ts) overflows at Ts = 1");
}

TEST(StateSpaceValidation, RejectsBadStatesAndSignals) {
  const auto model = two_state_example();
  EXPECT_HYST_ERROR(model.make_state(VectorXd::Zero(3)),
                    "state space: the state x has 3 values; the model has 2 states");
  EXPECT_HYST_ERROR(model.make_state((VectorXd(2) << 0.0, std::nan("")).finished()),
                    "state space: state x[1] = nan is not finite");
  auto state = model.initial_state();
  state.x = VectorXd::Zero(1);
  EXPECT_HYST_ERROR(model.simulate(MatrixXd::Zero(4, 2), state), "the state x has 1 values");
  EXPECT_HYST_ERROR(model.simulate(MatrixXd::Zero(4, 3)),
                    "state space: input has 3 columns; the model has 2 inputs");
  MatrixXd u = MatrixXd::Zero(4, 2);
  u(2, 1) = std::numeric_limits<double>::infinity();
  EXPECT_HYST_ERROR(model.simulate(u),
                    "state space: input(2, 1) = inf is not finite (sample 2, input 1)");
  EXPECT_HYST_ERROR(model.periodic_state(u),
                    "state space: one_period(2, 1) = inf is not finite (sample 2, input 1)");
  EXPECT_HYST_ERROR(model.simulate_periodic(MatrixXd::Zero(4, 1)),
                    "state space: one_period has 1 columns; the model has 2 inputs");
  const std::vector<double> f{1.0, std::nan("")};
  EXPECT_HYST_ERROR(model.frequency_response(f), "state space: frequency[1] = nan is not finite");
}

}  // namespace
}  // namespace hyst::state_space_test
