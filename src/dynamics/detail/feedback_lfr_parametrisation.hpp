#pragma once
// The parametrisation of fit_hysteretic_lfr (its header explains the structure): the feedback's
// Theta, T and PI weights and the linear block's parameters, with the derivative of every entry
// of the LFR that each moves.

#include <string>
#include <vector>

#include "hyst/dynamics/fit_hysteretic_lfr.hpp"
#include "lfr_parametrisation.hpp"
#include "linear_block_parameters.hpp"
#include "simulation_error_fit.hpp"

namespace hyst::detail {

// The feedback structure of fit_hysteretic_lfr.hpp. Parameters: Theta (m x q), T (q x p), both
// column-major, then each channel's weights of the plays r > 0, then the linear block's
// (LinearBlockParameters). Scales make them dimensionless: z = T diag(1 / output_scale) y,
// u_eff = u + input_scale Theta w.
class FeedbackLfrParametrisation final : public LfrParametrisation {
 public:
  // The starting weight of every play r > 0 (the r = 0 one is held at 1).
  static constexpr double kStartPlayWeight = 0.1;

  // Starts at Theta = 0, T = I: the linear model (see initial() for why the weights of the plays
  // r > 0 start at kStartPlayWeight). Throws hyst::Error as LinearBlockParameters.
  FeedbackLfrParametrisation(const StateSpace& linear, const SignalScales& scales,
                             const HystereticLfrFitOptions& options, const std::string& fit);

  Eigen::Index size() const override { return feedback_size() + linear_.size(); }
  std::vector<double> initial() const override;
  LfrPoint at(const double* parameters) const override;
  void bound(ceres::Problem& problem, double* parameters) const override {
    linear_.bound(problem, parameters, feedback_size());
  }
  std::string description() const override;

 private:
  Eigen::Index q() const { return q_; }
  Eigen::Index feedback_size() const {
    return m_ * q() + q() * p_ + q() * Eigen::Index(thresholds_.size() - 1);
  }

  LinearBlockParameters linear_;
  Eigen::VectorXd to_z_;  // 1 / the largest |y_k| over the data
  double input_scale_;    // the largest |u| over the data
  std::vector<double> thresholds_;
  Eigen::Index m_, p_, q_;
};

}  // namespace hyst::detail
