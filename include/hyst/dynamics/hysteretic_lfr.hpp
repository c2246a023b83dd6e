#pragma once
//! \file
//! Hysteresis inside the dynamics: a linear fractional representation (LFR) whose feedback
//! channels are hysteresis models. The linear block (a StateSpace with m + q inputs and p + q
//! outputs) maps the inputs u (m) and the hysteresis outputs w (q) to the outputs y (p) and the
//! hysteresis inputs z (q); each w_i = H_i[z_i] is a hysteresis model with its own memory:
//!
//!     z[k]   = Cz x[k] + Dzu u[k]                  (Dzw = 0: no algebraic loop)
//!     w_i[k] = H_i[z_i][k]
//!     y[k]   = Cy x[k] + Dyu u[k] + Dyw w[k]
//!     x[k+1] = A x[k] + Bu u[k] + Bw w[k]
//!
//! The linear block's inputs are ordered (u, w) and its outputs (y, z). With z a deflection of the
//! structure and w a force fed back into it, the hysteresis acts in the stiffness path, as it does
//! in a piezo stack, so the resonances shift with the amplitude; a hysteresis ahead of the dynamics
//! (Hammerstein) only scales and distorts the input and cannot do that. The Hammerstein structure
//! (w_i = H_i[u_i] driving the linear block, no direct path from u) is the special case Cz = 0,
//! Dzu = I, Bu = 0, Dyu = 0 (hammerstein()).
//!
//! Like every model of hyst, the object holds validated, immutable parameters and a separate,
//! copyable State; step() does no allocation and no virtual call (H is a concrete model type).

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "hyst/core/assert.hpp"
#include "hyst/core/model_concept.hpp"
#include "hyst/dynamics/state_space.hpp"

namespace hyst {

//! The linear block of an LFR cut into its (u, w) -> (y, z) parts; validated on construction.
struct LfrMatrices {
  //! Throws hyst::Error when the block has more than kMaxLfrOrder states, not `inputs + feedback`
  //! inputs and more than `feedback` outputs, when inputs is 0, or when Dzw has a non-zero entry
  //! (named by its place in D).
  LfrMatrices(const StateSpace& linear, std::size_t inputs, std::size_t feedback);

  Eigen::MatrixXd a, b_u, b_w, c_y, c_z, d_yu, d_yw, d_zu;
  Eigen::MatrixXd d_u;  //!< [Dyu; Dzu], D's columns of u
};

//! How the periodic steady state of a nonlinear loop is found (HystereticLfr::periodic_state).
struct LfrPeriodicOptions {
  //! Fixed-point iterations (periods) before giving up: a loop with a slow mode can need a
  //! few hundred periods to settle to the tolerance (a fitted FSM model needs 250 on one test
  //! input, its mode shrinking by 5 % per period).
  std::size_t max_iterations = 1000;
  //! Converged when the hysteresis outputs over a period change by at most this, relative to
  //! their largest magnitude.
  double tolerance = 1e-10;
};

//! Hysteresis outputs beyond this magnitude mean the loop diverges (periodic_state gives up).
inline constexpr double kMaxPeriodicMagnitude = 1e100;

//! The most states of the linear block: 100, the most a state-space fit makes. The search for the
//! periodic state may run LfrPeriodicOptions::max_iterations periods of about 2 n^2 operations
//! per sample: at 100 states about a minute per realisation of the FSM test set at the worst; a
//! dense linear model of 500 states scores in 6 s, but as an LFR block could take hours.
inline constexpr std::size_t kMaxLfrOrder = 100;

//! Checks of the non-template code (input signals, convergence), shared by every H.
namespace lfr_detail {
//! Throws hyst::Error for a column count other than `columns` or a non-finite sample.
void require_signal(const Eigen::MatrixXd& signal, std::size_t columns, const char* what);
//! Throws hyst::Error saying that the periodic state did not converge within the limit.
[[noreturn]] void throw_not_periodic(std::size_t iterations, double change, double tolerance);
//! Throws hyst::Error saying that the loop diverged: in period `period` of the search for the
//! periodic state the hysteresis outputs reached `magnitude` (beyond kMaxPeriodicMagnitude, or
//! not finite).
[[noreturn]] void throw_diverging(std::size_t period, double magnitude);
//! Throws hyst::Error unless there is one block per input of the linear block.
void require_hammerstein_blocks(std::size_t linear_inputs, std::size_t blocks);
//! Throws hyst::Error for a state of the wrong size or with a non-finite value.
void require_state(const Eigen::VectorXd& x, std::size_t order, std::size_t feedback_states,
                   std::size_t feedback);
}  // namespace lfr_detail

template <HysteresisModel H>
class HystereticLfr {
 public:
  using Feedback = H;
  struct State {
    Eigen::VectorXd x;                        //!< the linear block's state (n)
    std::vector<typename H::State> feedback;  //!< each hysteresis model's memory (q)
    Eigen::VectorXd next;                     //!< scratch: the next x while it is computed
    Eigen::VectorXd response;  //!< scratch: C x + D [u; 0], i.e. y without w's term, then z
    Eigen::VectorXd drive;     //!< scratch: the linear block's inputs [u; w]
    Eigen::VectorXd w;         //!< the hysteresis outputs of the last step
  };

