#include "feedback_lfr_parametrisation.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

namespace hyst::detail {

using Eigen::Index;
using Eigen::MatrixXd;

FeedbackLfrParametrisation::FeedbackLfrParametrisation(const StateSpace& linear,
                                                       const SignalScales& scales,
                                                       const HystereticLfrFitOptions& options,
                                                       const std::string& fit)
    : linear_(linear, options.fit_poles, options.fit_io_matrices, options.max_pole_radius, fit),
      to_z_(scales.output.cwiseInverse()),
      input_scale_(scales.input.maxCoeff()),
      thresholds_(options.threshold_fractions),
      m_(Index(linear.inputs())),
      p_(Index(linear.outputs())),
      q_(options.feedback_channels > 0 ? Index(options.feedback_channels) : p_) {}

std::vector<double> FeedbackLfrParametrisation::initial() const {
  std::vector<double> theta(std::size_t(size()), 0.0);
  // T = I for q = p; channel i = k p + j: output j, plus half of output (j + k) mod p for k > 0.
  const auto t = [&](Index row, Index col) -> double& {
    return theta[std::size_t(m_ * q() + row + col * q())];
  };
  for (Index i = 0; i < q(); ++i) {
    const Index k = i / p_, j = i % p_;
    t(i, j) = 1.0;
    if (k > 0) t(i, (j + k) % p_) += 0.5;
  }
  // The plays r > 0 start weighted: with Theta = 0 the start is the linear model whatever the
  // weights, and they give Theta's derivative the hysteresis' shape. With them zero, a linear
  // model that already minimises the simulation error (one experiment, its frequency response
  // fitted) is a stationary point: Theta's derivative is then that of a linear feedback, zero at
  // that optimum, and the weights' and T's derivatives vanish with Theta.
  std::fill(theta.begin() + m_ * q() + q() * p_, theta.begin() + feedback_size(), kStartPlayWeight);
  return theta;
}

std::string FeedbackLfrParametrisation::description() const {
  return fmt::format("Theta, T, the PI weights ({} plays per channel) and {}", thresholds_.size(),
                     linear_.description());
}

LfrPoint FeedbackLfrParametrisation::at(const double* parameters) const {
  const Index m = m_, p = p_, q = this->q();
  const Eigen::Map<const MatrixXd> theta(parameters, m, q);
  const Eigen::Map<const MatrixXd> t(parameters + m * q, q, p);
  const double* linear_parameters = parameters + feedback_size();
  const auto base = linear_.params(linear_parameters);
  const Index n = base.a.rows();
  const MatrixXd to_z = t * to_z_.asDiagonal();
  const MatrixXd feedback = input_scale_ * theta;
  StateSpace::Params params;
  params.sample_time = base.sample_time;
  params.a = base.a;
  params.b.resize(n, m + q);
  params.b << base.b, base.b * feedback;
  params.c.resize(p + q, n);
  params.c << base.c, to_z * base.c;
  params.d.resize(p + q, m + q);
  params.d << base.d, base.d * feedback, to_z * base.d, MatrixXd::Zero(q, q);

  const Index weights_at = m * q + q * p;
  LfrPoint point{{StateSpace(std::move(params)), std::size_t(m),
                  pi_blocks(std::vector(std::size_t(q), thresholds_), parameters + weights_at)},
                 {},
                 pi_weight_derivatives(q, Index(thresholds_.size()), weights_at)};
  auto& entries = point.entries;
  const auto add = [&entries](LfrMatrix matrix, Index j, Index row, Index col, double value) {
    if (value != 0.0) entries.push_back({matrix, j, row, col, value});
  };
  for (Index b = 0; b < q; ++b)
    for (Index a = 0; a < m; ++a) {
      const Index j = a + b * m;  // Theta(a, b): B_w = B feedback, D_yw = D feedback
      for (Index r = 0; r < n; ++r)
        add(LfrMatrix::b, j, r, m + b, input_scale_ * base.b(r, a));
      for (Index r = 0; r < p; ++r)
        add(LfrMatrix::d, j, r, m + b, input_scale_ * base.d(r, a));
    }
  for (Index b = 0; b < p; ++b)
    for (Index a = 0; a < q; ++a) {
      const Index j = m * q + a + b * q;  // T(a, b): C_z = to_z C, D_zu = to_z D
      for (Index c = 0; c < n; ++c)
        add(LfrMatrix::c, j, p + a, c, to_z_[b] * base.c(b, c));
      for (Index c = 0; c < m; ++c)
        add(LfrMatrix::d, j, p + a, c, to_z_[b] * base.d(b, c));
    }
  // The linear block's own derivatives, through the same products.
  std::vector<MatrixEntryDerivative> own;
  linear_.derivatives(linear_parameters, feedback_size(), own);
  for (const auto& e : own) {
    switch (e.matrix) {
      case LfrMatrix::a:
        entries.push_back(e);
        break;
      case LfrMatrix::b:
        add(LfrMatrix::b, e.parameter, e.row, e.col, e.value);
        for (Index c = 0; c < q; ++c)
          add(LfrMatrix::b, e.parameter, e.row, m + c, e.value * feedback(e.col, c));
        break;
      case LfrMatrix::c:
        add(LfrMatrix::c, e.parameter, e.row, e.col, e.value);
        for (Index c = 0; c < q; ++c)
          add(LfrMatrix::c, e.parameter, p + c, e.col, e.value * to_z(c, e.row));
        break;
      case LfrMatrix::d:
        add(LfrMatrix::d, e.parameter, e.row, e.col, e.value);
        for (Index c = 0; c < q; ++c) {
          add(LfrMatrix::d, e.parameter, e.row, m + c, e.value * feedback(e.col, c));
          add(LfrMatrix::d, e.parameter, p + c, e.col, e.value * to_z(c, e.row));
        }
        break;
    }
  }
  return point;
}

}  // namespace hyst::detail
