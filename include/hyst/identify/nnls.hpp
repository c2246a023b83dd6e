#pragma once
//! \file
//! Non-negative least squares (NNLS) by the active-set method of Lawson and Hanson.
//!
//!     min_x ||A x - b||^2   subject to   x >= 0          A: m x n, b: m
//!
//! Optimality (Karush-Kuhn-Tucker) with the dual vector w = A^T (b - A x), the negative gradient of
//! 0.5 ||A x - b||^2:
//!
//!     x >= 0,   w_j <= 0 where x_j = 0,   w_j = 0 where x_j > 0.
//!
//! The method keeps a passive set P (the free variables) and a feasible x. Each outer iteration
//! moves the index with the largest w_j > tolerance into P and solves the unconstrained least-
//! squares problem on the columns of P (Householder QR with column pivoting); while that solution
//! has a non-positive entry it steps from x towards it as far as feasibility allows and returns
//! the variables that reached 0 to the active set. It stops when no w_j exceeds the tolerance.
//! When m > n the problem is first reduced to n rows by one QR factorisation of A
//! (||A x - b||^2 = ||R x - Q^T b||^2 + const), so each subproblem costs O(n^3), not O(m n^2).
//!
//! Rank-deficient A is allowed: x is then not unique, the residual is. The result is always
//! feasible (x >= 0), also when the iteration limit stops the method early.
//! Source: C. L. Lawson, R. J. Hanson, "Solving Least Squares Problems", Prentice-Hall 1974 (SIAM
//! 1995), chapter 23, algorithm NNLS.

#include <cstddef>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "hyst/identify/fit_report.hpp"

namespace hyst {

struct NnlsOptions {
  //! Limit on the least-squares subproblems solved (each addition to P and each step back counts
  //! one); not set = 3 n. Must be >= 1.
  std::optional<std::size_t> max_iterations{};
  //! The method has converged when every w_j of the active set is <= tolerance [units of A^T b].
  //! Not set = 10 max(m, n) eps ||A||_1 ||b||_inf, the rounding error of computing w. Must be
  //! finite and >= 0.
  std::optional<double> tolerance{};
};

struct NnlsResult {
  Eigen::VectorXd x;           //!< the solution, every entry >= 0
  Eigen::VectorXd dual;        //!< w = A^T (b - A x): <= tolerance where x_j = 0, ~0 where x_j > 0
  std::size_t iterations = 0;  //!< least-squares subproblems solved
  Termination termination = Termination::failed;
  std::string message;         //!< how it ended, in words
  double residual_norm = 0.0;  //!< ||A x - b||_2
  double tolerance = 0.0;      //!< the tolerance that was used

  bool converged() const { return termination == Termination::converged; }
};

//! Solves min ||A x - b||^2 subject to x >= 0. Throws hyst::Error when A has no rows or columns,
//! b's length differs from A's rows, an entry is not finite ("NNLS matrix A(3, 1) = nan is not
//! finite"), or an option is invalid. The outcome of the iteration is reported, not thrown.
NnlsResult nnls(const Eigen::Ref<const Eigen::MatrixXd>& A,
                const Eigen::Ref<const Eigen::VectorXd>& b, const NnlsOptions& options = {});

}  // namespace hyst
