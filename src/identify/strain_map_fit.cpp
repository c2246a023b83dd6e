#include "strain_map_fit.hpp"

#include <Eigen/QR>

namespace hyst::detail {

Eigen::MatrixXd map_columns(const Eigen::VectorXd& input, const Eigen::VectorXd& polarisation,
                            std::size_t degree, bool field_term) {
  const auto first = field_term ? 2 : 1;
  Eigen::MatrixXd X(input.size(), first + static_cast<Eigen::Index>(degree));
  X.col(0).setOnes();
  if (field_term) X.col(1) = input;
  Eigen::VectorXd power = Eigen::VectorXd::Ones(input.size());
  for (std::size_t n = 0; n < degree; ++n) {
    power.array() *= polarisation.array();
    X.col(first + static_cast<Eigen::Index>(n)) = power;
  }
  return X;
}

MapFit fit_map(const Eigen::VectorXd& input, const Eigen::VectorXd& polarisation,
               const Eigen::VectorXd& output, std::size_t degree, bool field_term) {
  const Eigen::MatrixXd X = map_columns(input, polarisation, degree, field_term);
  const Eigen::VectorXd solved = X.colPivHouseholderQr().solve(output);
  MapFit fit{Eigen::VectorXd::Zero(2 + static_cast<Eigen::Index>(degree)),
             (X * solved - output).norm()};
  fit.coefficients[0] = solved[0];
  if (field_term) fit.coefficients[1] = solved[1];
  fit.coefficients.tail(static_cast<Eigen::Index>(degree)) =
      solved.tail(static_cast<Eigen::Index>(degree));
  return fit;
}

}  // namespace hyst::detail
