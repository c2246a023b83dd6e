#pragma once
// The parameters of a fitted linear block that a fit on the simulation error frees: the poles,
// when A is in real modal form (what fit_state_space returns), as the change of log |pole| and of
// the angle of each pair; and B, C and D as their fitted values plus a scale (the RMS of the
// fitted entries) times the parameters. Every parameter is dimensionless and starts at 0. An LFR's
// whole linear block can be freed too: its Dzw corner (hysteresis output to hysteresis input, no
// algebraic loop) then stays zero.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hyst/dynamics/state_space.hpp"
#include "lfr_parametrisation.hpp"

namespace hyst::detail {

class LinearBlockParameters {
 public:
  // Relative excess over max_pole_radius taken as rounding of a pole that lies on the bound.
  static constexpr double kPoleRadiusRounding = 1e-12;

  // Throws hyst::Error (the message starting with `fit`) when a pole that is freed has a magnitude
  // above max_pole_radius. Poles are kept when A is not in real modal form. The bottom-right
  // zero_corner x zero_corner block of D is no parameter.
  LinearBlockParameters(const StateSpace& linear, bool poles, bool io_matrices,
                        double max_pole_radius, const std::string& fit,
                        Eigen::Index zero_corner = 0);

  Eigen::Index size() const { return pole_parameters_ + io_parameters_; }
  bool poles_free() const { return !blocks_.empty(); }
  bool io_matrices_free() const { return io_parameters_ > 0; }

  // The block at parameters[0, size()).
  StateSpace::Params params(const double* parameters) const;
  // d(A, B, C, D of the block)/d parameter, numbered from `offset`; LfrMatrix names the block's
  // own matrices here, which each LFR structure maps into its linear block.
  void derivatives(const double* parameters, Eigen::Index offset,
                   std::vector<MatrixEntryDerivative>& out) const;
  // Every freed pole stays inside the circle of radius max_pole_radius.
  void bound(ceres::Problem& problem, double* block, Eigen::Index offset) const;
  std::string description() const;

 private:
  // A diagonal block of a real modal A: a real pole (size 1) or a pair rho e^(+-j theta) as
  // rho [cos t, sin t; -sin t, cos t] (size 2).
  struct ModalBlock {
    Eigen::Index at = 0;
    Eigen::Index size = 1;
    double radius = 0.0;  // |pole|; a real pole keeps its sign in `sign`
    double angle = 0.0;
    double sign = 1.0;
  };
  static std::vector<ModalBlock> modal_blocks(const Eigen::MatrixXd& a);

  StateSpace::Params linear_;
  std::vector<ModalBlock> blocks_;
  Eigen::Index pole_parameters_ = 0, io_parameters_ = 0;
  double b_scale_ = 1.0, c_scale_ = 1.0, d_scale_ = 1.0;
  double max_pole_radius_ = 1.0;
  Eigen::Index zero_corner_ = 0;

  bool is_parameter_of_d(Eigen::Index row, Eigen::Index col) const {
    return row < linear_.d.rows() - zero_corner_ || col < linear_.d.cols() - zero_corner_;
  }
};

}  // namespace hyst::detail
