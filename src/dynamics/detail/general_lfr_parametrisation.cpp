#include "general_lfr_parametrisation.hpp"

#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::detail {

using Eigen::Index;

GeneralLfrParametrisation::GeneralLfrParametrisation(const HystereticLfr<PrandtlIshlinskii>& start,
                                                     bool poles, double max_pole_radius,
                                                     const std::string& fit)
    : linear_(start.linear(), poles, true, max_pole_radius, fit, Index(start.feedback().size())),
      inputs_(start.inputs()) {
  for (const auto& pi : start.feedback()) {
    const auto& p = pi.params();
    if (p.weights.front() != 1.0 || p.offset != 0.0)
      throw Error(
          fmt::format("{}: the start's PI models need the r = 0 weight 1 and no offset "
                      "(the linear block carries the scale)",
                      fit));
    if (!thresholds_.empty() && p.thresholds.size() != thresholds_.front().size())
      throw Error(fmt::format("{}: the start's PI models have different numbers of plays", fit));
    thresholds_.push_back(p.thresholds);
    weights_.insert(weights_.end(), p.weights.begin() + 1, p.weights.end());
  }
  if (thresholds_.empty()) throw Error(fit + ": the start has no feedback channel");
}

std::vector<double> GeneralLfrParametrisation::initial() const {
  std::vector<double> theta(std::size_t(size()), 0.0);
  std::copy(weights_.begin(), weights_.end(), theta.begin());
  return theta;
}

LfrPoint GeneralLfrParametrisation::at(const double* parameters) const {
  const double* linear_parameters = parameters + weights_size();
  const auto q = Index(thresholds_.size());
  LfrPoint point{
      {StateSpace(linear_.params(linear_parameters)), inputs_, pi_blocks(thresholds_, parameters)},
      {},
      pi_weight_derivatives(q, Index(thresholds_.front().size()), 0)};
  linear_.derivatives(linear_parameters, weights_size(), point.entries);
  return point;
}

std::string GeneralLfrParametrisation::description() const {
  return fmt::format("the PI weights ({} plays per channel) and every matrix of the LFR ({})",
                     thresholds_.front().size(), linear_.description());
}

}  // namespace hyst::detail
