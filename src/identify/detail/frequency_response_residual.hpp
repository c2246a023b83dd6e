#pragma once
// The residuals of the state-space fit's second stage at one frequency line, with their analytic
// Jacobian: the model in real modal form (fit_state_space.cpp), the BLA's response and weights.

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <ceres/ceres.h>
#include <Eigen/Dense>

namespace hyst::detail {

using Complex = std::complex<double>;

//! The BLA as the fit sees it: points on the unit circle, responses, residual weights (1/sigma).
struct FrequencyData {
  std::vector<Complex> z;
  std::vector<Eigen::MatrixXcd> response;
  std::vector<Eigen::MatrixXd> weight;
  Eigen::Index inputs = 0;
  Eigen::Index outputs = 0;
};

//! Stage 2's residuals at one line: weighted real and imaginary parts of G_model - G_BLA, with
//! the analytic Jacobian. Parameter blocks: poles, B (row-major), C (row-major), D (row-major).
class LineResidual final : public ceres::CostFunction {
 public:
  LineResidual(const FrequencyData& data, std::size_t line, std::size_t pairs, std::size_t reals)
      : z_(data.z[line]),
        target_(data.response[line]),
        weight_(data.weight[line]),
        pairs_(Eigen::Index(pairs)),
        reals_(Eigen::Index(reals)),
        m_(data.inputs),
        p_(data.outputs) {
    const Eigen::Index n = 2 * pairs_ + reals_;
    set_num_residuals(int(2 * p_ * m_));
    *mutable_parameter_block_sizes() = {int(2 * pairs_ + reals_), int(n * m_), int(p_ * n),
                                        int(p_ * m_)};
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const double* poles = parameters[0];
    const double* b = parameters[1];
    const double* c = parameters[2];
    const double* d = parameters[3];
    const Eigen::Index n = 2 * pairs_ + reals_;
    const Eigen::Index poles_size = 2 * pairs_ + reals_;
    Eigen::MatrixXcd g(p_, m_);
    for (Eigen::Index i = 0; i < p_; ++i)
      for (Eigen::Index j = 0; j < m_; ++j)
        g(i, j) = d[i * m_ + j];
    if (jacobians != nullptr)
      for (int block = 0; block < 4; ++block)
        if (jacobians[block] != nullptr)
          std::fill_n(jacobians[block], num_residuals() * parameter_block_sizes()[block], 0.0);
    // d residual(i, j) / d parameter, weighted, into a block's row-major Jacobian.
    const auto put = [&](int block, Eigen::Index size, Eigen::Index parameter, Eigen::Index i,
                         Eigen::Index j, Complex value) {
      if (jacobians == nullptr || jacobians[block] == nullptr) return;
      const double w = weight_(i, j);
      const Eigen::Index row = 2 * (i * m_ + j);
      jacobians[block][row * size + parameter] = w * value.real();
      jacobians[block][(row + 1) * size + parameter] = w * value.imag();
    };
    Eigen::MatrixXcd left(p_, 2);
    Eigen::MatrixXcd right(2, m_);
    for (Eigen::Index mode = 0; mode < pairs_ + reals_; ++mode) {
      const bool pair = mode < pairs_;
      const Eigen::Index s = pair ? 2 * mode : 2 * pairs_ + (mode - pairs_);
      const Eigen::Index width = pair ? 2 : 1;
      Complex d_first_parameter[2];  // factors of the pole parameters' derivatives
      if (pair) {
        const double rho = poles[2 * mode];
        const double theta = poles[2 * mode + 1];
        const double re = rho * std::cos(theta);
        const double im = rho * std::sin(theta);
        const Complex w = z_ - re;
        const Complex det = w * w + im * im;
        // (zI - A_mode)^-1 = [w, im; -im, w] / det
        for (Eigen::Index j = 0; j < m_; ++j) {
          right(0, j) = (w * b[s * m_ + j] + im * b[(s + 1) * m_ + j]) / det;
          right(1, j) = (-im * b[s * m_ + j] + w * b[(s + 1) * m_ + j]) / det;
        }
        for (Eigen::Index i = 0; i < p_; ++i) {
          left(i, 0) = (c[i * n + s] * w - c[i * n + s + 1] * im) / det;
          left(i, 1) = (c[i * n + s] * im + c[i * n + s + 1] * w) / det;
        }
        d_first_parameter[0] = {std::cos(theta),
                                std::sin(theta)};  // d/d rho = (cos, sin).(d/dre, d/dim)
        d_first_parameter[1] = {-im, re};          // d/d theta
      } else {
        const Complex inverse = 1.0 / (z_ - poles[s]);
        for (Eigen::Index j = 0; j < m_; ++j)
          right(0, j) = b[s * m_ + j] * inverse;
        for (Eigen::Index i = 0; i < p_; ++i)
          left(i, 0) = c[i * n + s] * inverse;
      }
      for (Eigen::Index i = 0; i < p_; ++i)
        for (Eigen::Index j = 0; j < m_; ++j) {
          Complex sum = 0.0;
          for (Eigen::Index t = 0; t < width; ++t)
            sum += c[i * n + s + t] * right(t, j);
          g(i, j) += sum;
        }
      if (jacobians == nullptr) continue;
      for (Eigen::Index i = 0; i < p_; ++i)
        for (Eigen::Index j = 0; j < m_; ++j) {
          for (Eigen::Index t = 0; t < width; ++t) {
            put(1, n * m_, (s + t) * m_ + j, i, j, left(i, t));
            put(2, p_ * n, i * n + s + t, i, j, right(t, j));
          }
          if (pair) {
            // dG/dre = L R, dG/dim = L J R with J = [0 1; -1 0]
            const Complex d_re = left(i, 0) * right(0, j) + left(i, 1) * right(1, j);
            const Complex d_im = left(i, 0) * right(1, j) - left(i, 1) * right(0, j);
            put(0, poles_size, 2 * mode, i, j,
                d_first_parameter[0].real() * d_re + d_first_parameter[0].imag() * d_im);
            put(0, poles_size, 2 * mode + 1, i, j,
                d_first_parameter[1].real() * d_re + d_first_parameter[1].imag() * d_im);
          } else {
            put(0, poles_size, s, i, j, left(i, 0) * right(0, j));
          }
          put(3, p_ * m_, i * m_ + j, i, j, 1.0);
        }
    }
    for (Eigen::Index i = 0; i < p_; ++i)
      for (Eigen::Index j = 0; j < m_; ++j) {
        const Complex e = (g(i, j) - target_(i, j)) * weight_(i, j);
        residuals[2 * (i * m_ + j)] = e.real();
        residuals[2 * (i * m_ + j) + 1] = e.imag();
      }
    return true;
  }

 private:
  Complex z_;
  Eigen::MatrixXcd target_;
  Eigen::MatrixXd weight_;
  Eigen::Index pairs_;
  Eigen::Index reals_;
  Eigen::Index m_;
  Eigen::Index p_;
};

}  // namespace hyst::detail
