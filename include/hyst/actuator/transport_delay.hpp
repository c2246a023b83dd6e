#pragma once
//! \file
//! Transport delay y(t) = x(t - T) on a sampled signal, as a ring buffer.
//!
//! With D = T / h = d + f (d whole, 0 <= f < 1), the output is the linear interpolation between
//! the samples d and d + 1 back:  y[k] = (1 - f) x[k - d] + f x[k - d - 1]. For a whole D this is
//! exact; otherwise it is exact for signals linear between samples (first-order hold), the
//! documented choice of the reference (actuator_msma.md section 3). Before any sample arrived the
//! buffer holds the initial value.

#include <cstddef>
#include <vector>

namespace hyst {

class TransportDelay {
 public:
  struct State {
    std::vector<double> buffer;  //!< the last d + 2 inputs (ring)
    std::size_t head = 0;        //!< index of the newest input
  };

  //! delay T >= 0 [s], period h > 0 [s]; hyst::Error otherwise. T / h within 1e-9 of a whole
  //! number counts as whole.
  TransportDelay(double delay, double period);

  double delay() const { return delay_; }
  double period() const { return period_; }
  //! d and f of the file comment.
  std::size_t whole_samples() const { return whole_; }
  double fraction() const { return fraction_; }

  //! Every buffered sample equal to `initial` (the output before the first input arrived).
  State initial_state(double initial = 0.0) const;
  //! Pushes x[k] and returns y[k]. No allocation.
  double step(State& state, double input) const noexcept {
    const std::size_t size = state.buffer.size();
    state.head = state.head + 1 == size ? 0 : state.head + 1;
    state.buffer[state.head] = input;
    const std::size_t newer = (state.head + size - whole_) % size;
    if (fraction_ == 0.0) return state.buffer[newer];
    const std::size_t older = newer == 0 ? size - 1 : newer - 1;
    return (1.0 - fraction_) * state.buffer[newer] + fraction_ * state.buffer[older];
  }

 private:
  double delay_;
  double period_;
  std::size_t whole_ = 0;
  double fraction_ = 0.0;
};

}  // namespace hyst