  //! `linear` has inputs + feedback.size() inputs (u, then w) and more than feedback.size()
  //! outputs (y, then z); throws hyst::Error otherwise (see LfrMatrices).
  HystereticLfr(StateSpace linear, std::size_t inputs, std::vector<H> feedback)
      : linear_(std::move(linear)),
        inputs_(inputs),
        feedback_(std::move(feedback)),
        m_(linear_, inputs, feedback_.size()) {}

  //! The Hammerstein system: input i passes through blocks[i], whose outputs drive `linear` (as
  //! many inputs as blocks); as an LFR with z = u.
  static HystereticLfr hammerstein(const StateSpace& linear, std::vector<H> blocks) {
    const auto q = Eigen::Index(blocks.size());
    const auto& p = linear.params();
    const auto n = p.a.rows();
    const auto outputs = p.c.rows();
    lfr_detail::require_hammerstein_blocks(linear.inputs(), blocks.size());
    StateSpace::Params lfr;
    lfr.sample_time = p.sample_time;
    lfr.a = p.a;
    lfr.b.setZero(n, 2 * q);
    lfr.b.rightCols(q) = p.b;
    lfr.c.setZero(outputs + q, n);
    lfr.c.topRows(outputs) = p.c;
    lfr.d.setZero(outputs + q, 2 * q);
    lfr.d.topRightCorner(outputs, q) = p.d;
    lfr.d.bottomLeftCorner(q, q).setIdentity();
    return HystereticLfr(StateSpace(std::move(lfr)), std::size_t(q), std::move(blocks));
  }

  const StateSpace& linear() const { return linear_; }
  const std::vector<H>& feedback() const { return feedback_; }
  const LfrMatrices& matrices() const { return m_; }
  std::size_t inputs() const { return inputs_; }
  std::size_t outputs() const { return std::size_t(m_.c_y.rows()); }
  std::size_t order() const { return linear_.order(); }
  double sample_time() const { return linear_.sample_time(); }

  //! At rest: x = 0 and every hysteresis model in its initial state.
  State initial_state() const { return make_state(Eigen::VectorXd::Zero(m_.a.rows())); }
  //! A given linear state, the hysteresis models in their initial states; hyst::Error for a wrong
  //! size or a non-finite value.
  State make_state(const Eigen::VectorXd& x) const {
    std::vector<typename H::State> feedback;
    feedback.reserve(feedback_.size());
    for (const auto& model : feedback_)
      feedback.push_back(model.initial_state());
    return make_state(x, std::move(feedback));
  }
  State make_state(const Eigen::VectorXd& x, std::vector<typename H::State> feedback) const {
    lfr_detail::require_state(x, order(), feedback.size(), feedback_.size());
    const auto q = Eigen::Index(feedback_.size());
    const auto& linear = linear_.params();
    return State{x,
                 std::move(feedback),
                 Eigen::VectorXd::Zero(x.size()),
                 Eigen::VectorXd::Zero(linear.c.rows()),
                 Eigen::VectorXd::Zero(linear.b.cols()),
                 Eigen::VectorXd::Zero(q)};
  }

  //! One sample: the hysteresis inputs z, the hysteresis outputs w, y into `output` (p values),
  //! then the next state. `input` has m values; `state` comes from this model (sizes checked in
  //! debug builds only). No allocation, no virtual call.
  void step(State& state, std::span<const double> input, std::span<double> output) const noexcept {
    HYST_ASSERT(input.size() == inputs_, "step() needs one input value per model input");
    HYST_ASSERT(output.size() == outputs(), "step() needs room for one value per model output");
    HYST_ASSERT(state.feedback.size() == feedback_.size(), "step() needs a state of this model");
    const Eigen::Map<const Eigen::VectorXd> u(input.data(), Eigen::Index(input.size()));
    Eigen::Map<Eigen::VectorXd> y(output.data(), Eigen::Index(output.size()));
    const auto& linear = linear_.params();
    const auto m = Eigen::Index(inputs_);
    const auto p = Eigen::Index(outputs());
    const auto q = Eigen::Index(feedback_.size());
    // Four products with the whole C, D's u columns, Dyw and the whole B rather than seven with
    // their blocks: at these sizes each product's fixed cost outweighs its arithmetic.
    state.response.noalias() = linear.c * state.x;
    state.response.noalias() += m_.d_u * u;
    for (Eigen::Index i = 0; i < q; ++i)
      state.w[i] =
          feedback_[std::size_t(i)].step(state.feedback[std::size_t(i)], state.response[p + i]);
    y = state.response.head(p);
    y.noalias() += m_.d_yw * state.w;
    state.drive.head(m) = u;
    state.drive.tail(q) = state.w;
    linear_.transition().apply(state.x, state.next);
    state.next.noalias() += linear.b * state.drive;
    state.x.swap(state.next);
  }

