#include "hammerstein_parametrisation.hpp"

#include <utility>

#include <fmt/format.h>

namespace hyst::detail {

using Eigen::Index;

HammersteinParametrisation::HammersteinParametrisation(const StateSpace& linear,
                                                       const SignalScales& scales,
                                                       const HammersteinFitOptions& options,
                                                       const std::string& fit)
    : linear_(linear, options.fit_poles, options.fit_io_matrices, options.max_pole_radius, fit) {
  for (Index i = 0; i < scales.input.size(); ++i) {
    thresholds_.push_back(options.threshold_fractions);
    for (double& r : thresholds_.back())
      r *= scales.input[i];
  }
}

std::vector<double> HammersteinParametrisation::initial() const {
  return std::vector<double>(std::size_t(size()), 0.0);
}

LfrPoint HammersteinParametrisation::at(const double* parameters) const {
  const double* linear_parameters = parameters + weights_size();
  const StateSpace linear(linear_.params(linear_parameters));
  const Index m = Index(linear.inputs());
  const Index plays = Index(thresholds_.front().size());
  LfrPoint point{
      HystereticLfr<PrandtlIshlinskii>::hammerstein(linear, pi_blocks(thresholds_, parameters)),
      {},
      pi_weight_derivatives(m, plays, 0)};
  std::vector<MatrixEntryDerivative> own;
  linear_.derivatives(linear_parameters, weights_size(), own);
  for (auto e : own) {
    // The Hammerstein LFR's inputs are (u, w) and its outputs (y, z): the block sees w.
    if (e.matrix == LfrMatrix::b || e.matrix == LfrMatrix::d) e.col += m;
    point.entries.push_back(e);
  }
  return point;
}

std::string HammersteinParametrisation::description() const {
  return fmt::format("the PI weights ({} plays per input) and {}", thresholds_.front().size(),
                     linear_.description());
}

}  // namespace hyst::detail
