#pragma once
// A hysteretic LFR with PI feedback and every matrix free: the poles (real modal form), B, C and D
// of its whole linear block (so the feedback paths Bw, Cz, Dyw and Dzu no longer follow the
// actuators' B, C and D) and the PI weights, starting from a given model. Its zero Dzw stays zero
// and each PI's r = 0 weight stays at 1 (the linear block carries the scale). Where the feedback
// structure of fit_hysteretic_lfr ties the hysteresis to the actuators' paths, this one lets the
// fit find where it acts in the structure; it starts from that structure's fit, since at zero
// feedback (Bw = 0) the paths that drive it have no gradient.

#include <string>
#include <vector>

#include "hyst/dynamics/hysteretic_lfr.hpp"
#include "lfr_parametrisation.hpp"
#include "linear_block_parameters.hpp"

namespace hyst::detail {

class GeneralLfrParametrisation final : public LfrParametrisation {
 public:
  // Throws hyst::Error (the message starting with `fit`) for a feedback model whose r = 0 weight is
  // not 1, PI models of different play counts, or a pole beyond max_pole_radius.
  GeneralLfrParametrisation(const HystereticLfr<PrandtlIshlinskii>& start, bool poles,
                            double max_pole_radius, const std::string& fit);

  Eigen::Index size() const override { return weights_size() + linear_.size(); }
  std::vector<double> initial() const override;
  LfrPoint at(const double* parameters) const override;
  void bound(ceres::Problem& problem, double* parameters) const override {
    linear_.bound(problem, parameters, weights_size());
  }
  std::string description() const override;

 private:
  Eigen::Index weights_size() const {
    return Eigen::Index(thresholds_.size() * (thresholds_.front().size() - 1));
  }

  LinearBlockParameters linear_;
  std::vector<std::vector<double>> thresholds_;  // per channel
  std::vector<double> weights_;                  // the start's, r > 0, channel by channel
  std::size_t inputs_ = 0;
};

}  // namespace hyst::detail