  //! y (N x p) for u (N x m) from `state`, which ends as the state after the last sample. Throws
  //! hyst::Error for a column count other than m or a non-finite sample.
  Eigen::MatrixXd simulate(const Eigen::MatrixXd& input, State& state) const {
    lfr_detail::require_signal(input, inputs_, "input");
    state = make_state(state.x, std::move(state.feedback));
    const Eigen::MatrixXd u = input.transpose();
    Eigen::MatrixXd y(Eigen::Index(outputs()), input.rows());
    for (Eigen::Index k = 0; k < input.rows(); ++k)
      step(state, {u.col(k).data(), inputs_}, {y.col(k).data(), outputs()});
    return y.transpose();
  }
  //! y (N x p) for u (N x m) from rest.
  Eigen::MatrixXd simulate(const Eigen::MatrixXd& input) const {
    State state = initial_state();
    return simulate(input, state);
  }

  //! The state that the periodic input `one_period` (N x m, repeated forever) returns to after one
  //! period. First by a fixed point on the hysteresis outputs w: run a period, solve the linear
  //! block's periodic state for that period's inputs (u, w) exactly (StateSpace::periodic_state),
  //! keep the hysteresis memories where the period left them, and repeat. That converges in a few
  //! periods when the feedback is weak next to the linear block's periodic gain; a stable loop
  //! with strong feedback (the hysteresis carrying part of a stiffness) can make it diverge, so
  //! once an iteration fails to halve the change, the remaining iterations simply run periods from
  //! where the last one ended, which converges for every loop that forgets its initial state.
  //! Done when w over a period changes by less than the tolerance. Throws hyst::Error when it does
  //! not converge (naming the iteration limit), for an empty period, for the input errors of
  //! simulate() and when the linear block has no unique periodic state.
  State periodic_state(const Eigen::MatrixXd& one_period,
                       const LfrPeriodicOptions& options = {}) const {
    lfr_detail::require_signal(one_period, inputs_, "one_period");
    const auto samples = one_period.rows();
    const auto m = Eigen::Index(inputs_);
    const auto q = Eigen::Index(feedback_.size());
    Eigen::MatrixXd linear_input(samples, m + q);
    linear_input.leftCols(m) = one_period;
    linear_input.rightCols(q).setZero();
    State state = make_state(linear_.periodic_state(linear_input));
    if (q == 0) return state;
    const Eigen::MatrixXd u = one_period.transpose();
    Eigen::VectorXd y(static_cast<Eigen::Index>(outputs()));
    Eigen::MatrixXd w(samples, q);
    bool solve_linear = true;  // the fixed point on w; false: plain periods
    double change = 0.0;       // relative to the largest |w|
    double previous_change = std::numeric_limits<double>::infinity();
    for (std::size_t iteration = 0; iteration < options.max_iterations; ++iteration) {
      for (Eigen::Index k = 0; k < samples; ++k) {
        step(state, {u.col(k).data(), inputs_}, {y.data(), outputs()});
        w.row(k) = state.w.transpose();
      }
      const double scale = std::max(w.cwiseAbs().maxCoeff(), 1e-300);
      change = (w - linear_input.rightCols(q)).cwiseAbs().maxCoeff() / scale;
      // A loop that diverges within a period leaves nothing to solve for.
      if (!std::isfinite(change) || !std::isfinite(scale) || scale > kMaxPeriodicMagnitude)
        lfr_detail::throw_diverging(iteration + 1, scale);
      linear_input.rightCols(q) = w;
      if (solve_linear && iteration > 0 && change > 0.5 * previous_change) solve_linear = false;
      previous_change = change;
      // Converged: the period's w (and so the state it leads to) reproduces itself.
      const bool converged = iteration > 0 && change <= options.tolerance;
      if (solve_linear)
        state = make_state(linear_.periodic_state(linear_input), std::move(state.feedback));
      if (converged) return state;
    }
    lfr_detail::throw_not_periodic(options.max_iterations, change, options.tolerance);
  }

  //! y (N x p) over one period in periodic steady state.
  Eigen::MatrixXd simulate_periodic(const Eigen::MatrixXd& one_period,
                                    const LfrPeriodicOptions& options = {}) const {
    State state = periodic_state(one_period, options);
    return simulate(one_period, state);
  }

 private:
  StateSpace linear_;
  std::size_t inputs_;
  std::vector<H> feedback_;
  LfrMatrices m_;
};

}  // namespace hyst
