// The analytic Jacobian of the state-space fit's residuals against central differences, for every
// parameter of every block (complex pole pairs, a real pole, B, C, D), MIMO and weighted.

#include "../../src/identify/detail/frequency_response_residual.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace hyst {
namespace {

TEST(FrequencyResponseResidual, JacobianMatchesCentralDifferences) {
  std::mt19937_64 random(4);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const std::size_t pairs = 2, reals = 1, m = 2, p = 3, n = 2 * pairs + reals;
  detail::FrequencyData data;
  data.inputs = Eigen::Index(m);
  data.outputs = Eigen::Index(p);
  for (const double angle : {0.05, 0.7, 2.9}) {
    data.z.push_back(std::polar(1.0, angle));
    data.response.push_back(Eigen::MatrixXcd::Random(Eigen::Index(p), Eigen::Index(m)));
    data.weight.push_back(Eigen::MatrixXd::Random(Eigen::Index(p), Eigen::Index(m)).cwiseAbs() +
                          Eigen::MatrixXd::Constant(Eigen::Index(p), Eigen::Index(m), 0.5));
  }
  std::vector<std::vector<double>> blocks = {{0.9, 0.3, 0.7, 1.9, -0.6},
                                             std::vector<double>(n * m),
                                             std::vector<double>(p * n),
                                             std::vector<double>(p * m)};
  for (std::size_t b = 1; b < 4; ++b)
    for (double& v : blocks[b])
      v = uniform(random);

  for (std::size_t line = 0; line < data.z.size(); ++line) {
    const detail::LineResidual residual(data, line, pairs, reals);
    const int rows = residual.num_residuals();
    std::vector<const double*> parameters;
    for (auto& block : blocks)
      parameters.push_back(block.data());
    std::vector<double> values(static_cast<std::size_t>(rows));
    std::vector<std::vector<double>> jacobians(4);
    std::vector<double*> jacobian_pointers;
    for (std::size_t b = 0; b < 4; ++b) {
      jacobians[b].resize(std::size_t(rows) * blocks[b].size());
      jacobian_pointers.push_back(jacobians[b].data());
    }
    ASSERT_TRUE(residual.Evaluate(parameters.data(), values.data(), jacobian_pointers.data()));
    for (std::size_t b = 0; b < 4; ++b)
      for (std::size_t k = 0; k < blocks[b].size(); ++k) {
        const double saved = blocks[b][k];
        const double h = 1e-6;
        std::vector<double> plus(static_cast<std::size_t>(rows));
        std::vector<double> minus(static_cast<std::size_t>(rows));
        blocks[b][k] = saved + h;
        residual.Evaluate(parameters.data(), plus.data(), nullptr);
        blocks[b][k] = saved - h;
        residual.Evaluate(parameters.data(), minus.data(), nullptr);
        blocks[b][k] = saved;
        for (int r = 0; r < rows; ++r) {
          const double numeric = (plus[std::size_t(r)] - minus[std::size_t(r)]) / (2.0 * h);
          const double analytic = jacobians[b][std::size_t(r) * blocks[b].size() + k];
          EXPECT_NEAR(analytic, numeric, 1e-7 * (1.0 + std::abs(numeric)))
              << "line " << line << " block " << b << " parameter " << k << " residual " << r;
        }
      }
  }
}

}  // namespace
}  // namespace hyst
