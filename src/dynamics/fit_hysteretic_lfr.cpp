#include "hyst/dynamics/fit_hysteretic_lfr.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "../identify/detail/convergence.hpp"
#include "hyst/core/error.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/identify/error_metrics.hpp"

namespace hyst {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;

// What the fit keeps fixed: the linear model, the scales that make the parameters dimensionless
// (z = T diag(1 / output_scale) y, u_eff = u + input_scale Theta w) and the PI thresholds.
// A diagonal block of a real modal A: a real pole (size 1) or a pair rho e^(+-j theta) as
// rho [cos t, sin t; -sin t, cos t] (size 2).
struct ModalBlock {
  Index at = 0;
  Index size = 1;
  double radius = 0.0;  // |pole|; a real pole keeps its sign in `sign`
  double angle = 0.0;
  double sign = 1.0;
};

// The blocks of A when it is in real modal form (block diagonal, 2 x 2 blocks [a, b; -b, a]),
// else none: the poles are then kept as they are.
std::vector<ModalBlock> modal_blocks(const MatrixXd& a) {
  std::vector<ModalBlock> blocks;
  const Index n = a.rows();
  for (Index i = 0; i < n;) {
    const bool pair = i + 1 < n && a(i + 1, i) != 0.0;
    const Index size = pair ? 2 : 1;
    for (Index r = 0; r < n; ++r)
      for (Index c = i; c < i + size; ++c)
        if ((r < i || r >= i + size) && (a(r, c) != 0.0 || a(c, r) != 0.0)) return {};
    ModalBlock block{i, size};
    if (pair) {
      if (a(i, i) != a(i + 1, i + 1) || a(i, i + 1) != -a(i + 1, i)) return {};
      block.radius = std::hypot(a(i, i), a(i, i + 1));
      block.angle = std::atan2(a(i, i + 1), a(i, i));
    } else {
      block.radius = std::abs(a(i, i));
      block.sign = a(i, i) < 0.0 ? -1.0 : 1.0;
    }
    if (!(block.radius > 0.0)) return {};
    blocks.push_back(block);
    i += size;
  }
  return blocks;
}

struct Structure {
  const StateSpace* linear = nullptr;
  std::vector<ModalBlock> poles;  // empty: A stays as fitted
  Eigen::VectorXd output_scale;   // largest |y_k| over the data
  double input_scale = 0.0;       // largest |u| over the data
  std::vector<double> thresholds;
  Index m = 0, p = 0;

  Index q() const { return p; }
  Index feedback_parameters() const {
    return m * q() + q() * p + q() * Index(thresholds.size() - 1);
  }
  Index pole_parameters() const {
    Index count = 0;
    for (const auto& block : poles)
      count += block.size;
    return count;
  }
  Index parameter_count() const { return feedback_parameters() + pole_parameters(); }
};

// The parameter vector: Theta (m x q), T (q x p), both column-major, then each channel's weights
// of the plays r > 0, then per modal block the change of log |pole| (and of the angle of a pair).
std::vector<double> initial_parameters(const Structure& s) {
  std::vector<double> theta(std::size_t(s.parameter_count()), 0.0);
  for (Index i = 0; i < s.q(); ++i)
    theta[std::size_t(s.m * s.q() + i * s.q() + i)] = 1.0;  // T = I
  return theta;
}

HystereticLfr<PrandtlIshlinskii> build(const Structure& s, const double* parameters) {
  const auto& lin = s.linear->params();
  const Index m = s.m, p = s.p, q = s.q(), n = lin.a.rows();
  const Eigen::Map<const MatrixXd> theta(parameters, m, q);
  const Eigen::Map<const MatrixXd> t(parameters + m * q, q, p);
  const MatrixXd to_z = t * s.output_scale.cwiseInverse().asDiagonal();
  const MatrixXd feedback = s.input_scale * theta;
  StateSpace::Params params;
  params.sample_time = lin.sample_time;
  params.a = lin.a;
  const double* pole = parameters + s.feedback_parameters();
  for (const auto& block : s.poles) {
    const double radius = block.radius * std::exp(*pole++);
    if (block.size == 1) {
      params.a(block.at, block.at) = block.sign * radius;
      continue;
    }
    const double angle = block.angle + *pole++;
    const Index i = block.at;
    params.a(i, i) = params.a(i + 1, i + 1) = radius * std::cos(angle);
    params.a(i, i + 1) = radius * std::sin(angle);
    params.a(i + 1, i) = -params.a(i, i + 1);
  }
  params.b.resize(n, m + q);
  params.b << lin.b, lin.b * feedback;
  params.c.resize(p + q, n);
  params.c << lin.c, to_z * lin.c;
  params.d.resize(p + q, m + q);
  params.d << lin.d, lin.d * feedback, to_z * lin.d, MatrixXd::Zero(q, q);
  const double* weights = parameters + m * q + q * p;
  const std::size_t plays = s.thresholds.size();
  std::vector<PrandtlIshlinskii> blocks;
  for (Index i = 0; i < q; ++i) {
    std::vector<double> w{1.0};
    w.insert(w.end(), weights + i * Index(plays - 1), weights + (i + 1) * Index(plays - 1));
    blocks.emplace_back(PrandtlIshlinskii::Params{s.thresholds, std::move(w), 0.0});
  }
  return {StateSpace(std::move(params)), std::size_t(m), std::move(blocks)};
}

// One realisation: its record, the linear model's periodic state of its first period (where the
// simulation starts), the measured outputs after the warm-up period and their weights.
struct Realisation {
  MatrixXd input;
  MatrixXd measured;  // rows from `warmup` on
  Eigen::VectorXd start;
  Eigen::RowVectorXd weight;  // per channel
  Index warmup = 0;
};

struct RealisationResidual {
  const Structure* structure;
  const Realisation* data;

