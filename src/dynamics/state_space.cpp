#include "hyst/dynamics/state_space.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <unsupported/Eigen/MatrixFunctions>

#include "hyst/core/assert.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

using Index = Eigen::Index;
using Complex = std::complex<double>;

// Below this distance of I - A^N to a singular matrix, relative to the size of I and A^N (whose
// rounding errors it must exceed), the periodic state's relative error could exceed about 1e-6:
// a pole sits on, or too near, an N-th root of unity.
constexpr double kMinPeriodicDistanceToSingular = 1e-10;

// The names a matrix goes by in messages ("B", "Bc") and in Params / model files ("b").
struct MatrixName {
  std::string_view symbol;
  std::string_view field;
};

void require_finite_entries(const Eigen::MatrixXd& matrix, const MatrixName& name) {
  for (Index j = 0; j < matrix.cols(); ++j)
    for (Index i = 0; i < matrix.rows(); ++i)
      if (!std::isfinite(matrix(i, j)))
        throw Error(fmt::format("state space: {}({}, {}) = {} is not finite", name.symbol, i, j,
                                matrix(i, j)),
                    fmt::format("{}[{}][{}]", name.field, i, j));
}

void require_sample_time(double sample_time) {
  if (!std::isfinite(sample_time) || !(sample_time > 0.0))
    throw Error(fmt::format("state space: sample time Ts = {} must be finite and > 0", sample_time),
                "sample_time");
}

// The sizes of A (n x n), B (n x m), C (p x n), D (p x m); m and p at least 1.
void require_sizes(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::MatrixXd& c,
                   const Eigen::MatrixXd& d, const MatrixName& a_name, const MatrixName& b_name) {
  if (a.rows() != a.cols())
    throw Error(fmt::format("state space: {} is {} x {}; it must be square", a_name.symbol,
                            a.rows(), a.cols()),
                std::string(a_name.field));
  if (a.rows() > Index(StateSpace::max_order))
    throw Error(fmt::format("state space: order n = {} is above the limit of {} states", a.rows(),
                            StateSpace::max_order),
                std::string(a_name.field));
  if (b.cols() > Index(StateSpace::max_channels))
    throw Error(fmt::format("state space: {} inputs are above the limit of {}", b.cols(),
                            StateSpace::max_channels),
                std::string(b_name.field));
  if (c.rows() > Index(StateSpace::max_channels))
    throw Error(fmt::format("state space: {} outputs are above the limit of {}", c.rows(),
                            StateSpace::max_channels),
                "c");
  if (b.rows() != a.rows())
    throw Error(fmt::format("state space: {} has {} rows, {} has {}", b_name.symbol, b.rows(),
                            a_name.symbol, a.rows()),
                std::string(b_name.field));
  if (c.cols() != a.rows())
    throw Error(
        fmt::format("state space: C has {} columns, {} has {}", c.cols(), a_name.symbol, a.rows()),
        "c");
  if (d.rows() != c.rows())
    throw Error(fmt::format("state space: D has {} rows, C has {}", d.rows(), c.rows()), "d");
  if (d.cols() != b.cols())
    throw Error(
        fmt::format("state space: D has {} columns, {} has {}", d.cols(), b_name.symbol, b.cols()),
        "d");
  if (d.rows() == 0 || d.cols() == 0)
    throw Error(fmt::format("state space: D is {} x {}; the model needs at least one input and "
                            "one output (m, p >= 1)",
                            d.rows(), d.cols()),
                "d");
}

void validate(const StateSpace::Params& p) {
  require_sizes(p.a, p.b, p.c, p.d, {"A", "a"}, {"B", "b"});
  require_finite_entries(p.a, {"A", "a"});
  require_finite_entries(p.b, {"B", "b"});
  require_finite_entries(p.c, {"C", "c"});
  require_finite_entries(p.d, {"D", "d"});
  require_sample_time(p.sample_time);
}

// Every row of `signal` (N x m) is one sample of the m inputs: the column count must be m and
// every value finite; messages name the sample and the channel.
void require_signal(const Eigen::MatrixXd& signal, std::size_t inputs, std::string_view name) {
  if (signal.cols() != Index(inputs))
    throw Error(fmt::format("state space: {} has {} columns; the model has {} inputs", name,
                            signal.cols(), inputs));
  for (Index j = 0; j < signal.cols(); ++j)
    for (Index k = 0; k < signal.rows(); ++k)
      if (!std::isfinite(signal(k, j)))
        throw Error(fmt::format("state space: {}({}, {}) = {} is not finite (sample {}, input {})",
                                name, k, j, signal(k, j), k, j));
}

// A^N by repeated squaring: O(n^3 log N) instead of N products.
Eigen::MatrixXd matrix_power(const Eigen::MatrixXd& a, std::size_t exponent) {
  Eigen::MatrixXd result = Eigen::MatrixXd::Identity(a.rows(), a.cols());
  Eigen::MatrixXd base = a;
  while (exponent > 0) {
    if (exponent & 1u) result = result * base;
    exponent >>= 1u;
    if (exponent > 0) base = base * base;
  }
  return result;
}

