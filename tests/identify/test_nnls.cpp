#include "hyst/identify/nnls.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/QR>

#include "../support/expect_error.hpp"

namespace hyst {
namespace {

// The options field a hyst::Error names ("no error" when nothing is thrown).
template <class Statement>
std::string nnls_field_of(Statement statement) {
  try {
    statement();
  } catch (const Error& error) {
    return error.field();
  }
  return "no error";
}

struct Problem {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
};

Problem random_problem(std::uint64_t seed, Eigen::Index m, Eigen::Index n) {
  std::mt19937_64 draw(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Problem problem{Eigen::MatrixXd(m, n), Eigen::VectorXd(m)};
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < m; ++i)
      problem.A(i, j) = normal(draw);
  for (Eigen::Index i = 0; i < m; ++i)
    problem.b[i] = normal(draw);
  return problem;
}

double cost(const Problem& problem, const Eigen::VectorXd& x) {
  return 0.5 * (problem.A * x - problem.b).squaredNorm();
}

// Karush-Kuhn-Tucker conditions of min ||Ax - b||^2, x >= 0, with w = A^T (b - A x).
void expect_kkt(const Problem& problem, const NnlsResult& result, double tolerance) {
  const Eigen::VectorXd w = problem.A.transpose() * (problem.b - problem.A * result.x);
  for (Eigen::Index j = 0; j < result.x.size(); ++j) {
    EXPECT_GE(result.x[j], 0.0) << "x[" << j << "]";
    if (result.x[j] == 0.0) {
      EXPECT_LE(w[j], tolerance) << "w[" << j << "] where x[" << j << "] = 0";
    } else {
      EXPECT_LE(std::abs(w[j]), tolerance) << "w[" << j << "] where x[" << j << "] > 0";
    }
  }
  EXPECT_NEAR(result.residual_norm, (problem.A * result.x - problem.b).norm(), 1e-12);
}

// A second algorithm: every passive set P, unconstrained least squares on the columns of P
// (minimum-norm solution), the best feasible one wins.
struct BruteForce {
  Eigen::VectorXd x;
  double cost = std::numeric_limits<double>::infinity();
};

BruteForce brute_force(const Problem& problem) {
  const Eigen::Index n = problem.A.cols();
  BruteForce best;
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    std::vector<Eigen::Index> passive;
    for (Eigen::Index j = 0; j < n; ++j)
      if (mask & (1u << j)) passive.push_back(j);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    if (!passive.empty()) {
      Eigen::MatrixXd columns(problem.A.rows(), static_cast<Eigen::Index>(passive.size()));
      for (std::size_t i = 0; i < passive.size(); ++i)
        columns.col(static_cast<Eigen::Index>(i)) = problem.A.col(passive[i]);
      const Eigen::VectorXd solution = columns.completeOrthogonalDecomposition().solve(problem.b);
      if ((solution.array() < -1e-12).any()) continue;
      for (std::size_t i = 0; i < passive.size(); ++i)
        x[passive[i]] = std::max(0.0, solution[static_cast<Eigen::Index>(i)]);
    }
    if (const double c = cost(problem, x); c < best.cost) best = {x, c};
  }
  return best;
}

TEST(Nnls, HandSolvableCase) {
  // min (x1 + x2 - 2)^2 + (x2 + 1)^2: the unconstrained optimum (3, -1) is infeasible; with
  // x2 = 0 the best x1 is 2 (cost 1), with x1 = 0 the best x2 is 0.5 (cost 4.5).
  Problem problem{Eigen::MatrixXd(2, 2), Eigen::VectorXd(2)};
  problem.A << 1, 1, 0, 1;
  problem.b << 2, -1;
  const NnlsResult result = nnls(problem.A, problem.b);
  EXPECT_TRUE(result.converged()) << result.message;
  EXPECT_NEAR(result.x[0], 2.0, 1e-15);
  EXPECT_EQ(result.x[1], 0.0);
  EXPECT_NEAR(result.residual_norm, 1.0, 1e-15);
  EXPECT_NEAR(result.dual[0], 0.0, 1e-15);
  EXPECT_NEAR(result.dual[1], -1.0, 1e-15);
  EXPECT_EQ(result.iterations, 1u);
}

TEST(Nnls, TallHandSolvableCase) {
  // More rows than columns (the QR-reduced path): x = (1, 0), residual sqrt(4 + 9).
  Problem problem{Eigen::MatrixXd(3, 2), Eigen::VectorXd(3)};
  problem.A << 1, 0, 0, 1, 0, 0;
  problem.b << 1, -2, 3;
  const NnlsResult result = nnls(problem.A, problem.b);
  EXPECT_TRUE(result.converged());
  EXPECT_NEAR(result.x[0], 1.0, 1e-15);
  EXPECT_EQ(result.x[1], 0.0);
  EXPECT_NEAR(result.residual_norm, std::sqrt(13.0), 1e-14);
}

TEST(Nnls, SatisfiesKktOnRandomProblems) {
  std::mt19937_64 seeds(7);
  for (int trial = 0; trial < 200; ++trial) {
    const std::uint64_t seed = seeds();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 draw(seed);
    const auto m = static_cast<Eigen::Index>(1 + draw() % 120);
    const auto n = static_cast<Eigen::Index>(1 + draw() % 40);
    const Problem problem = random_problem(draw(), m, n);
    const NnlsResult result = nnls(problem.A, problem.b);
    EXPECT_TRUE(result.converged()) << result.message;
    // The scale of w is ||A|| ||b||; allow rounding relative to it.
    const double scale = problem.A.norm() * problem.b.norm();
    expect_kkt(problem, result, 1e-11 * scale);
  }
}

TEST(Nnls, AgreesWithBruteForceEnumeration) {
  std::mt19937_64 seeds(2024);
  for (int trial = 0; trial < 300; ++trial) {
    const std::uint64_t seed = seeds();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 draw(seed);
    const auto m = static_cast<Eigen::Index>(1 + draw() % 12);
    const auto n = static_cast<Eigen::Index>(1 + draw() % 8);
    const Problem problem = random_problem(draw(), m, n);
    const NnlsResult result = nnls(problem.A, problem.b);
    const BruteForce reference = brute_force(problem);
    EXPECT_TRUE(result.converged()) << result.message;
    EXPECT_NEAR(cost(problem, result.x), reference.cost, 1e-12 * (1.0 + reference.cost));
    if (m >= n) {
      // Full column rank (almost surely): the minimiser is unique.
      for (Eigen::Index j = 0; j < n; ++j)
        EXPECT_NEAR(result.x[j], reference.x[j], 1e-9) << "x[" << j << "] (m = " << m << ")";
    }
  }
}

TEST(Nnls, EqualsLeastSquaresWhenItsOptimumIsNonNegative) {
  std::mt19937_64 seeds(99);
  for (int trial = 0; trial < 50; ++trial) {
    const std::uint64_t seed = seeds();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 draw(seed);
    std::uniform_real_distribution<double> positive(0.5, 2.0);
    const auto n = static_cast<Eigen::Index>(1 + draw() % 10);
    const Eigen::Index m = n + 5 + static_cast<Eigen::Index>(draw() % 30);
    Problem problem = random_problem(draw(), m, n);
    Eigen::VectorXd x_true(n);
    for (Eigen::Index j = 0; j < n; ++j)
      x_true[j] = positive(draw);
    problem.b = problem.A * x_true + 0.01 * problem.b;
    const Eigen::VectorXd least_squares = problem.A.colPivHouseholderQr().solve(problem.b);
    ASSERT_TRUE((least_squares.array() > 0.0).all()) << "precondition: LS optimum is positive";
    const NnlsResult result = nnls(problem.A, problem.b);
    EXPECT_TRUE(result.converged());
    for (Eigen::Index j = 0; j < n; ++j)
      EXPECT_NEAR(result.x[j], least_squares[j], 1e-12 * (1.0 + std::abs(least_squares[j])));
  }
}

TEST(Nnls, HandlesRankDeficientColumns) {
  std::mt19937_64 seeds(31);
  for (int trial = 0; trial < 100; ++trial) {
    const std::uint64_t seed = seeds();
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937_64 draw(seed);
    const Eigen::Index m = 3 + static_cast<Eigen::Index>(draw() % 15);
    Problem problem = random_problem(draw(), m, 7);
    problem.A.col(3) = problem.A.col(0);                         // duplicate
    problem.A.col(4).setZero();                                  // zero column
    problem.A.col(5) = problem.A.col(1) + 2 * problem.A.col(2);  // positive combination
    problem.A.col(6) = -problem.A.col(1);                        // opposite direction
    const NnlsResult result = nnls(problem.A, problem.b);
    EXPECT_TRUE(result.converged()) << result.message;
    EXPECT_EQ(result.x[4], 0.0) << "a zero column never enters";
    expect_kkt(problem, result, 1e-11 * problem.A.norm() * problem.b.norm());
    const BruteForce reference = brute_force(problem);
    EXPECT_NEAR(cost(problem, result.x), reference.cost, 1e-10 * (1.0 + reference.cost));
  }
}

TEST(Nnls, ZeroRightHandSideGivesZero) {
  const Problem problem = random_problem(5, 10, 4);
  const NnlsResult result = nnls(problem.A, Eigen::VectorXd::Zero(10));
  EXPECT_TRUE(result.converged());
  EXPECT_TRUE(result.x.isZero(0.0));
  EXPECT_EQ(result.iterations, 0u);
}

TEST(Nnls, OptionsLimitTheWork) {
  // x = A^{-1} b with b = A * (1, 2, 3, 4): four additions are needed.
  const Problem random = random_problem(11, 20, 4);
  const Eigen::VectorXd b = random.A * Eigen::Vector4d(1, 2, 3, 4);
  const NnlsResult full = nnls(random.A, b);
  EXPECT_TRUE(full.converged());
  EXPECT_EQ(full.iterations, 4u);

  const NnlsResult limited = nnls(random.A, b, {.max_iterations = 2});
  EXPECT_EQ(limited.termination, Termination::max_iterations);
  EXPECT_EQ(limited.iterations, 2u);
  EXPECT_TRUE((limited.x.array() >= 0.0).all()) << "feasible even when stopped early";
  EXPECT_LT(limited.residual_norm, b.norm());
  EXPECT_NE(limited.message.find("max_iterations = 2"), std::string::npos) << limited.message;

  // A tolerance above every w_j accepts x = 0.
  const NnlsResult loose = nnls(random.A, b, {.tolerance = 1e300});
  EXPECT_TRUE(loose.converged());
  EXPECT_TRUE(loose.x.isZero(0.0));
  EXPECT_EQ(loose.tolerance, 1e300);
}

TEST(Nnls, RejectsInvalidInput) {
  const Eigen::MatrixXd A = Eigen::MatrixXd::Ones(3, 2);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(3);
  EXPECT_HYST_ERROR(nnls(Eigen::MatrixXd(0, 2), Eigen::VectorXd(0)),
                    "NNLS matrix A is 0x2; it needs at least one row and one column");
  EXPECT_HYST_ERROR(nnls(Eigen::MatrixXd(3, 0), b), "NNLS matrix A is 3x0");
  EXPECT_HYST_ERROR(nnls(A, Eigen::VectorXd::Ones(4)),
                    "NNLS vector b has 4 values but matrix A has 3 rows");
  Eigen::MatrixXd bad_A = A;
  bad_A(2, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_HYST_ERROR(nnls(bad_A, b), "NNLS matrix A(2, 1) = nan is not finite");
  Eigen::VectorXd bad_b = b;
  bad_b[1] = -std::numeric_limits<double>::infinity();
  EXPECT_HYST_ERROR(nnls(A, bad_b), "NNLS vector b[1] = -inf is not finite");
  EXPECT_HYST_ERROR(nnls(A, b, {.max_iterations = 0}), "NNLS max_iterations = 0 must be >= 1");
  EXPECT_HYST_ERROR(nnls(A, b, {.tolerance = -1.0}), "NNLS tolerance = -1 must be finite and >= 0");
  EXPECT_HYST_ERROR(nnls(A, b, {.tolerance = std::numeric_limits<double>::quiet_NaN()}),
                    "NNLS tolerance = nan");
  EXPECT_EQ(nnls_field_of([&] { nnls(A, b, {.tolerance = -1.0}); }), "tolerance");
  EXPECT_EQ(nnls_field_of([&] { nnls(A, b, {.max_iterations = 0}); }), "max_iterations");
  EXPECT_EQ(nnls_field_of([&] { nnls(bad_A, b); }), "") << "not an options field";
}

}  // namespace
}  // namespace hyst
