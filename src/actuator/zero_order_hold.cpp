#include "hyst/actuator/zero_order_hold.hpp"

#include <cmath>

#include <fmt/format.h>
#include <unsupported/Eigen/MatrixFunctions>

#include "hyst/core/error.hpp"

namespace hyst {

ZeroOrderHold zero_order_hold(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double period) {
  if (a.rows() != a.cols() || a.rows() == 0) {
    throw Error(fmt::format("zero-order hold: A is {}x{}, must be square and not empty", a.rows(),
                            a.cols()));
  }
  if (b.rows() != a.rows() || b.cols() == 0) {
    throw Error(fmt::format("zero-order hold: B has {} rows, A has {}", b.rows(), a.rows()));
  }
  if (!std::isfinite(period) || !(period > 0.0)) {
    throw Error(fmt::format("sample period h = {} must be finite and > 0", period), "period");
  }
  if (!a.allFinite() || !b.allFinite()) throw Error("zero-order hold: A and B must be finite");
  const Eigen::Index n = a.rows();
  const Eigen::Index m = b.cols();
  Eigen::MatrixXd augmented = Eigen::MatrixXd::Zero(n + m, n + m);
  augmented.topLeftCorner(n, n) = a * period;
  augmented.topRightCorner(n, m) = b * period;
  const Eigen::MatrixXd exponential = augmented.exp();
  return {exponential.topLeftCorner(n, n), exponential.topRightCorner(n, m)};
}

}  // namespace hyst
