#pragma once
//! \file
//! Discrete-time multi-input multi-output linear state-space model, the linear dynamic block of
//! hyst's dynamic models (a piezo stage's lightly damped structure, a sensor's filter):
//!
//!     x[k+1] = A x[k] + B u[k],    y[k] = C x[k] + D u[k]
//!
//! with n states, m inputs and p outputs at sample time Ts. A continuous-time model
//! (dx/dt = Ac x + Bc u) becomes this form by exact zero-order-hold discretisation
//! (from_continuous: A = exp(Ac Ts), B = integral_0^Ts exp(Ac s) ds Bc, through the matrix
//! exponential of the augmented matrix [[Ac, Bc], [0, 0]] Ts).
//!
//! Like every model of hyst, the object holds validated, immutable parameters and a separate,
//! copyable State; step() does no allocation and no virtual call (the state holds the scratch
//! vector the update needs).

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "hyst/dynamics/state_transition.hpp"

namespace hyst {

class StateSpace {
 public:
  //! The most states a model may have: 500. Its matrices are dense: a sample costs about 2 n^2
  //! operations and a periodic state about 2 n^3 log2(N) (A^N), so at n = 2000 scoring the FSM
  //! test set (3 x 16 384 samples, --periodic) ran past 5 minutes; at 500 it takes 5.7 s of CPU,
  //! at 250 0.8 s. A hysteretic LFR's linear block has a lower limit (kMaxLfrOrder).
  static constexpr std::size_t max_order = 500;
  //! The most inputs and the most outputs (a hysteretic LFR's linear block counts its hysteresis
  //! channels among both): with max_order they bound B, C and D, and so what a sample costs.
  static constexpr std::size_t max_channels = 256;

  struct Params {
    Eigen::MatrixXd a;         //!< n x n
    Eigen::MatrixXd b;         //!< n x m
    Eigen::MatrixXd c;         //!< p x n
    Eigen::MatrixXd d;         //!< p x m
    double sample_time = 1.0;  //!< Ts > 0 [s]
  };
  struct State {
    Eigen::VectorXd x;        //!< n
    Eigen::VectorXd scratch;  //!< n, the next state while it is computed (not state proper)
  };

  //! Validates sizes (m, p >= 1; n may be 0: a static gain D), finite entries and Ts; throws
  //! hyst::Error naming the matrix ("state space: B has 3 rows, A has 4").
  explicit StateSpace(Params params);

  //! Exact zero-order-hold discretisation of dx/dt = ac x + bc u, y = c x + d u at sample time ts.
  static StateSpace from_continuous(const Eigen::MatrixXd& ac, const Eigen::MatrixXd& bc,
                                    const Eigen::MatrixXd& c, const Eigen::MatrixXd& d,
                                    double sample_time);

  //! A x as step() computes it (block by block when A is in real modal form).
  const StateTransition& transition() const { return transition_; }
  const Params& params() const { return params_; }
  std::size_t order() const { return static_cast<std::size_t>(params_.a.rows()); }
  std::size_t inputs() const { return static_cast<std::size_t>(params_.b.cols()); }
  std::size_t outputs() const { return static_cast<std::size_t>(params_.c.rows()); }
  double sample_time() const { return params_.sample_time; }

  //! At rest: x = 0.
  State initial_state() const;
  //! A given state; throws hyst::Error for a wrong size or a non-finite value.
  State make_state(const Eigen::VectorXd& x) const;

  //! One sample: y[k] = C x[k] + D u[k] into `output` (p values), then x[k+1] = A x[k] + B u[k].
  //! `input` has m values; `state` comes from initial_state() or make_state() of this model (the
  //! sizes are checked in debug builds only). No allocation, no virtual call.
  void step(State& state, std::span<const double> input, std::span<double> output) const noexcept;

  //! y (N x p) for u (N x m) from `state`, which ends as the state after the last sample. Throws
  //! hyst::Error for a column count other than m, a non-finite sample ("state space: input(17, 1)
  //! = nan is not finite (sample 17, input 1)") or a state of the wrong size.
  Eigen::MatrixXd simulate(const Eigen::MatrixXd& input, State& state) const;
  //! y (N x p) for u (N x m) from rest.
  Eigen::MatrixXd simulate(const Eigen::MatrixXd& input) const;

  //! The state x0 that the periodic input `one_period` (N x m, repeated forever) returns to after
  //! one period: x0 = A^N x0 + sum_k A^(N-1-k) B u[k], solved directly (not by running periods).
  //! Throws hyst::Error when I - A^N is singular or nearly so (an eigenvalue of A on or next to an
  //! N-th root of unity, e.g. an integrator: no unique periodic state), for an empty period and
  //! for the input errors of simulate().
  Eigen::VectorXd periodic_state(const Eigen::MatrixXd& one_period) const;
  //! y (N x p) over one period in periodic steady state.
  Eigen::MatrixXd simulate_periodic(const Eigen::MatrixXd& one_period) const;

  //! G(z) = C (zI - A)^-1 B + D at z = exp(j 2 pi f Ts), one p x m matrix per frequency [Hz].
  //! A is brought to Hessenberg form once, so each frequency costs O(n^2 m). At a pole on the unit
  //! circle the response is infinite (non-finite entries). Throws for a non-finite frequency.
  std::vector<Eigen::MatrixXcd> frequency_response(std::span<const double> frequencies) const;
  //! Eigenvalues of A (computed at each call, O(n^3); also for spectral_radius and is_stable).
  Eigen::VectorXcd poles() const;
  //! Largest pole magnitude (0 for n = 0).
  double spectral_radius() const;
  //! Every pole strictly inside the unit circle.
  bool is_stable() const { return spectral_radius() < 1.0; }

 private:
  Params params_;
  StateTransition transition_;  // A x of step(), cheap in real modal form
};

}  // namespace hyst
