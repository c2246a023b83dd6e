#include "hyst/dynamics/state_transition.hpp"

namespace hyst {

using Eigen::Index;

StateTransition::StateTransition(const Eigen::MatrixXd& a) {
  // Blocks where the first sub- or super-diagonal joins two states, then one pass over A: every
  // non-zero entry must join states of one block.
  const Index n = a.rows();
  std::vector<Index> block_of(std::size_t(n), 0);
  for (Index i = 0; i < n;) {
    const Index size = i + 1 < n && (a(i + 1, i) != 0.0 || a(i, i + 1) != 0.0) ? 2 : 1;
    Block block{i, size, a(i, i)};
    if (size == 2) {
      block.a01 = a(i, i + 1);
      block.a10 = a(i + 1, i);
      block.a11 = a(i + 1, i + 1);
    }
    for (Index k = i; k < i + size; ++k)
      block_of[std::size_t(k)] = Index(blocks_.size());
    blocks_.push_back(block);
    i += size;
  }
  for (Index c = 0; c < n; ++c)
    for (Index r = 0; r < n; ++r)
      if (a(r, c) != 0.0 && block_of[std::size_t(r)] != block_of[std::size_t(c)]) {
        blocks_.clear();
        dense_ = a;
        return;
      }
}

void StateTransition::apply(const Eigen::VectorXd& x, Eigen::VectorXd& out) const noexcept {
  if (!block_diagonal()) {
    out.noalias() = dense_ * x;
    return;
  }
  for (const Block& block : blocks_) {
    const Index i = block.at;
    if (block.size == 1) {
      out[i] = block.a00 * x[i];
    } else {
      out[i] = block.a00 * x[i] + block.a01 * x[i + 1];
      out[i + 1] = block.a10 * x[i] + block.a11 * x[i + 1];
    }
  }
}

void StateTransition::apply_rows(const Eigen::MatrixXd& x, Eigen::MatrixXd& out) const noexcept {
  if (!block_diagonal()) {
    out.noalias() = x * dense_.transpose();
    return;
  }
  for (const Block& block : blocks_) {
    const Index i = block.at;
    if (block.size == 1) {
      out.col(i) = block.a00 * x.col(i);
    } else {
      out.col(i) = block.a00 * x.col(i) + block.a01 * x.col(i + 1);
      out.col(i + 1) = block.a10 * x.col(i) + block.a11 * x.col(i + 1);
    }
  }
}

}  // namespace hyst
