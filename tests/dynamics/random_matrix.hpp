#pragma once
// A matrix of independent normal samples for the dynamics tests (random models and inputs).

#include <random>

#include <Eigen/Dense>

namespace hyst::test {

inline Eigen::MatrixXd random_matrix(Eigen::Index rows, Eigen::Index cols, std::mt19937_64& random,
                                     double scale = 1.0) {
  std::normal_distribution<double> gauss(0.0, scale);
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i)
      m(i, j) = gauss(random);
  return m;
}

}  // namespace hyst::test
