#pragma once
//! \file
//! Neural NARX model with play-operator regressors: a black-box model of a hysteretic system.
//!
//!     phi[k] = ( v[k], v[k-1..k-n_u], y[k-1..k-n_y], F_{r_1}[v][k], ..., F_{r_q}[v][k] )
//!     y[k]   = y_off + y_scale * ( c + l . s(phi[k]) + w_o . h_L )
//!     h_1    = tanh(W_1 s(phi[k]) + b_1),   h_2 = tanh(W_2 h_1 + b_2)   (one or two layers)
//!
//! s() normalises each regressor: inputs and play outputs as (x - v_off) / v_scale, outputs as
//! (y - y_off) / y_scale, so that the network works on numbers of order one whatever the units.
//! The play outputs F_r[v] give the network the multivalued memory a static map lacks; the lags
//! give it rate dependence and dynamics. The linear term l . s(phi) is the ARX part (the fitter
//! starts from the least-squares ARX model); the network adds the nonlinearity.
//!
//! In simulation (free run) the past outputs are the model's own; in one-step-ahead prediction
//! they are measured (narx_one_step_prediction()). Free run is what a compensator sees.
//!
//! Parameters (`weights`, flat, in this order): for each hidden layer l: W_l row-major
//! (h_l x inputs of the layer), then b_l (h_l); then w_o (h_L), c, l (one per regressor).
//! Regressor count n_phi = 1 + n_u + n_y + q. State: the n_u past inputs, the n_y past outputs,
//! the q play outputs (all in their own units), and scratch space for the regressors and the
//! hidden activations - everything sized when the state is made, so step() never allocates.
//! Sources: Leontaritis & Billings (1985) for NARX/NARMAX; play regressors as in Yu et al.'s
//! NARMAX hysteresis models (reference other_models.md, section 8).

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "hyst/core/assert.hpp"
#include "hyst/operators/play.hpp"

namespace hyst {

class Narx {
 public:
  //! The most neurons a hidden layer may have.
  static constexpr std::size_t max_neurons = 1000;

  struct Params {
    std::size_t input_lags = 2;             //!< n_u: v[k-1..k-n_u] (v[k] is always used)
    std::size_t output_lags = 2;            //!< n_y >= 0: y[k-1..k-n_y]
    std::vector<double> play_thresholds;    //!< r_i > 0, strictly increasing [input units]
    std::vector<std::size_t> hidden_sizes;  //!< one or two layers, 1..1000 neurons each
    std::vector<double> weights;            //!< network_parameter_count() values, see above
    double input_offset = 0.0;              //!< v_off [input units]
    double input_scale = 1.0;               //!< v_scale > 0 [input units]
    double output_offset = 0.0;             //!< y_off [output units]
    double output_scale = 1.0;              //!< y_scale > 0 [output units]
    //! Ts [s] of the samples the lags count; 0 when fitted without a time axis (any is taken).
    double sample_time = 0.0;
  };
  struct State {
    std::vector<double> past_inputs;   //!< v[k-1], v[k-2], ... (n_u values) [input units]
    std::vector<double> past_outputs;  //!< y[k-1], y[k-2], ... (n_y values) [output units]
    std::vector<double> play;          //!< F_{r_i} outputs (q values) [input units]
    std::vector<double> scratch;       //!< regressors and hidden activations (not state proper)
  };

  //! Validates; throws hyst::Error naming the parameter ("NARX weights: expected 61 values for
  //! 7 regressors and hidden layers [6], got 60").
  explicit Narx(Params params);

  const Params& params() const { return params_; }
  std::size_t regressor_count() const { return regressors_; }

