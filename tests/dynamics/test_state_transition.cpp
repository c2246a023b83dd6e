// StateTransition against the dense product A x: block-diagonal matrices (the real modal form and
// other 1 x 1 / 2 x 2 blockings) take the block path, anything else the dense one, with the same
// numbers either way.

#include <random>

#include <gtest/gtest.h>

#include "hyst/dynamics/state_transition.hpp"

namespace hyst {
namespace {

Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd x(n);
  for (auto& v : x)
    v = normal(random);
  return x;
}

// Blocks of sizes `sizes` on the diagonal, rotation-like pairs and real poles, all else zero.
Eigen::MatrixXd block_diagonal(const std::vector<int>& sizes, unsigned seed) {
  Eigen::Index n = 0;
  for (const int s : sizes)
    n += s;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  const Eigen::VectorXd values = random_vector(4 * n, seed);
  Eigen::Index at = 0;
  Eigen::Index next = 0;
  for (const int s : sizes) {
    for (int r = 0; r < s; ++r)
      for (int c = 0; c < s; ++c)
        a(at + r, at + c) = values[next++];
    at += s;
  }
  return a;
}

void expect_same_product(const Eigen::MatrixXd& a, bool block_path) {
  const StateTransition transition(a);
  EXPECT_EQ(transition.block_diagonal(), block_path);
  const Eigen::VectorXd x = random_vector(a.rows(), 3);
  Eigen::VectorXd out(a.rows());
  transition.apply(x, out);
  const Eigen::VectorXd expected = a * x;
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    EXPECT_NEAR(out[i], expected[i], 1e-15 * (1.0 + std::abs(expected[i]))) << i;
  // The same on every row of a matrix: X A^T.
  Eigen::MatrixXd rows(5, a.rows());
  for (Eigen::Index r = 0; r < rows.rows(); ++r)
    rows.row(r) = random_vector(a.rows(), 10 + unsigned(r)).transpose();
  Eigen::MatrixXd rows_out(rows.rows(), rows.cols());
  transition.apply_rows(rows, rows_out);
  const Eigen::MatrixXd rows_expected = rows * a.transpose();
  for (Eigen::Index r = 0; r < rows.rows(); ++r)
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      EXPECT_NEAR(rows_out(r, i), rows_expected(r, i),
                  1e-15 * (1.0 + std::abs(rows_expected(r, i))))
          << r << ", " << i;
}

TEST(StateTransition, RealModalFormTakesTheBlockPath) {
  expect_same_product(block_diagonal({2, 1, 2, 2, 1}, 1), true);
  expect_same_product(block_diagonal({1}, 2), true);
  expect_same_product(block_diagonal({2}, 3), true);
  // A triangular 2 x 2 block (one of its off-diagonal entries zero) is still a block.
  Eigen::MatrixXd triangular = block_diagonal({2, 1}, 4);
  triangular(1, 0) = 0.0;
  expect_same_product(triangular, true);
}

TEST(StateTransition, AnyOtherMatrixIsMultipliedAsItIs) {
  // One entry joining two blocks, a 3 x 3 block, a full matrix.
  Eigen::MatrixXd joined = block_diagonal({2, 1, 2}, 5);
  joined(4, 0) = 0.5;
  expect_same_product(joined, false);
  expect_same_product(block_diagonal({3, 1}, 6), false);
  expect_same_product(Eigen::MatrixXd::Random(7, 7), false);
  // A block that starts at an odd place: (1, 2) pairs states 1 and 2, state 0 alone.
  Eigen::MatrixXd shifted = Eigen::MatrixXd::Zero(3, 3);
  shifted << 0.9, 0, 0, 0, 0.8, 0.3, 0, -0.3, 0.8;
  expect_same_product(shifted, true);
}

}  // namespace
}  // namespace hyst
