#include "hyst/dynamics/simulation_score.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/dynamics/initial_state_estimate.hpp"

namespace hyst {

Eigen::MatrixXd realisation_record(const PeriodicSignals& signals, std::size_t realisation) {
  const auto rows = Eigen::Index(signals.record_length());
  const auto columns = Eigen::Index(signals.channels);
  // One realisation is contiguous and row-major (sample, channel) in PeriodicSignals.
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      signals.values.data() + signals.index(0, 0, realisation, 0), rows, columns);
}

SimulationScore score_simulation(const PeriodicSignals& input, const PeriodicSignals& output,
                                 const RealisationSimulator& simulate,
                                 std::size_t transient_samples) {
  if (input.samples != output.samples || input.realisations != output.realisations ||
      input.periods != output.periods)
    throw Error(fmt::format(
        "score: inputs are {} samples x {} realisations x {} periods, outputs {} x {} x {}",
        input.samples, input.realisations, input.periods, output.samples, output.realisations,
        output.periods));
  if (input.samples == 0 || input.realisations == 0 || input.periods == 0 || output.channels == 0)
    throw Error("score: no data");
  if (transient_samples >= input.samples)
    throw Error(
        fmt::format("score: a transient of {} samples leaves nothing of the first period "
                    "of {} samples",
                    transient_samples, input.samples));
  require_finite_signals(input, "score: input");
  require_finite_signals(output, "score: output");
  const std::size_t p = output.channels;
  SimulationScore score;
  score.channels.resize(p);

  // Standard deviation of every measured channel over all its samples.
  for (std::size_t c = 0; c < p; ++c) {
    double sum = 0.0;
    double squares = 0.0;
    const double count = double(output.samples * output.realisations * output.periods);
    for (std::size_t r = 0; r < output.realisations; ++r)
      for (std::size_t q = 0; q < output.periods; ++q)
        for (std::size_t n = 0; n < output.samples; ++n) {
          sum += output(n, c, r, q);
          squares += output(n, c, r, q) * output(n, c, r, q);
        }
    const double mean = sum / count;
    score.channels[c].output_std = std::sqrt(std::max(squares / count - mean * mean, 0.0));
    if (!(score.channels[c].output_std > 0.0))
      throw Error(fmt::format("score: output channel {} is constant", c + 1));
  }

  const auto ranges = channel_ranges(output);
  for (std::size_t r = 0; r < input.realisations; ++r) {
    const Eigen::MatrixXd u = realisation_record(input, r);
    const Eigen::MatrixXd simulated = simulate(u, u.topRows(Eigen::Index(input.samples)));
    if (simulated.rows() != u.rows() || simulated.cols() != Eigen::Index(p))
      throw Error(fmt::format("score: the model gave {} x {} outputs for {} x {} expected",
                              simulated.rows(), simulated.cols(), u.rows(), p));
    if (!simulated.allFinite())
      throw Error(fmt::format("score: the simulation of realisation {} is not finite", r + 1));
    count_runaway(simulated, ranges, r, score.runaway);
    for (std::size_t q = 0; q < input.periods; ++q) {
      const std::size_t first = q == 0 ? transient_samples : 0;
      for (std::size_t c = 0; c < p; ++c) {
        double squares = 0.0;
        for (std::size_t n = first; n < input.samples; ++n) {
          const double e =
              output(n, c, r, q) - simulated(Eigen::Index(q * input.samples + n), Eigen::Index(c));
          squares += e * e;
        }
        score.channels[c].rmse += std::sqrt(squares / double(input.samples - first));
      }
    }
  }
  const double runs = double(input.realisations * input.periods);
  for (auto& channel : score.channels) {
    channel.rmse /= runs;
    channel.relative_error = channel.rmse / channel.output_std;
    score.mean_rmse += channel.rmse / double(p);
    score.mean_relative_error += channel.relative_error / double(p);
  }
  score.scored_samples =
      input.realisations * input.periods * input.samples - input.realisations * transient_samples;
  return score;
}

SimulationScore score_state_space(const StateSpace& model, const PeriodicSignals& input,
                                  const PeriodicSignals& output, const ScoreOptions& options) {
  if (input.channels != model.inputs() || output.channels != model.outputs())
    throw Error(fmt::format("score: the model has {} inputs and {} outputs, the data {} and {}",
                            model.inputs(), model.outputs(), input.channels, output.channels));
  const std::size_t transient = scored_transient(options);
  std::size_t realisation = 0;
  const auto simulate = [&](const Eigen::MatrixXd& u, const Eigen::MatrixXd& one_period) {
    if (options.init_samples > 0) {
      const auto measured = realisation_record(output, realisation++);
      auto state =
          model.make_state(estimate_initial_state(model, u, measured, options.init_samples).state);
      return model.simulate(u, state);
    }
    auto state = options.periodic ? model.make_state(model.periodic_state(one_period))
                                  : model.initial_state();
    return model.simulate(u, state);
  };
  return score_simulation(input, output, simulate, transient);
}

std::size_t scored_transient(const ScoreOptions& options) {
  if (options.init_samples == 0) return options.transient_samples;
  if (options.periodic)
    throw Error("score: init_samples and periodic are two ways to start a realisation: choose one",
                "init_samples");
  return options.init_samples;
}

}  // namespace hyst
