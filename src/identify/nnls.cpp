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

// With more rows than columns, the equivalent n-row problem ||R x - (Q^T b)_{1..n}||.
struct ReducedProblem {
  Eigen::MatrixXd M;
  Eigen::VectorXd c;
};

ReducedProblem reduced_problem(const Eigen::Ref<const Eigen::MatrixXd>& A,
                               const Eigen::Ref<const Eigen::VectorXd>& b) {
  const Eigen::Index n = A.cols();
  if (A.rows() <= n) return {A, b};
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
  ReducedProblem reduced;
  reduced.M = qr.matrixQR().topRows(n).triangularView<Eigen::Upper>();
  const Eigen::VectorXd qtb = qr.householderQ().adjoint() * b;
  reduced.c = qtb.head(n);
  return reduced;
}

// The Lawson-Hanson active-set iteration on the reduced problem.
class ActiveSet {
 public:
  ActiveSet(const ReducedProblem& problem, double tolerance, std::size_t max_iterations)
      : M_(problem.M),
        c_(problem.c),
        tolerance_(tolerance),
        max_iterations_(max_iterations),
        x_(Eigen::VectorXd::Zero(M_.cols())),
        is_passive_(static_cast<std::size_t>(M_.cols()), false),
        rejected_(static_cast<std::size_t>(M_.cols()), false) {}

  void run() {
    while (!stopped_) {
      const Eigen::Index entering = entering_variable();
      if (entering < 0) break;
      if (iterations_ >= max_iterations_) {
        stopped_ = true;
        break;
      }
      free_variable(entering);
    }
  }

  const Eigen::VectorXd& x() const { return x_; }
  std::size_t iterations() const { return iterations_; }
  bool stopped() const { return stopped_; }  // the iteration limit was reached
  bool rejected(Eigen::Index j) const { return rejected_[static_cast<std::size_t>(j)]; }

 private:
  // The variable of largest dual value above the tolerance; -1 when there is none (optimal).
  Eigen::Index entering_variable() const {
    const Eigen::VectorXd w = M_.transpose() * (c_ - M_ * x_);
    Eigen::Index entering = -1;
    for (Eigen::Index j = 0; j < M_.cols(); ++j) {
      const auto uj = static_cast<std::size_t>(j);
      if (is_passive_[uj] || rejected_[uj] || !(w[j] > tolerance_)) continue;
      if (entering < 0 || w[j] > w[entering]) entering = j;
    }
    return entering;
  }

  // Moves `entering` into the passive set and solves until the passive solution is feasible.
  void free_variable(Eigen::Index entering) {
    is_passive_[static_cast<std::size_t>(entering)] = true;
    bool first = true;
    while (true) {
      std::vector<Eigen::Index> passive;
      for (Eigen::Index j = 0; j < M_.cols(); ++j)
        if (is_passive_[static_cast<std::size_t>(j)]) passive.push_back(j);
      const Eigen::VectorXd z = solve_passive(M_, c_, passive);
      ++iterations_;
      if (first && !(z[entering] > 0.0)) {
        // Lawson & Hanson, step 6: freeing this variable does not help (its column is, within
        // rounding, a combination of the passive ones); keep it at 0 and try the next.
        is_passive_[static_cast<std::size_t>(entering)] = false;
        rejected_[static_cast<std::size_t>(entering)] = true;
        return;
      }
      first = false;
      bool feasible = true;
      for (Eigen::Index j : passive)
        feasible = feasible && z[j] > 0.0;
      if (feasible) {
        x_ = z;
        std::fill(rejected_.begin(), rejected_.end(), false);
        return;
      }
      step_towards(z, passive);
      std::fill(rejected_.begin(), rejected_.end(), false);
      if (iterations_ >= max_iterations_) {
        stopped_ = true;
        return;
      }
    }
  }

  // Step from x towards z as far as x >= 0 allows; the variables that reach 0 leave P.
  void step_towards(const Eigen::VectorXd& z, const std::vector<Eigen::Index>& passive) {
    double alpha = std::numeric_limits<double>::infinity();
    Eigen::Index blocking = -1;
    for (Eigen::Index j : passive) {
      if (z[j] <= 0.0) {
        const double step = x_[j] / (x_[j] - z[j]);
        if (step < alpha) {
          alpha = step;
          blocking = j;
        }
      }
    }
    x_ += alpha * (z - x_);
    x_[blocking] = 0.0;
    for (Eigen::Index j : passive) {
      if (x_[j] <= 0.0) {
        x_[j] = 0.0;
        is_passive_[static_cast<std::size_t>(j)] = false;
      }
    }
  }

  const Eigen::MatrixXd& M_;
  const Eigen::VectorXd& c_;
  double tolerance_;
  std::size_t max_iterations_;
  Eigen::VectorXd x_;
  std::vector<bool> is_passive_;
  // Indices whose column did not reduce the residual when freed (rounding); retried after x moves.
  std::vector<bool> rejected_;
  std::size_t iterations_ = 0;
  bool stopped_ = false;
};

// How the iteration ended, by the KKT conditions of the original problem.
void conclude(NnlsResult& result, const ActiveSet& solver, std::size_t max_iterations) {
  const Eigen::Index n = result.x.size();
  const auto positive = (result.x.array() > 0.0).count();
  if (solver.stopped()) {
    result.termination = Termination::max_iterations;
    result.message = fmt::format(
        "stopped after max_iterations = {} least-squares solves; x is feasible but not optimal",
        max_iterations);
    return;
  }
  Eigen::Index worst_rejected = -1;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (solver.rejected(j) &&
        (worst_rejected < 0 || result.dual[j] > result.dual[worst_rejected])) {
      worst_rejected = j;
    }
  }
  if (worst_rejected >= 0) {
    result.termination = Termination::no_progress;
    result.message = fmt::format(
        "w[{}] = {:.3g} exceeds the tolerance {:.3g}, but freeing x[{}] does not reduce the "
        "residual (rounding: its column is nearly a combination of others); {} of {} entries > 0",
        worst_rejected, result.dual[worst_rejected], result.tolerance, worst_rejected, positive, n);
  } else {
    result.termination = Termination::converged;
    result.message =
        fmt::format("KKT conditions hold within tolerance {:.3g}; {} of {} entries > 0",
                    result.tolerance, positive, n);
  }
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

  const ReducedProblem problem = reduced_problem(A, b);
  ActiveSet solver(problem, tolerance, max_iterations);
  solver.run();

  NnlsResult result;
  result.tolerance = tolerance;
  result.x = solver.x();
  result.iterations = solver.iterations();
  result.dual = A.transpose() * (b - A * result.x);
  result.residual_norm = (A * result.x - b).norm();
  conclude(result, solver, max_iterations);
  return result;
}

}  // namespace hyst
