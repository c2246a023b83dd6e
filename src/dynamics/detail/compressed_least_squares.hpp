#pragma once
// A least-squares problem with many more residuals than parameters, reduced to as many residuals
// as parameters plus one, from its normal equations: Levenberg-Marquardt sees the same cost, the
// same gradient and the same linearised model, without holding the tall Jacobian. The simulation
// error fits accumulate J^T J and J^T r realisation by realisation (in parallel) and hand Ceres
// this reduced problem.

#include <Eigen/Dense>

namespace hyst::detail {

struct CompressedLeastSquares {
  Eigen::VectorXd residuals;  // P + 1: r_c, then the part of r no step can reach
  Eigen::MatrixXd jacobian;   // (P + 1) x P: R, then a zero row
};

// For normal equations H = J^T J (P x P, symmetric), g = J^T r and s = r^T r, the R and r_c with
// R^T R = H, R^T r_c = g and |r_c|^2 + e^2 = s, so that |r + J d|^2 = |r_c + R d|^2 + e^2 for every
// step d. From the eigen-decomposition of H with each parameter scaled to a unit column of J
// (S H S = V L V^T, R = sqrt(L) V^T S^-1): directions with no curvature (scaled eigenvalues below
// 1e-14 of the largest, e.g. parameters the residual does not depend on) get a zero row, as they
// carry no gradient either.
CompressedLeastSquares compress_least_squares(const Eigen::MatrixXd& normal,
                                              const Eigen::VectorXd& gradient, double squares);

}  // namespace hyst::detail
