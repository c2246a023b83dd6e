#pragma once
// A hysteretic LFR as a function of a parameter vector, with the derivative of every matrix entry
// and PI weight that a parameter moves: what a fit on the simulation error needs to compute the
// simulation's sensitivities analytically (lfr_sensitivity.hpp) instead of by differences.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hyst/dynamics/hysteretic_lfr.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace ceres {
class Problem;
}

namespace hyst::detail {

// The matrices of the LFR's whole linear block (StateSpace::Params of HystereticLfr::linear()):
// A (n x n), B (n x (m + q)), C ((p + q) x n), D ((p + q) x (m + q)).
enum class LfrMatrix { a, b, c, d };

// d M(row, col) / d parameter.
struct MatrixEntryDerivative {
  LfrMatrix matrix = LfrMatrix::a;
  Eigen::Index parameter = 0;
  Eigen::Index row = 0, col = 0;
  double value = 0.0;
};

// The parameter is the weight of play `play` of the PI model of feedback channel `channel`.
struct WeightDerivative {
  Eigen::Index parameter = 0;
  Eigen::Index channel = 0;
  Eigen::Index play = 0;
};

// The model at one parameter vector and what each parameter moves in it.
struct LfrPoint {
  HystereticLfr<PrandtlIshlinskii> model;
  std::vector<MatrixEntryDerivative> entries;
  std::vector<WeightDerivative> weights;
};

// A structure of LFR whose parameters a fit on the simulation error adjusts. Called once per
// evaluation of a whole realisation, never per sample.
class LfrParametrisation {
 public:
  virtual ~LfrParametrisation() = default;
  virtual Eigen::Index size() const = 0;
  virtual std::vector<double> initial() const = 0;
  // hyst::Error for parameters that make no valid model.
  virtual LfrPoint at(const double* parameters) const = 0;
  // Bounds on the parameters, if any, set on `problem` for the block `parameters`.
  virtual void bound(ceres::Problem& problem, double* parameters) const = 0;
  // What the fit adjusts, for the FitReport's method.
  virtual std::string description() const = 0;
};

// One PI model per channel with thresholds[i], the weight of its r = 0 play held at 1 (the linear
// part, whose scale the linear block carries) and the others from `weights`, channel by channel.
std::vector<PrandtlIshlinskii> pi_blocks(const std::vector<std::vector<double>>& thresholds,
                                         const double* weights);
// The parameters of pi_blocks' weights, numbered from `offset`.
std::vector<WeightDerivative> pi_weight_derivatives(Eigen::Index channels, Eigen::Index plays,
                                                    Eigen::Index offset);
// Throws hyst::Error (the message starting with `fit`) unless the fractions start at 0 and
// increase.
void check_threshold_fractions(const std::vector<double>& fractions, const std::string& fit);

}  // namespace hyst::detail