// About min ||E|| / (1 + ||A^N||) (1-norms) over the E that make I - A^N + E singular: the LU's
// estimate of 1 / ||(I - A^N)^-1||, in the scale of the terms the matrix was formed from. Not its
// condition number, which is blind to scale: I - A^N = 1e-15 R (A^N = I up to rounding) would
// look well conditioned.
double relative_distance_to_singular(const Eigen::FullPivLU<Eigen::MatrixXd>& lu,
                                     const Eigen::MatrixXd& lhs, const Eigen::MatrixXd& power) {
  const auto norm_1 = [](const Eigen::MatrixXd& m) {
    return m.cwiseAbs().colwise().sum().maxCoeff();
  };
  return lu.rcond() * norm_1(lhs) / (1.0 + norm_1(power));
}

// Solves (z I - H) X = R in place of R for an upper Hessenberg H: Gaussian elimination with
// partial pivoting, where the next row is the only candidate pivot row, so O(n^2) per column of
// R instead of a dense LU's O(n^3). `work` is the shifted matrix, reused across frequencies.
void solve_shifted_hessenberg(const Eigen::MatrixXcd& h, Complex z, Eigen::MatrixXcd& work,
                              Eigen::MatrixXcd& r) {
  const Index n = h.rows();
  work = -h;
  work.diagonal().array() += z;
  for (Index k = 0; k + 1 < n; ++k) {
    if (std::abs(work(k + 1, k)) > std::abs(work(k, k))) {
      work.row(k).tail(n - k).swap(work.row(k + 1).tail(n - k));
      r.row(k).swap(r.row(k + 1));
    }
    // A zero pivot (z exactly at a pole) leaves the column as it is; the back substitution then
    // gives the infinite response there.
    if (work(k, k) == Complex(0.0)) continue;
    const Complex factor = work(k + 1, k) / work(k, k);
    work.row(k + 1).tail(n - k - 1) -= factor * work.row(k).tail(n - k - 1);
    work(k + 1, k) = 0.0;
    r.row(k + 1) -= factor * r.row(k);
  }
  work.triangularView<Eigen::Upper>().solveInPlace(r);
}

// The parameters once validate() has taken them (before StateTransition reads A).
StateSpace::Params validated(StateSpace::Params params) {
  validate(params);
  return params;
}

}  // namespace

StateSpace::StateSpace(Params params)
    : params_(validated(std::move(params))), transition_(params_.a) {}

StateSpace StateSpace::from_continuous(const Eigen::MatrixXd& ac, const Eigen::MatrixXd& bc,
                                       const Eigen::MatrixXd& c, const Eigen::MatrixXd& d,
                                       double sample_time) {
  require_sizes(ac, bc, c, d, {"Ac", "a"}, {"Bc", "b"});
  require_finite_entries(ac, {"Ac", "a"});
  require_finite_entries(bc, {"Bc", "b"});
  require_sample_time(sample_time);
  // exp([[Ac, Bc], [0, 0]] Ts) = [[A, B], [0, I]]: both blocks of the exact zero-order hold from
  // one matrix exponential, with no inverse of Ac (which may be singular, e.g. an integrator).
  const Index n = ac.rows();
  const Index m = bc.cols();
  Eigen::MatrixXd augmented = Eigen::MatrixXd::Zero(n + m, n + m);
  augmented.topLeftCorner(n, n) = ac * sample_time;
  augmented.topRightCorner(n, m) = bc * sample_time;
  const Eigen::MatrixXd exponential = augmented.exp();
  if (!exponential.allFinite())
    throw Error(
        fmt::format("state space: exp(Ac Ts) overflows at Ts = {}; the continuous model's "
                    "growth over one sample is beyond double precision",
                    sample_time));
  return StateSpace(
      Params{exponential.topLeftCorner(n, n), exponential.topRightCorner(n, m), c, d, sample_time});
}

StateSpace::State StateSpace::initial_state() const {
  const auto n = Index(order());
  return State{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
}

StateSpace::State StateSpace::make_state(const Eigen::VectorXd& x) const {
  if (x.size() != Index(order()))
    throw Error(fmt::format("state space: the state x has {} values; the model has {} states",
                            x.size(), order()),
                "x");
  for (Index i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]))
      throw Error(fmt::format("state space: state x[{}] = {} is not finite", i, x[i]),
                  fmt::format("x[{}]", i));
  return State{x, Eigen::VectorXd::Zero(x.size())};
}

void StateSpace::step(State& state, std::span<const double> input,
                      std::span<double> output) const noexcept {
  HYST_ASSERT(input.size() == inputs(), "step() needs one input value per model input");
  HYST_ASSERT(output.size() == outputs(), "step() needs room for one value per model output");
  HYST_ASSERT(state.x.size() == Index(order()) && state.scratch.size() == Index(order()),
              "step() needs a state made by this model");
  const Eigen::Map<const Eigen::VectorXd> u(input.data(), Index(input.size()));
  Eigen::Map<Eigen::VectorXd> y(output.data(), Index(output.size()));
  const auto& p = params_;
  y.noalias() = p.c * state.x;
  y.noalias() += p.d * u;
  // The next state goes to scratch first: A x reads every entry of x while it is written.
  transition_.apply(state.x, state.scratch);
  state.scratch.noalias() += p.b * u;
  state.x.swap(state.scratch);
}