  //! At rest at input 0 and output 0 (plays at 0).
  State initial_state() const;
  //! At rest: every past input and play at `input`, every past output at `output`.
  State state_at_rest(double input, double output) const;
  //! The state after a measured history (oldest first): plays run over `inputs`, lags taken
  //! from its last samples (missing ones repeat the first sample). Throws hyst::Error for
  //! lengths that differ, an empty history or a non-finite sample.
  State state_after(std::span<const double> inputs, std::span<const double> outputs) const;
  //! A given state (e.g. from a model file); throws hyst::Error for a wrong size or a
  //! non-finite value.
  State make_state(std::vector<double> past_inputs, std::vector<double> past_outputs,
                   std::vector<double> play) const;

  //! One sample in free run: y[k] from v[k] and the state; the state then holds v[k] and y[k] as
  //! the newest lags. No allocation, no virtual call.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    const double output = evaluate(state, input);
    push_front(state.past_outputs, output);
    return output;
  }

  //! One-step-ahead form: y[k] predicted like step(), but the state then takes the measured
  //! `measured_output` as the newest past output.
  double predict(State& state, double input, double measured_output) const noexcept {
    const double output = evaluate(state, input);
    push_front(state.past_outputs, measured_output);
    return output;
  }

  //! Number of network values (the size `weights` must have).
  static std::size_t network_parameter_count(std::size_t regressors,
                                             std::span<const std::size_t> hidden_sizes);

 private:
  static void push_front(std::vector<double>& lags, double value) noexcept {
    for (std::size_t i = lags.size(); i > 1; --i)
      lags[i - 1] = lags[i - 2];
    if (!lags.empty()) lags[0] = value;
  }

  // Regressors into scratch, network, then the input lags and plays advance.
  double evaluate(State& state, double input) const noexcept {
    const auto& p = params_;
    double* phi = state.scratch.data();
    const double inv_u = 1.0 / p.input_scale;
    const double inv_y = 1.0 / p.output_scale;
    std::size_t i = 0;
    phi[i++] = (input - p.input_offset) * inv_u;
    for (const double v : state.past_inputs)
      phi[i++] = (v - p.input_offset) * inv_u;
    for (const double y : state.past_outputs)
      phi[i++] = (y - p.output_offset) * inv_y;
    for (std::size_t j = 0; j < p.play_thresholds.size(); ++j) {
      state.play[j] = play_step(input, p.play_thresholds[j], state.play[j]);
      phi[i++] = (state.play[j] - p.input_offset) * inv_u;
    }
    const double net = network(phi, phi + regressors_);
    push_front(state.past_inputs, input);
    return p.output_offset + p.output_scale * net;
  }

  // The network on the normalised regressors `phi`; `hidden` has room for every hidden layer.
  double network(const double* phi, double* hidden) const noexcept {
    const double* w = params_.weights.data();
    const double* layer_input = phi;
    std::size_t inputs = regressors_;
    for (const std::size_t size : params_.hidden_sizes) {
      const double* bias = w + size * inputs;
      for (std::size_t n = 0; n < size; ++n) {
        double sum = bias[n];
        const double* row = w + n * inputs;
        for (std::size_t m = 0; m < inputs; ++m)
          sum += row[m] * layer_input[m];
        hidden[n] = std::tanh(sum);
      }
      w = bias + size;
      layer_input = hidden;
      inputs = size;
      hidden += size;
    }
    double out = 0.0;
    for (std::size_t n = 0; n < inputs; ++n)
      out += w[n] * layer_input[n];
    w += inputs;
    out += *w++;  // c
    for (std::size_t m = 0; m < regressors_; ++m)
      out += w[m] * phi[m];
    return out;
  }

  Params params_;
  std::size_t regressors_ = 0;
  std::size_t scratch_size_ = 0;
};

//! One-step-ahead prediction over a record: y_hat[k] from v[k] and the measured y[k-1..k-n_y],
//! starting from `state` (advanced). Throws hyst::Error for lengths that differ or non-finite
//! samples.
std::vector<double> narx_one_step_prediction(const Narx& model, Narx::State& state,
                                             std::span<const double> input,
                                             std::span<const double> measured_output);

}  // namespace hyst
