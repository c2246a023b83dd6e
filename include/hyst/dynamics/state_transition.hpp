#pragma once
//! \file
//! The product A x of a state-space step, cheap when A is block diagonal with blocks of size 1 and
//! 2: the real modal form that fit_state_space() returns, where a 28th-order A has 56 non-zero
//! entries of its 784. Any other A is multiplied as the dense matrix it is. Both give the same
//! numbers: the skipped terms are exact zeros.

#include <vector>

#include <Eigen/Dense>

namespace hyst {

class StateTransition {
 public:
  explicit StateTransition(const Eigen::MatrixXd& a);

  //! out = A x; `out` has the size of x and is another vector. No allocation.
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& out) const noexcept;

  //! out = X A^T: A applied to every row of X (each row a vector of the state's size, such as the
  //! state's derivative by one parameter); `out` has the size of X and is another matrix.
  void apply_rows(const Eigen::MatrixXd& x, Eigen::MatrixXd& out) const noexcept;

  //! Whether A was found block diagonal (blocks of size 1 or 2).
  bool block_diagonal() const { return dense_.size() == 0; }

 private:
  struct Block {
    Eigen::Index at = 0;
    Eigen::Index size = 1;
    double a00 = 0.0, a01 = 0.0, a10 = 0.0, a11 = 0.0;
  };
  std::vector<Block> blocks_;
  Eigen::MatrixXd dense_;  // empty when blocks_ holds A
};

}  // namespace hyst