Eigen::MatrixXd StateSpace::simulate(const Eigen::MatrixXd& input, State& state) const {
  require_signal(input, inputs(), "input");
  state = make_state(state.x);  // checks a state built by hand and sizes its scratch
  // One column per sample, so that each sample's values are contiguous for step().
  const Eigen::MatrixXd u = input.transpose();
  Eigen::MatrixXd y(Index(outputs()), input.rows());
  for (Index k = 0; k < input.rows(); ++k)
    step(state, {u.col(k).data(), inputs()}, {y.col(k).data(), outputs()});
  return y.transpose();
}

Eigen::MatrixXd StateSpace::simulate(const Eigen::MatrixXd& input) const {
  State state = initial_state();
  return simulate(input, state);
}

Eigen::VectorXd StateSpace::periodic_state(const Eigen::MatrixXd& one_period) const {
  require_signal(one_period, inputs(), "one_period");
  if (one_period.rows() == 0) throw Error("state space: the period has no sample");
  const auto period = std::size_t(one_period.rows());
  State forced = initial_state();
  Eigen::VectorXd unused = Eigen::VectorXd::Zero(Index(outputs()));
  const Eigen::MatrixXd u = one_period.transpose();
  for (Index k = 0; k < u.cols(); ++k)
    step(forced, {u.col(k).data(), inputs()}, {unused.data(), outputs()});
  if (order() == 0) return forced.x;

  const auto n = Index(order());
  const Eigen::MatrixXd power = matrix_power(params_.a, period);
  const Eigen::MatrixXd lhs = Eigen::MatrixXd::Identity(n, n) - power;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(lhs);
  const double distance = relative_distance_to_singular(lu, lhs, power);
  if (!lu.isInvertible() || !(distance >= kMinPeriodicDistanceToSingular))
    throw Error(fmt::format(
        "state space: no unique periodic state for a period of {} samples: I - A^{} is singular "
        "or nearly so (relative distance to a singular matrix {:.3g}, below {:g}). A pole of A "
        "lies on or next to a root of unity z^{} = 1 (e.g. an integrator's pole at z = 1, or an "
        "undamped oscillation with a whole number of cycles per period), so that mode has either "
        "no periodic response (an input that drives it, like a non-zero mean into an "
        "integrator) or infinitely many (any constant for an integrator under a zero-mean "
        "input). Damp or remove that mode, or start from a given state instead",
        period, period, distance, kMinPeriodicDistanceToSingular, period));
  return lu.solve(forced.x);
}

Eigen::MatrixXd StateSpace::simulate_periodic(const Eigen::MatrixXd& one_period) const {
  State state = make_state(periodic_state(one_period));
  return simulate(one_period, state);
}

std::vector<Eigen::MatrixXcd> StateSpace::frequency_response(
    std::span<const double> frequencies) const {
  require_finite(frequencies, "state space: frequency");
  const Eigen::MatrixXcd d = params_.d.cast<Complex>();
  std::vector<Eigen::MatrixXcd> response;
  response.reserve(frequencies.size());
  if (order() == 0) {
    response.assign(frequencies.size(), d);
    return response;
  }
  // A = Q H Q^T with H upper Hessenberg, once: then G(z) = (C Q) (zI - H)^-1 (Q^T B) + D and
  // each frequency costs O(n^2 m) instead of a dense LU's O(n^3).
  const Eigen::HessenbergDecomposition<Eigen::MatrixXd> hessenberg(params_.a);
  const Eigen::MatrixXd q = hessenberg.matrixQ();
  const Eigen::MatrixXcd h = hessenberg.matrixH().cast<Complex>();
  const Eigen::MatrixXcd qb = (q.transpose() * params_.b).cast<Complex>();
  const Eigen::MatrixXcd cq = (params_.c * q).cast<Complex>();
  Eigen::MatrixXcd work;
  Eigen::MatrixXcd x;
  for (const double f : frequencies) {
    const Complex z = std::polar(1.0, 2.0 * std::numbers::pi * f * params_.sample_time);
    x = qb;
    solve_shifted_hessenberg(h, z, work, x);
    response.push_back(cq * x + d);
  }
  return response;
}

Eigen::VectorXcd StateSpace::poles() const {
  if (order() == 0) return Eigen::VectorXcd(0);
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(params_.a, false);
  if (solver.info() != Eigen::Success)
    throw Error(
        fmt::format("state space: the eigenvalues of A (order {}) did not converge", order()));
  return solver.eigenvalues();
}

double StateSpace::spectral_radius() const {
  const Eigen::VectorXcd p = poles();
  return p.size() == 0 ? 0.0 : p.cwiseAbs().maxCoeff();
}

}  // namespace hyst
