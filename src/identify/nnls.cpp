#include "hyst/identify/nnls.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <Eigen/QR>

#include "hyst/core/error.hpp"

namespace hyst {
namespace {

void validate(const Eigen::Ref<const Eigen::MatrixXd>& A,
              const Eigen::Ref<const Eigen::VectorXd>& b, const NnlsOptions& options) {
  if (A.rows() == 0 || A.cols() == 0) {
    throw Error(fmt::format("NNLS matrix A is {}x{}; it needs at least one row and one column",
                            A.rows(), A.cols()));
  }
  if (b.size() != A.rows()) {
    throw Error(
        fmt::format("NNLS vector b has {} values but matrix A has {} rows; they must be "
                    "equal",
                    b.size(), A.rows()));
  }
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
      if (!std::isfinite(A(i, j))) {
        throw Error(fmt::format("NNLS matrix A({}, {}) = {} is not finite", i, j, A(i, j)));
      }
    }
  }
  for (Eigen::Index i = 0; i < b.size(); ++i) {
    if (!std::isfinite(b[i])) {
      throw Error(fmt::format("NNLS vector b[{}] = {} is not finite", i, b[i]));
    }
  }
  if (options.max_iterations && *options.max_iterations == 0) {
    throw Error("NNLS max_iterations = 0 must be >= 1", "max_iterations");
  }
  if (options.tolerance && !(std::isfinite(*options.tolerance) && *options.tolerance >= 0.0)) {
    throw Error(fmt::format("NNLS tolerance = {} must be finite and >= 0", *options.tolerance),
                "tolerance");
  }
}

// Unconstrained least squares on the passive columns; the other entries of the result are 0.
Eigen::VectorXd solve_passive(const Eigen::MatrixXd& M, const Eigen::VectorXd& c,
                              const std::vector<Eigen::Index>& passive) {
  Eigen::MatrixXd columns(M.rows(), static_cast<Eigen::Index>(passive.size()));
  for (std::size_t i = 0; i < passive.size(); ++i)
    columns.col(static_cast<Eigen::Index>(i)) = M.col(passive[i]);
  const Eigen::VectorXd solution = columns.colPivHouseholderQr().solve(c);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(M.cols());
  for (std::size_t i = 0; i < passive.size(); ++i)
    z[passive[i]] = solution[static_cast<Eigen::Index>(i)];
  return z;
}

}  // namespace

NnlsResult nnls(const Eigen::Ref<const Eigen::MatrixXd>& A,
                const Eigen::Ref<const Eigen::VectorXd>& b, const NnlsOptions& options) {
  validate(A, b, options);
  const Eigen::Index m = A.rows();
  const Eigen::Index n = A.cols();
  const double tolerance = options.tolerance.value_or(
      10.0 * static_cast<double>(std::max(m, n)) * std::numeric_limits<double>::epsilon() *
      A.cwiseAbs().colwise().sum().maxCoeff() * b.lpNorm<Eigen::Infinity>());
  const std::size_t max_iterations =
      options.max_iterations.value_or(3 * static_cast<std::size_t>(n));

  // With more rows than columns, solve the equivalent n-row problem ||R x - (Q^T b)_{1..n}||.
  Eigen::MatrixXd M;
  Eigen::VectorXd c;
  if (m > n) {
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
    M = qr.matrixQR().topRows(n).triangularView<Eigen::Upper>();
    const Eigen::VectorXd qtb = qr.householderQ().adjoint() * b;
    c = qtb.head(n);
  } else {
    M = A;
    c = b;
  }

  NnlsResult result;
  result.tolerance = tolerance;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> is_passive(static_cast<std::size_t>(n), false);
  // Indices whose column did not reduce the residual when freed (rounding); retried after x moves.
  std::vector<bool> rejected(static_cast<std::size_t>(n), false);
  std::size_t iterations = 0;
  bool stopped = false;  // the iteration limit was reached

  while (!stopped) {
    const Eigen::VectorXd w = M.transpose() * (c - M * x);
    Eigen::Index entering = -1;
    for (Eigen::Index j = 0; j < n; ++j) {
      const auto uj = static_cast<std::size_t>(j);
      if (is_passive[uj] || rejected[uj] || !(w[j] > tolerance)) continue;
      if (entering < 0 || w[j] > w[entering]) entering = j;
    }
    if (entering < 0) break;
    if (iterations >= max_iterations) {
      stopped = true;
      break;
    }
    is_passive[static_cast<std::size_t>(entering)] = true;

    bool first = true;
    while (true) {
      std::vector<Eigen::Index> passive;
      for (Eigen::Index j = 0; j < n; ++j)
        if (is_passive[static_cast<std::size_t>(j)]) passive.push_back(j);
      const Eigen::VectorXd z = solve_passive(M, c, passive);
      ++iterations;
      if (first && !(z[entering] > 0.0)) {
        // Lawson & Hanson, step 6: freeing this variable does not help (its column is, within
        // rounding, a combination of the passive ones); keep it at 0 and try the next.
        is_passive[static_cast<std::size_t>(entering)] = false;
        rejected[static_cast<std::size_t>(entering)] = true;
        break;
      }
      first = false;
      bool feasible = true;
      for (Eigen::Index j : passive)
        feasible = feasible && z[j] > 0.0;
      if (feasible) {
        x = z;
        std::fill(rejected.begin(), rejected.end(), false);
        break;
      }
      // Step from x towards z as far as x >= 0 allows; the variables that reach 0 leave P.
      double alpha = std::numeric_limits<double>::infinity();
      Eigen::Index blocking = -1;
      for (Eigen::Index j : passive) {
        if (z[j] <= 0.0) {
          const double step = x[j] / (x[j] - z[j]);
          if (step < alpha) {
            alpha = step;
            blocking = j;
          }
        }
      }
      x += alpha * (z - x);
      x[blocking] = 0.0;
      for (Eigen::Index j : passive) {
        if (x[j] <= 0.0) {
          x[j] = 0.0;
          is_passive[static_cast<std::size_t>(j)] = false;
        }
      }
      std::fill(rejected.begin(), rejected.end(), false);
      if (iterations >= max_iterations) {
        stopped = true;
        break;
      }
    }
  }

  result.x = x;
  result.iterations = iterations;
  result.dual = A.transpose() * (b - A * x);
  result.residual_norm = (A * x - b).norm();
  const auto positive = (x.array() > 0.0).count();
  if (stopped) {
    result.termination = Termination::max_iterations;
    result.message = fmt::format(
        "stopped after max_iterations = {} least-squares solves; x is feasible but not optimal",
        max_iterations);
    return result;
  }
  Eigen::Index worst_rejected = -1;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (rejected[static_cast<std::size_t>(j)] &&
        (worst_rejected < 0 || result.dual[j] > result.dual[worst_rejected])) {
      worst_rejected = j;
    }
  }
  if (worst_rejected >= 0) {
    result.termination = Termination::no_progress;
    result.message = fmt::format(
        "w[{}] = {:.3g} exceeds the tolerance {:.3g}, but freeing x[{}] does not reduce the "
        "residual (rounding: its column is nearly a combination of others); {} of {} entries > 0",
        worst_rejected, result.dual[worst_rejected], tolerance, worst_rejected, positive, n);
  } else {
    result.termination = Termination::converged;
    result.message =
        fmt::format("KKT conditions hold within tolerance {:.3g}; {} of {} entries > 0", tolerance,
                    positive, n);
  }
  return result;
}

}  // namespace hyst
