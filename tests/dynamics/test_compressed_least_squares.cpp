// The compressed least-squares problem against the tall one it replaces: the same cost of every
// step (|r + J d|^2, computed directly) and the same normal equations, also when parameters of
// very different scales meet and when a parameter moves nothing.

#include "../../src/dynamics/detail/compressed_least_squares.hpp"

#include <random>

#include <gtest/gtest.h>

namespace hyst::compressed_least_squares_test {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd random_matrix(Eigen::Index rows, Eigen::Index cols, std::mt19937_64& random) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  MatrixXd m(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i)
      m(i, j) = gauss(random);
  return m;
}

void expect_same_problem(const MatrixXd& j, const VectorXd& r, std::mt19937_64& random) {
  const MatrixXd normal = j.transpose() * j;
  const auto c = detail::compress_least_squares(normal, j.transpose() * r, r.squaredNorm());
  ASSERT_EQ(c.residuals.size(), j.cols() + 1);
  ASSERT_EQ(c.jacobian.rows(), j.cols() + 1);
  EXPECT_NEAR(c.residuals.squaredNorm(), r.squaredNorm(), 1e-12 * r.squaredNorm());
  EXPECT_LE((c.jacobian.transpose() * c.jacobian - normal).cwiseAbs().maxCoeff(),
            1e-10 * normal.cwiseAbs().maxCoeff());
  for (int trial = 0; trial < 5; ++trial) {
    // Steps of the size that brings each parameter's effect to that of the residual.
    VectorXd d = random_matrix(j.cols(), 1, random);
    for (Eigen::Index k = 0; k < j.cols(); ++k)
      d[k] *= j.col(k).norm() > 0.0 ? r.norm() / j.col(k).norm() : 1.0;
    const double tall = (r + j * d).squaredNorm();
    const double compressed = (c.residuals + c.jacobian * d).squaredNorm();
    EXPECT_NEAR(compressed, tall, 1e-9 * tall) << "trial " << trial;
  }
}

TEST(CompressedLeastSquares, SameCostOfEveryStepAsTheTallProblem) {
  std::mt19937_64 random(1);
  const MatrixXd j = random_matrix(500, 12, random);
  const VectorXd r = random_matrix(500, 1, random).col(0);
  expect_same_problem(j, r, random);
}

TEST(CompressedLeastSquares, ParametersOfVeryDifferentScales) {
  std::mt19937_64 random(2);
  MatrixXd j = random_matrix(400, 6, random);
  j.col(1) *= 1e9;  // e.g. a pole against a feedback weight
  j.col(4) *= 1e-8;
  const VectorXd r = random_matrix(400, 1, random).col(0);
  expect_same_problem(j, r, random);
}

TEST(CompressedLeastSquares, AParameterThatMovesNothing) {
  std::mt19937_64 random(3);
  MatrixXd j = random_matrix(300, 5, random);
  j.col(2).setZero();
  const VectorXd r = random_matrix(300, 1, random).col(0);
  expect_same_problem(j, r, random);
  const MatrixXd normal = j.transpose() * j;
  const auto c = detail::compress_least_squares(normal, j.transpose() * r, r.squaredNorm());
  EXPECT_EQ(c.jacobian.col(2).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace hyst::compressed_least_squares_test
