#pragma once
// The simulation of a hysteretic LFR with PI feedback together with its forward sensitivities:
// the derivative of every output sample by every parameter of an LfrParametrisation, propagated
// sample by sample next to the state (one pass instead of one or two simulations per parameter).
// Each play's derivative is the derivative of its input while the play is pushed and keeps its
// value while it rests, the one-sided derivative at a reversal: the simulation is piecewise
// smooth in the parameters and this is the derivative of the piece it runs on.

#include <Eigen/Dense>

#include "lfr_parametrisation.hpp"

namespace hyst::detail {

// Where the derivatives go: for samples k >= first, d y(k, c) / d parameter j times weight[c]
// into jacobian[((k - first) * p + c) * parameters + j] (row-major, one row per scored value,
// the layout of a Ceres Jacobian).
struct SensitivitySink {
  Eigen::Index first = 0;
  Eigen::RowVectorXd weight;  // p
  double* jacobian = nullptr;
  // The start is the model's periodic state for the input (one period, repeated): the derivatives
  // then include the start's own, from the linearised period map (the run carries the derivatives
  // by every state value too), so that they are those of the periodic steady state.
  bool periodic_start = false;
};

// y (N x p) for input (N x m) from `start` (a state of point.model), the outputs computed by the
// model's own step (the numbers of HystereticLfr::simulate), and their derivatives into `sink`.
// Unless sink.periodic_start, the start is taken as given: its derivatives are zero.
Eigen::MatrixXd simulate_with_sensitivities(const LfrPoint& point, Eigen::Index parameters,
                                            const Eigen::MatrixXd& input,
                                            HystereticLfr<PrandtlIshlinskii>::State start,
                                            const SensitivitySink& sink);

}  // namespace hyst::detail
