#pragma once
//! \file
//! Exact zero-order-hold discretisation of a linear system x' = A x + B u: with u held constant
//! over one period h, x[k+1] = Phi x[k] + Gamma u[k], where
//!
//!     exp([[A, B], [0, 0]] h) = [[Phi, Gamma], [0, I]]
//!
//! (the augmented-matrix exponential; Eigen's MatrixFunctions, Pade approximation with scaling
//! and squaring). Computed once when a block is built, never per sample.

#include <Eigen/Core>

namespace hyst {

struct ZeroOrderHold {
  Eigen::MatrixXd transition;  //!< Phi = exp(A h)
  Eigen::MatrixXd input;       //!< Gamma = int_0^h exp(A s) ds B
};

//! Phi and Gamma of (A, B) for the period h > 0. Throws hyst::Error when A is not square, B has
//! a different number of rows, h is not finite and positive or an entry is not finite.
ZeroOrderHold zero_order_hold(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double period);

}  // namespace hyst
