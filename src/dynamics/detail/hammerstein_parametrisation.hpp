#pragma once
// The parametrisation of fit_hammerstein (its header explains the structure): each input's PI
// weights, then the linear block's parameters, with the derivative of every entry of the
// Hammerstein LFR (B = [0, B_lin], C = [C_lin; 0], D = [0, D_lin; I, 0]) that each moves.

#include <string>
#include <vector>

#include "hyst/dynamics/fit_hammerstein.hpp"
#include "lfr_parametrisation.hpp"
#include "linear_block_parameters.hpp"
#include "simulation_error_fit.hpp"

namespace hyst::detail {

class HammersteinParametrisation final : public LfrParametrisation {
 public:
  // Starts at the linear model (every weight of a play r > 0 zero). Throws hyst::Error as
  // LinearBlockParameters.
  HammersteinParametrisation(const StateSpace& linear, const SignalScales& scales,
                             const HammersteinFitOptions& options, const std::string& fit);

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
  std::vector<std::vector<double>> thresholds_;  // per input
};

}  // namespace hyst::detail