  // Simulated minus measured, weighted; false (a step Ceres refuses) for parameters that make
  // the loop diverge or are not finite.
  bool operator()(double const* const* parameters, double* residuals) const {
    try {
      const auto model = build(*structure, parameters[0]);
      auto state = model.make_state(data->start);
      const MatrixXd y = model.simulate(data->input, state);
      const Index rows = data->measured.rows(), p = data->measured.cols();
      for (Index k = 0; k < rows; ++k)
        for (Index c = 0; c < p; ++c) {
          const double r = (y(data->warmup + k, c) - data->measured(k, c)) * data->weight[c];
          if (!std::isfinite(r)) return false;
          residuals[k * p + c] = r;
        }
      return true;
    } catch (const Error&) {
      return false;
    }
  }
};

void check(const StateSpace& linear, std::span<const PeriodicExperiment> experiments,
           const HystereticLfrFitOptions& options) {
  if (experiments.empty()) throw Error("hysteretic LFR fit: no experiment");
  for (std::size_t e = 0; e < experiments.size(); ++e) {
    const auto& x = experiments[e];
    if (x.input.channels != linear.inputs() || x.output.channels != linear.outputs())
      throw Error(
          fmt::format("hysteretic LFR fit: experiment {} has {} inputs and {} outputs; "
                      "the linear model has {} and {}",
                      e, x.input.channels, x.output.channels, linear.inputs(), linear.outputs()));
    if (x.input.periods < 2)
      throw Error(
          fmt::format("hysteretic LFR fit: experiment {} has {} period per realisation; "
                      "the fit needs 2 or more (the first warms the hysteresis up)",
                      e, x.input.periods));
  }
  const auto& r = options.threshold_fractions;
  if (r.empty() || r[0] != 0.0)
    throw Error("hysteretic LFR fit: threshold_fractions must start at 0", "threshold_fractions");
  for (std::size_t j = 1; j < r.size(); ++j)
    if (!std::isfinite(r[j]) || !(r[j] > r[j - 1]))
      throw Error(fmt::format("hysteretic LFR fit: threshold_fractions[{}] = {} must be finite and "
                              "above the one before",
                              j, r[j]),
                  fmt::format("threshold_fractions[{}]", j));
}

// Each experiment's channels weighted by 1 / (std * sqrt(scored values of the experiment)), so
// that the cost is half the sum over experiments of the mean squared relative error.
std::vector<Realisation> realisations(const StateSpace& linear,
                                      std::span<const PeriodicExperiment> experiments) {
  std::vector<Realisation> result;
  for (const auto& x : experiments) {
    const auto n = Index(x.input.samples);
    const auto p = Index(x.output.channels);
    Eigen::RowVectorXd mean = Eigen::RowVectorXd::Zero(p), square = mean;
    std::vector<MatrixXd> outputs;
    for (std::size_t r = 0; r < x.output.realisations; ++r) {
      outputs.push_back(realisation_record(x.output, r));
      mean += outputs.back().colwise().sum();
      square += outputs.back().array().square().matrix().colwise().sum();
    }
    const double count = double(x.output.realisations * x.output.record_length());
    mean /= count;
    const Eigen::RowVectorXd deviation =
        (square / count - mean.array().square().matrix()).cwiseMax(0.0).cwiseSqrt();
    const double scored = double(x.output.realisations * (x.output.periods - 1) * x.output.samples);
    for (std::size_t r = 0; r < x.output.realisations; ++r) {
      Realisation data;
      data.input = realisation_record(x.input, r);
      data.warmup = n;
      data.measured = outputs[r].bottomRows(outputs[r].rows() - n);
      data.start = linear.periodic_state(data.input.topRows(n));
      data.weight = (deviation * std::sqrt(scored * double(p))).cwiseInverse();
      for (Index c = 0; c < p; ++c)
        if (!std::isfinite(data.weight[c]))
          throw Error(fmt::format("hysteretic LFR fit: output {} is constant in an experiment", c));
      result.push_back(std::move(data));
    }
  }
  return result;
}

}  // namespace

