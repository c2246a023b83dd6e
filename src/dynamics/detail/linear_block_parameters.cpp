#include "linear_block_parameters.hpp"

#include <algorithm>
#include <cmath>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::detail {

using Eigen::Index;
using Eigen::MatrixXd;

namespace {

// The RMS of a matrix's entries, or 1 for a zero matrix (its parameters then move it in units).
double rms_or_one(const MatrixXd& m) {
  const double rms = m.size() > 0 ? m.norm() / std::sqrt(double(m.size())) : 0.0;
  return rms > 0.0 && std::isfinite(rms) ? rms : 1.0;
}

}  // namespace

std::vector<LinearBlockParameters::ModalBlock> LinearBlockParameters::modal_blocks(
    const MatrixXd& a) {
  std::vector<ModalBlock> blocks;
  const Index n = a.rows();
  for (Index i = 0; i < n;) {
    const bool pair = i + 1 < n && a(i + 1, i) != 0.0;
    const Index size = pair ? 2 : 1;
    for (Index r = 0; r < n; ++r)
      for (Index c = i; c < i + size; ++c)
        if ((r < i || r >= i + size) && (a(r, c) != 0.0 || a(c, r) != 0.0)) return {};
    ModalBlock block{i, size};
    if (pair) {
      if (a(i, i) != a(i + 1, i + 1) || a(i, i + 1) != -a(i + 1, i)) return {};
      block.radius = std::hypot(a(i, i), a(i, i + 1));
      block.angle = std::atan2(a(i, i + 1), a(i, i));
    } else {
      block.radius = std::abs(a(i, i));
      block.sign = a(i, i) < 0.0 ? -1.0 : 1.0;
    }
    if (!(block.radius > 0.0)) return {};
    blocks.push_back(block);
    i += size;
  }
  return blocks;
}

LinearBlockParameters::LinearBlockParameters(const StateSpace& linear, bool poles, bool io_matrices,
                                             double max_pole_radius, const std::string& fit,
                                             Index zero_corner)
    : linear_(linear.params()), max_pole_radius_(max_pole_radius), zero_corner_(zero_corner) {
  if (poles) blocks_ = modal_blocks(linear_.a);
  for (const auto& block : blocks_) {
    // A pole that an earlier fit left on the bound may lie an ulp or so above it (the radius
    // comes back from its logarithm and from the 2 x 2 block): that is still on the bound.
    if (!(block.radius <= max_pole_radius * (1.0 + kPoleRadiusRounding)))
      throw Error(fmt::format("{}: a pole of the linear model has magnitude {}, above "
                              "max_pole_radius {}",
                              fit, block.radius, max_pole_radius),
                  "max_pole_radius");
    pole_parameters_ += block.size;
  }
  if (io_matrices) {
    io_parameters_ =
        linear_.b.size() + linear_.c.size() + linear_.d.size() - zero_corner * zero_corner;
    b_scale_ = rms_or_one(linear_.b);
    c_scale_ = rms_or_one(linear_.c);
    d_scale_ = rms_or_one(linear_.d);
  }
}

StateSpace::Params LinearBlockParameters::params(const double* parameters) const {
  StateSpace::Params result = linear_;
  const double* pole = parameters;
  for (const auto& block : blocks_) {
    const double radius = block.radius * std::exp(*pole++);
    const Index i = block.at;
    if (block.size == 1) {
      result.a(i, i) = block.sign * radius;
      continue;
    }
    const double angle = block.angle + *pole++;
    result.a(i, i) = result.a(i + 1, i + 1) = radius * std::cos(angle);
    result.a(i, i + 1) = radius * std::sin(angle);
    result.a(i + 1, i) = -result.a(i, i + 1);
  }
  if (io_parameters_ == 0) return result;
  const double* io = parameters + pole_parameters_;
  const auto shift = [&io](MatrixXd& m, double scale) {
    m += scale * Eigen::Map<const MatrixXd>(io, m.rows(), m.cols());
    io += m.size();
  };
  shift(result.b, b_scale_);
  shift(result.c, c_scale_);
  for (Index c = 0; c < result.d.cols(); ++c)
    for (Index r = 0; r < result.d.rows(); ++r)
      if (is_parameter_of_d(r, c)) result.d(r, c) += d_scale_ * *io++;
  return result;
}

void LinearBlockParameters::derivatives(const double* parameters, Index offset,
                                        std::vector<MatrixEntryDerivative>& out) const {
  Index j = offset;
  const double* pole = parameters;
  for (const auto& block : blocks_) {
    const double radius = block.radius * std::exp(*pole++);
    const Index i = block.at;
    if (block.size == 1) {
      out.push_back({LfrMatrix::a, j++, i, i, block.sign * radius});
      continue;
    }
    const double angle = block.angle + *pole++;
    const double re = radius * std::cos(angle), im = radius * std::sin(angle);
    // d/d log radius: the block itself; d/d angle: the block turned by a quarter.
    out.push_back({LfrMatrix::a, j, i, i, re});
    out.push_back({LfrMatrix::a, j, i + 1, i + 1, re});
    out.push_back({LfrMatrix::a, j, i, i + 1, im});
    out.push_back({LfrMatrix::a, j, i + 1, i, -im});
    ++j;
    out.push_back({LfrMatrix::a, j, i, i, -im});
    out.push_back({LfrMatrix::a, j, i + 1, i + 1, -im});
    out.push_back({LfrMatrix::a, j, i, i + 1, re});
    out.push_back({LfrMatrix::a, j, i + 1, i, -re});
    ++j;
  }
  if (io_parameters_ == 0) return;
  const auto each = [&](LfrMatrix matrix, const MatrixXd& m, double scale) {
    for (Index c = 0; c < m.cols(); ++c)
      for (Index r = 0; r < m.rows(); ++r)
        if (matrix != LfrMatrix::d || is_parameter_of_d(r, c))
          out.push_back({matrix, j++, r, c, scale});
  };
  each(LfrMatrix::b, linear_.b, b_scale_);
  each(LfrMatrix::c, linear_.c, c_scale_);
  each(LfrMatrix::d, linear_.d, d_scale_);
}

void LinearBlockParameters::bound(ceres::Problem& problem, double* block, Index offset) const {
  Index at = offset;
  for (const auto& b : blocks_) {
    problem.SetParameterUpperBound(block, int(at),
                                   std::max(0.0, std::log(max_pole_radius_ / b.radius)));
    at += b.size;
  }
}

std::string LinearBlockParameters::description() const {
  if (poles_free() && io_matrices_free()) return "the linear block's poles, B, C and D";
  if (poles_free()) return "the linear block's poles (B, C and D fixed)";
  if (io_matrices_free()) return "the linear block's B, C and D (its poles fixed)";
  return "the linear block fixed";
}

}  // namespace hyst::detail
