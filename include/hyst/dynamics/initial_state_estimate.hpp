#pragma once
//! \file
//! The initial state of a dynamic model from measured samples: what a model may see under the
//! submission rule of the nonlinear system identification benchmarks (the input, and the first
//! n measured outputs of each realisation, n_init = 100 for the Fine Steering Mirror), so that
//! its simulation starts from the state the system was in instead of from rest.
//!
//! A linear model y_k = C A^k x0 + (its response from rest to u_0 .. u_k) is linear in x0: the
//! state is the least-squares solution over the first n samples (a complete orthogonal
//! decomposition: directions the n samples do not observe stay at 0, the minimum-norm answer).
//! A model with hysteresis in its feedback is not linear in x0 (the hysteresis channels see the
//! state's outputs): refine_initial_state() minimises the same residual by Gauss-Newton steps on
//! a forward-difference Jacobian, from the linear block's estimate; the hysteresis channels start
//! from their rest state (their memory is not estimated).

#include <cstddef>
#include <functional>

#include <Eigen/Dense>

#include "hyst/dynamics/state_space.hpp"

namespace hyst {

struct InitialStateEstimate {
  Eigen::VectorXd state;       //!< the linear block's state x0 at sample 0
  double rms_residual = 0.0;   //!< RMS over the n samples and every channel [output units]
  std::size_t samples = 0;     //!< n
  std::size_t iterations = 0;  //!< Gauss-Newton steps taken (0 for the linear least squares)
};

//! x0 of `model` from the first `samples` rows of `input` (N x m) and `output` (N x p). Throws
//! hyst::Error for sizes that do not match the model or each other, samples 0 or beyond the
//! record, and non-finite data.
InitialStateEstimate estimate_initial_state(const StateSpace& model, const Eigen::MatrixXd& input,
                                            const Eigen::MatrixXd& output, std::size_t samples);

//! The first outputs (n x p) of a model run from the linear-block state x0.
using FirstOutputs = std::function<Eigen::MatrixXd(const Eigen::VectorXd& x0)>;

//! x0 minimising the squared difference between first_outputs(x0) and `measured` (n x p):
//! Gauss-Newton from `start`, the Jacobian by forward differences (one run per state), until a
//! step lowers the residual by less than 1e-10 of it or after `max_iterations` steps. Throws
//! hyst::Error when a run gives another size than `measured` or a non-finite output.
InitialStateEstimate refine_initial_state(const FirstOutputs& first_outputs,
                                          const Eigen::MatrixXd& measured, Eigen::VectorXd start,
                                          std::size_t max_iterations = 20);

}  // namespace hyst
