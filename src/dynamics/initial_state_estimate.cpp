#include "hyst/dynamics/initial_state_estimate.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {
namespace {

// The rows of `m` as one column: sample by sample, channel by channel.
Eigen::VectorXd stacked(const Eigen::MatrixXd& m) {
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = m;
  return Eigen::Map<const Eigen::VectorXd>(rows.data(), rows.size());
}

double rms(const Eigen::VectorXd& residual) {
  return residual.size() == 0 ? 0.0 : std::sqrt(residual.squaredNorm() / double(residual.size()));
}

}  // namespace

InitialStateEstimate estimate_initial_state(const StateSpace& model, const Eigen::MatrixXd& input,
                                            const Eigen::MatrixXd& output, std::size_t samples) {
  if (input.cols() != Eigen::Index(model.inputs()) ||
      output.cols() != Eigen::Index(model.outputs()))
    throw Error(
        fmt::format("initial state: the model has {} inputs and {} outputs, the data {} "
                    "and {}",
                    model.inputs(), model.outputs(), input.cols(), output.cols()));
  if (input.rows() != output.rows())
    throw Error(fmt::format("initial state: {} input rows but {} output rows", input.rows(),
                            output.rows()));
  if (samples == 0 || Eigen::Index(samples) > input.rows())
    throw Error(fmt::format("initial state: {} samples of a record of {} (at least 1, at most the "
                            "record)",
                            samples, input.rows()),
                "init_samples");
  const auto n = Eigen::Index(samples);
  if (!input.topRows(n).allFinite() || !output.topRows(n).allFinite())
    throw Error("initial state: the samples are not all finite");
  const auto& p = model.params();
  const Eigen::Index channels = p.c.rows();
  // Observability rows C A^k of the n samples, and the residual of the response from rest.
  Eigen::MatrixXd observed(n * channels, p.a.rows());
  Eigen::MatrixXd power = p.c;
  for (Eigen::Index k = 0; k < n; ++k) {
    observed.middleRows(k * channels, channels) = power;
    power = power * p.a;
  }
  auto rest = model.initial_state();
  const Eigen::VectorXd residual =
      stacked(output.topRows(n)) - stacked(model.simulate(input.topRows(n), rest));
  InitialStateEstimate estimate;
  estimate.state = observed.completeOrthogonalDecomposition().solve(residual);
  estimate.rms_residual = rms(residual - observed * estimate.state);
  estimate.samples = samples;
  return estimate;
}

InitialStateEstimate refine_initial_state(const FirstOutputs& first_outputs,
                                          const Eigen::MatrixXd& measured, Eigen::VectorXd start,
                                          std::size_t max_iterations) {
  const Eigen::VectorXd target = stacked(measured);
  const auto residual_at = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    const Eigen::MatrixXd y = first_outputs(x);
    if (y.rows() != measured.rows() || y.cols() != measured.cols())
      throw Error(fmt::format("initial state: the model gave {} x {} outputs for {} x {} measured",
                              y.rows(), y.cols(), measured.rows(), measured.cols()));
    if (!y.allFinite()) throw Error("initial state: a run from a trial state is not finite");
    return target - stacked(y);
  };
  InitialStateEstimate estimate;
  estimate.state = std::move(start);
  estimate.samples = std::size_t(measured.rows());
  Eigen::VectorXd residual = residual_at(estimate.state);
  const Eigen::Index n = estimate.state.size();
  Eigen::MatrixXd jacobian(residual.size(), n);
  while (estimate.iterations < max_iterations) {
    for (Eigen::Index i = 0; i < n; ++i) {
      Eigen::VectorXd shifted = estimate.state;
      const double h = 1e-6 * (1.0 + std::abs(shifted[i]));
      shifted[i] += h;
      // The residual falls as the output rises: d(residual) = -d(output).
      jacobian.col(i) = (residual - residual_at(shifted)) / h;
    }
    const Eigen::VectorXd step = jacobian.completeOrthogonalDecomposition().solve(residual);
    const Eigen::VectorXd trial_state = estimate.state + step;
    const Eigen::VectorXd trial = residual_at(trial_state);
    ++estimate.iterations;
    const double before = residual.squaredNorm();
    const double after = trial.squaredNorm();
    if (!(after < before)) break;  // no progress: keep the better state
    estimate.state = trial_state;
    residual = trial;
    if (before - after <= 1e-10 * before) break;
  }
  estimate.rms_residual = rms(residual);
  return estimate;
}

}  // namespace hyst
