#pragma once
// The static strain map of the butterfly strain models, y = y_off + d v + sum_n q_n P^n, fitted by
// linear least squares for a given polarisation (shared by the fits with and without creep).

#include <cstddef>

#include <Eigen/Core>

namespace hyst::detail {

// Columns [1, v, P, P^2, ..., P^N] of the map (v only with the field term).
Eigen::MatrixXd map_columns(const Eigen::VectorXd& input, const Eigen::VectorXd& polarisation,
                            std::size_t degree, bool field_term);

// The map's coefficients [y_off, d, q_1 .. q_N] by linear least squares (d = 0 without the field
// term), and the residual norm.
struct MapFit {
  Eigen::VectorXd coefficients;
  double residual = 0.0;
};
MapFit fit_map(const Eigen::VectorXd& input, const Eigen::VectorXd& polarisation,
               const Eigen::VectorXd& output, std::size_t degree, bool field_term);

}  // namespace hyst::detail
