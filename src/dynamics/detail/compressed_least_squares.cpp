#include "compressed_least_squares.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace hyst::detail {

CompressedLeastSquares compress_least_squares(const Eigen::MatrixXd& normal,
                                              const Eigen::VectorXd& gradient, double squares) {
  const Eigen::Index p = normal.rows();
  // Decomposed with every parameter scaled to a unit column of J, so that parameters of very
  // different scales do not push each other below the floor: H = N Hs N, N the column norms.
  Eigen::VectorXd norm(p), scale(p);  // scale = N^-1, zero where the column of J is zero
  for (Eigen::Index j = 0; j < p; ++j) {
    norm[j] = std::sqrt(std::max(normal(j, j), 0.0));
    scale[j] = norm[j] > 0.0 ? 1.0 / norm[j] : 0.0;
  }
  const Eigen::MatrixXd scaled = scale.asDiagonal() * normal * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(scaled);
  const Eigen::VectorXd& values = eigen.eigenvalues();
  const Eigen::MatrixXd& vectors = eigen.eigenvectors();
  const double floor = 1e-14 * std::max(values.maxCoeff(), 0.0);
  const Eigen::VectorXd scaled_gradient = scale.cwiseProduct(gradient);
  CompressedLeastSquares result{Eigen::VectorXd::Zero(p + 1), Eigen::MatrixXd::Zero(p + 1, p)};
  for (Eigen::Index j = 0; j < p; ++j) {
    if (!(values[j] > floor)) continue;
    const double root = std::sqrt(values[j]);
    result.jacobian.row(j) = root * vectors.col(j).cwiseProduct(norm).transpose();
    result.residuals[j] = vectors.col(j).dot(scaled_gradient) / root;
  }
  const double reached = result.residuals.head(p).squaredNorm();
  result.residuals[p] = std::sqrt(std::max(squares - reached, 0.0));
  return result;
}

}  // namespace hyst::detail