HystereticLfrFit fit_hysteretic_lfr(const StateSpace& linear,
                                    std::span<const PeriodicExperiment> experiments,
                                    const HystereticLfrFitOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  check(linear, experiments, options);
  const auto tell = [&](std::size_t done, std::string_view step) {
    if (options.progress) options.progress(Progress{"hysteretic LFR fit", done, 1, step});
  };
  Structure s;
  s.linear = &linear;
  s.m = Index(linear.inputs());
  s.p = Index(linear.outputs());
  s.thresholds = options.threshold_fractions;
  if (options.fit_poles) s.poles = modal_blocks(linear.params().a);
  for (const auto& block : s.poles)
    if (!(block.radius < options.max_pole_radius))
      throw Error(fmt::format("hysteretic LFR fit: a pole of the linear model has magnitude {}, "
                              "not below max_pole_radius {}",
                              block.radius, options.max_pole_radius),
                  "max_pole_radius");
  s.output_scale = Eigen::VectorXd::Zero(s.p);
  for (const auto& x : experiments) {
    for (std::size_t i = 0; i < x.input.values.size(); ++i)
      s.input_scale = std::max(s.input_scale, std::abs(x.input.values[i]));
    for (std::size_t i = 0; i < x.output.values.size(); ++i) {
      const auto c = Index(i % x.output.channels);
      s.output_scale[c] = std::max(s.output_scale[c], std::abs(x.output.values[i]));
    }
  }
  if (!(s.input_scale > 0.0) || !(s.output_scale.minCoeff() > 0.0))
    throw Error("hysteretic LFR fit: an input or output is zero throughout");
  const auto data = realisations(linear, experiments);

  std::vector<double> parameters = initial_parameters(s);
  ceres::Problem problem;
  for (const auto& realisation : data) {
    auto* cost = new ceres::DynamicNumericDiffCostFunction<RealisationResidual, ceres::CENTRAL>(
        new RealisationResidual{&s, &realisation});
    cost->AddParameterBlock(int(parameters.size()));
    cost->SetNumResiduals(int(realisation.measured.size()));
    problem.AddResidualBlock(cost, nullptr, parameters.data());
  }
  // Every pole stays inside the circle of radius max_pole_radius.
  Index at = s.feedback_parameters();
  for (const auto& block : s.poles) {
    problem.SetParameterUpperBound(parameters.data(), int(at),
                                   std::log(options.max_pole_radius / block.radius));
    at += block.size;
  }
  ceres::Solver::Options solver =
      detail::levenberg_marquardt_options(options.max_iterations, detail::kFunctionTolerance);
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.num_threads = int(std::max<std::size_t>(1, options.threads));
  tell(0, "Levenberg-Marquardt");
  ceres::Solver::Summary summary;
  if (options.max_iterations > 0) ceres::Solve(solver, &problem, &summary);
  tell(1, "done");

  auto model = build(s, parameters.data());
  std::vector<double> measured, predicted;
  for (const auto& realisation : data) {
    auto state = model.make_state(realisation.start);
    const MatrixXd y = model.simulate(realisation.input, state);
    for (Index k = 0; k < realisation.measured.rows(); ++k)
      for (Index c = 0; c < realisation.measured.cols(); ++c) {
        measured.push_back(realisation.measured(k, c));
        predicted.push_back(y(realisation.warmup + k, c));
      }
  }
  FitReport report;
  report.model = "hysteretic_lfr";
  report.method = fmt::format(
      "Levenberg-Marquardt (Ceres, central differences) on the simulation error, of Theta, T and "
      "the PI weights ({} plays per channel){}",
      s.thresholds.size(), s.poles.empty() ? "; linear block fixed" : " and the linear poles");
  report.termination =
      options.max_iterations == 0 ? Termination::converged : detail::termination_of_ceres(summary);
  report.message = options.max_iterations == 0 ? "not refined" : summary.message;
  report.iterations = std::size_t(summary.iterations.size());
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  report.parameters = parameters.size();
  report.fit = error_metrics(measured, predicted);
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return {std::move(model), std::move(report)};
}

}  // namespace hyst
