#include "hyst/dynamics/hysteretic_lfr.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

LfrMatrices::LfrMatrices(const StateSpace& linear, std::size_t inputs, std::size_t feedback) {
  if (linear.order() > kMaxLfrOrder)
    throw Error(fmt::format("hysteretic LFR: the linear block has {} states, more than the limit "
                            "of {}",
                            linear.order(), kMaxLfrOrder),
                "linear.a");
  if (inputs == 0)
    throw Error("hysteretic LFR: it needs at least one input u (the linear block's first inputs)",
                "inputs");
  if (linear.inputs() != inputs + feedback)
    throw Error(fmt::format("hysteretic LFR: the linear block has {} inputs; it needs {} (the {} "
                            "inputs u, then one per hysteresis model w)",
                            linear.inputs(), inputs + feedback, inputs),
                "linear.b");
  if (linear.outputs() <= feedback)
    throw Error(fmt::format("hysteretic LFR: the linear block has {} outputs; it needs more than "
                            "the {} hysteresis inputs z (its outputs are y, then z)",
                            linear.outputs(), feedback),
                "linear.c");
  const auto& p = linear.params();
  const auto m = Eigen::Index(inputs);
  const auto q = Eigen::Index(feedback);
  const auto outputs = p.c.rows() - q;
  for (Eigen::Index i = 0; i < q; ++i)
    for (Eigen::Index j = 0; j < q; ++j)
      if (p.d(outputs + i, m + j) != 0.0)
        throw Error(fmt::format("hysteretic LFR: D({}, {}) = {} feeds hysteresis output w{} "
                                "straight into hysteresis input z{}, an algebraic loop; that part "
                                "of D (Dzw, rows {}.., columns {}..) must be zero",
                                outputs + i, m + j, p.d(outputs + i, m + j), j, i, outputs, m),
                    fmt::format("linear.d[{}][{}]", outputs + i, m + j));
  a = p.a;
  b_u = p.b.leftCols(m);
  b_w = p.b.rightCols(q);
  c_y = p.c.topRows(outputs);
  c_z = p.c.bottomRows(q);
  d_yu = p.d.topLeftCorner(outputs, m);
  d_yw = p.d.topRightCorner(outputs, q);
  d_zu = p.d.bottomLeftCorner(q, m);
  d_u = p.d.leftCols(m);
}

namespace lfr_detail {

void require_signal(const Eigen::MatrixXd& signal, std::size_t columns, const char* what) {
  if (std::size_t(signal.cols()) != columns)
    throw Error(fmt::format("hysteretic LFR: {} has {} columns; the model has {} inputs", what,
                            signal.cols(), columns),
                what);
  if (signal.rows() == 0) throw Error(fmt::format("hysteretic LFR: {} has no sample", what), what);
  for (Eigen::Index j = 0; j < signal.cols(); ++j)
    for (Eigen::Index k = 0; k < signal.rows(); ++k)
      if (!std::isfinite(signal(k, j)))
        throw Error(fmt::format("hysteretic LFR: {}({}, {}) = {} is not finite (sample {}, input "
                                "{})",
                                what, k, j, signal(k, j), k, j),
                    what);
}

void throw_not_periodic(std::size_t iterations, double change, double tolerance) {
  throw Error(fmt::format("hysteretic LFR: no periodic steady state within {} iterations (the "
                          "hysteresis outputs still change by {:.3g} of their largest magnitude "
                          "per iteration, tolerance {:g}); the loop may be unstable or chaotic for "
                          "this input, or raise LfrPeriodicOptions::max_iterations",
                          iterations, change, tolerance),
              "max_iterations");
}

void throw_diverging(std::size_t period, double magnitude) {
  const auto reached = std::isfinite(magnitude) ? fmt::format("{:.3g}", magnitude)
                                                : std::string("values that are not finite");
  throw Error(fmt::format("hysteretic LFR: the loop diverges: in period {} of the search for the "
                          "periodic steady state the hysteresis outputs reach {} (the limit is "
                          "{:g}); the feedback makes the loop unstable for this input (e.g. a "
                          "negative hysteresis weight, or a feedback gain too large for the linear "
                          "block)",
                          period, reached, kMaxPeriodicMagnitude),
              "feedback");
}

void require_hammerstein_blocks(std::size_t linear_inputs, std::size_t blocks) {
  if (blocks != linear_inputs)
    throw Error(fmt::format("Hammerstein system: {} blocks for a linear block with {} inputs; "
                            "each input needs its block",
                            blocks, linear_inputs),
                "feedback");
}

void require_state(const Eigen::VectorXd& x, std::size_t order, std::size_t feedback_states,
                   std::size_t feedback) {
  if (std::size_t(x.size()) != order)
    throw Error(fmt::format("hysteretic LFR: the state x has {} values; the linear block has {} "
                            "states",
                            x.size(), order),
                "state.x");
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]))
      throw Error(fmt::format("hysteretic LFR: state x[{}] = {} is not finite", i, x[i]),
                  fmt::format("state.x[{}]", i));
  if (feedback_states != feedback)
    throw Error(fmt::format("hysteretic LFR: {} hysteresis states for {} hysteresis models",
                            feedback_states, feedback),
                "state.feedback");
}

}  // namespace lfr_detail
}  // namespace hyst
