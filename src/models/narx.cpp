#include "hyst/models/narx.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

constexpr std::size_t kMaxLags = 1000;

std::string sizes_text(std::span<const std::size_t> sizes) {
  return fmt::format("[{}]", fmt::join(sizes, ", "));
}

void validate(const Narx::Params& p) {
  if (p.input_lags > kMaxLags) {
    throw Error(fmt::format("NARX input_lags = {} must be <= {}", p.input_lags, kMaxLags),
                "input_lags");
  }
  if (p.output_lags > kMaxLags) {
    throw Error(fmt::format("NARX output_lags = {} must be <= {}", p.output_lags, kMaxLags),
                "output_lags");
  }
  const auto& r = p.play_thresholds;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const auto field = fmt::format("play_thresholds[{}]", i);
    if (!std::isfinite(r[i]) || r[i] <= 0.0) {
      throw Error(fmt::format("NARX play threshold r[{}] = {} must be finite and > 0", i, r[i]),
                  field);
    }
    if (i > 0 && r[i] <= r[i - 1]) {
      throw Error(fmt::format("NARX play threshold r[{}] = {} must be > r[{}] = {}", i, r[i], i - 1,
                              r[i - 1]),
                  field);
    }
  }
  if (p.hidden_sizes.empty() || p.hidden_sizes.size() > 2) {
    throw Error(fmt::format("NARX hidden_sizes {} must list one or two hidden layers",
                            sizes_text(p.hidden_sizes)),
                "hidden_sizes");
  }
  for (std::size_t l = 0; l < p.hidden_sizes.size(); ++l) {
    if (p.hidden_sizes[l] < 1 || p.hidden_sizes[l] > Narx::max_neurons) {
      throw Error(fmt::format("NARX hidden_sizes[{}] = {} must be in 1..{}", l, p.hidden_sizes[l],
                              Narx::max_neurons),
                  fmt::format("hidden_sizes[{}]", l));
    }
  }
  const std::size_t regressors = 1 + p.input_lags + p.output_lags + r.size();
  const auto expected = Narx::network_parameter_count(regressors, p.hidden_sizes);
  if (p.weights.size() != expected) {
    throw Error(fmt::format("NARX weights: expected {} values for {} regressors and hidden layers "
                            "{}, got {}",
                            expected, regressors, sizes_text(p.hidden_sizes), p.weights.size()),
                "weights");
  }
  for (std::size_t i = 0; i < p.weights.size(); ++i) {
    if (!std::isfinite(p.weights[i])) {
      throw Error(fmt::format("NARX weight [{}] = {} is not finite", i, p.weights[i]),
                  fmt::format("weights[{}]", i));
    }
  }
  require_finite(p.input_offset, "NARX input_offset");
  require_finite(p.output_offset, "NARX output_offset");
  if (!std::isfinite(p.input_scale) || p.input_scale <= 0.0) {
    throw Error(fmt::format("NARX input_scale = {} must be finite and > 0", p.input_scale),
                "input_scale");
  }
  if (!std::isfinite(p.output_scale) || p.output_scale <= 0.0) {
    throw Error(fmt::format("NARX output_scale = {} must be finite and > 0", p.output_scale),
                "output_scale");
  }
  if (!std::isfinite(p.sample_time) || p.sample_time < 0.0) {
    throw Error(
        fmt::format("NARX sample_time = {} must be finite and >= 0 (0: not stated)", p.sample_time),
        "sample_time");
  }
}

void require_length(const std::vector<double>& values, std::size_t expected,
                    std::string_view name) {
  if (values.size() != expected) {
    throw Error(
        fmt::format("NARX state {}: expected {} values, got {}", name, expected, values.size()),
        std::string(name));
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw Error(fmt::format("NARX state {}[{}] = {} is not finite", name, i, values[i]),
                  fmt::format("{}[{}]", name, i));
    }
  }
}

}  // namespace

std::size_t Narx::network_parameter_count(std::size_t regressors,
                                          std::span<const std::size_t> hidden_sizes) {
  std::size_t count = 0;
  std::size_t inputs = regressors;
  for (const std::size_t size : hidden_sizes) {
    count += size * inputs + size;
    inputs = size;
  }
  return count + inputs + 1 + regressors;
}

Narx::Narx(Params params) : params_(std::move(params)) {
  validate(params_);
  regressors_ = 1 + params_.input_lags + params_.output_lags + params_.play_thresholds.size();
  scratch_size_ = regressors_;
  for (const std::size_t size : params_.hidden_sizes)
    scratch_size_ += size;
}

Narx::State Narx::initial_state() const {
  return state_at_rest(0.0, 0.0);
}

Narx::State Narx::state_at_rest(double input, double output) const {
  require_finite(input, "NARX rest input");
  require_finite(output, "NARX rest output");
  State state;
  state.past_inputs.assign(params_.input_lags, input);
  state.past_outputs.assign(params_.output_lags, output);
  state.play.assign(params_.play_thresholds.size(), input);
  state.scratch.assign(scratch_size_, 0.0);
  return state;
}

Narx::State Narx::state_after(std::span<const double> inputs,
                              std::span<const double> outputs) const {
  require_same_size(inputs.size(), "history inputs", outputs.size(), "history outputs");
  require_not_empty(inputs.size(), "history inputs");
  require_finite(inputs, "history inputs");
  require_finite(outputs, "history outputs");
  State state = state_at_rest(inputs.front(), outputs.front());
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    for (std::size_t j = 0; j < state.play.size(); ++j)
      state.play[j] = play_step(inputs[k], params_.play_thresholds[j], state.play[j]);
    push_front(state.past_inputs, inputs[k]);
    push_front(state.past_outputs, outputs[k]);
  }
  return state;
}

Narx::State Narx::make_state(std::vector<double> past_inputs, std::vector<double> past_outputs,
                             std::vector<double> play) const {
  require_length(past_inputs, params_.input_lags, "past_inputs");
  require_length(past_outputs, params_.output_lags, "past_outputs");
  require_length(play, params_.play_thresholds.size(), "play");
  State state;
  state.past_inputs = std::move(past_inputs);
  state.past_outputs = std::move(past_outputs);
  state.play = std::move(play);
  state.scratch.assign(scratch_size_, 0.0);
  return state;
}

std::vector<double> narx_one_step_prediction(const Narx& model, Narx::State& state,
                                             std::span<const double> input,
                                             std::span<const double> measured_output) {
  require_same_size(input.size(), "input", measured_output.size(), "measured output");
  require_finite(input, "input");
  require_finite(measured_output, "measured output");
  std::vector<double> predicted(input.size());
  for (std::size_t k = 0; k < input.size(); ++k)
    predicted[k] = model.predict(state, input[k], measured_output[k]);
  return predicted;
}

}  // namespace hyst
