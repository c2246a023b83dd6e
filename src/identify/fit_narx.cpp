#include "hyst/identify/fit_narx.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <utility>

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <Eigen/Dense>

#include "detail/multistart_driver.hpp"
#include "detail/multistart_fit.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/data_split.hpp"
#include "hyst/identify/fit_record.hpp"

namespace hyst {
namespace {

constexpr std::size_t kRowsPerBlock = 256;

double mean_of(std::span<const double> x) {
  return std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

double deviation_of(std::span<const double> x, double mean) {
  double sum = 0.0;
  for (const double value : x)
    sum += (value - mean) * (value - mean);
  return std::sqrt(sum / static_cast<double>(x.size()));
}

// Each start is a whole training run: a bound on what one fit can cost.
constexpr std::size_t kMaxStarts = 100;

void validate_options(const NarxFitOptions& o) {
  if (o.max_iterations < 1) {
    throw Error("NARX fit max_iterations = 0 must be >= 1", "max_iterations");
  }
  if (o.patience < 1) throw Error("NARX fit patience = 0 must be >= 1", "patience");
  if (o.starts < 1 || o.starts > kMaxStarts) {
    throw Error(fmt::format("NARX fit starts = {} must be in 1..{}", o.starts, kMaxStarts),
                "starts");
  }
  if (!(o.early_stopping_fraction >= 0.0 && o.early_stopping_fraction <= 0.9)) {
    throw Error(fmt::format("NARX fit early_stopping_fraction = {} must be in [0, 0.9]",
                            o.early_stopping_fraction),
                "early_stopping_fraction");
  }
  if (!(o.regularization >= 0.0) || !std::isfinite(o.regularization)) {
    throw Error(
        fmt::format("NARX fit regularization = {} must be finite and >= 0", o.regularization),
        "regularization");
  }
  // Checked before the network is sized (the model checks its own parameters later).
  for (std::size_t l = 0; l < o.hidden_sizes.size(); ++l) {
    if (o.hidden_sizes[l] < 1 || o.hidden_sizes[l] > Narx::max_neurons) {
      throw Error(fmt::format("NARX fit hidden_sizes[{}] = {} must be in 1..{}", l,
                              o.hidden_sizes[l], Narx::max_neurons),
                  fmt::format("hidden_sizes[{}]", l));
    }
  }
  if (o.play_thresholds.empty() && o.plays > 100) {
    throw Error(fmt::format("NARX fit plays = {} must be <= 100", o.plays), "plays");
  }
}

void validate_record(std::span<const double> input, std::span<const double> output,
                     std::string_view kind) {
  check_fit_record({input, output}, fmt::format("NARX fit{}", kind), {});
}

// The model structure with all network values 0: regressor layout and normalisation only.
Narx::Params structure(std::span<const double> input, std::span<const double> output,
                       const NarxFitOptions& options) {
  Narx::Params p;
  p.input_lags = options.input_lags;
  p.output_lags = options.output_lags;
  p.hidden_sizes = options.hidden_sizes;
  p.input_offset = mean_of(input);
  p.input_scale = deviation_of(input, p.input_offset);
  p.output_offset = mean_of(output);
  p.output_scale = deviation_of(output, p.output_offset);
  p.sample_time = options.sample_time;
  if (!(p.input_scale > 0.0)) {
    throw Error(fmt::format("NARX fit: the input is constant (all {} samples = {}); a model of "
                            "the input-output relation needs a varying input",
                            input.size(), input.front()),
                "input");
  }
  if (!(p.output_scale > 0.0)) {
    throw Error(fmt::format("NARX fit: the output is constant (all {} samples = {}); there is "
                            "nothing to model",
                            output.size(), output.front()),
                "output");
  }
  if (!options.play_thresholds.empty()) {
    p.play_thresholds = options.play_thresholds;
  } else {
    const auto [low, high] = std::minmax_element(input.begin(), input.end());
    const double half_range = 0.5 * (*high - *low);
    for (std::size_t i = 1; i <= options.plays; ++i)
      p.play_thresholds.push_back(half_range * static_cast<double>(i) /
                                  static_cast<double>(options.plays + 1));
  }
  const std::size_t regressors = 1 + p.input_lags + p.output_lags + p.play_thresholds.size();
  p.weights.assign(Narx::network_parameter_count(regressors, p.hidden_sizes), 0.0);
  return p;
}

// Normalised regressors and targets of the one-step-ahead problem, rows row-major.
struct Rows {
  std::vector<double> phi;
  std::vector<double> target;
  std::size_t width = 0;
  std::size_t count() const { return target.size(); }
};

// Rows k = skip..end-1 of a record, with the regressor code of the model itself.
Rows one_step_rows(const Narx& shape, std::span<const double> input, std::span<const double> output,
                   std::size_t skip) {
  Rows rows;
  rows.width = shape.regressor_count();
  auto state = shape.state_at_rest(input.front(), output.front());
  const auto& p = shape.params();
  for (std::size_t k = 0; k < input.size(); ++k) {
    shape.predict(state, input[k], output[k]);
    if (k < skip) continue;
    rows.phi.insert(rows.phi.end(), state.scratch.begin(),
                    state.scratch.begin() + static_cast<std::ptrdiff_t>(rows.width));
    rows.target.push_back((output[k] - p.output_offset) / p.output_scale);
  }
  return rows;
}

// The network's output and its gradient with respect to every weight (backpropagation).
class Network {
 public:
  Network(std::size_t regressors, std::vector<std::size_t> hidden)
      : regressors_(regressors), hidden_(std::move(hidden)) {
    std::size_t total = 0;
    for (const auto size : hidden_)
      total += size;
    activations_.resize(total);
    deltas_.resize(total);
  }

  // Output at `phi`; with `gradient` (size = weight count) also d output / d weights, and with
  // `input_gradient` (needs `gradient`) d output / d phi.
  double evaluate(const double* weights, const double* phi, double* gradient,
                  double* input_gradient = nullptr) {
    const double* w = weights;
    const double* layer_input = phi;
    std::size_t inputs = regressors_;
    double* a = activations_.data();
    for (const std::size_t size : hidden_) {
      const double* bias = w + size * inputs;
      for (std::size_t n = 0; n < size; ++n) {
        double sum = bias[n];
        for (std::size_t m = 0; m < inputs; ++m)
          sum += w[n * inputs + m] * layer_input[m];
        a[n] = std::tanh(sum);
      }
      w = bias + size;
      layer_input = a;
      inputs = size;
      a += size;
    }
    const double* output_weights = w;
    double out = w[inputs];
    for (std::size_t n = 0; n < inputs; ++n)
      out += output_weights[n] * layer_input[n];
    const double* linear = w + inputs + 1;
    for (std::size_t m = 0; m < regressors_; ++m)
      out += linear[m] * phi[m];
    if (gradient != nullptr) backpropagate(weights, phi, gradient);
    if (input_gradient != nullptr) {
      // d/dphi = l + W_1^T delta_1 (the deltas of the first layer are at the front).
      for (std::size_t m = 0; m < regressors_; ++m) {
        double sum = linear[m];
        for (std::size_t n = 0; n < hidden_.front(); ++n)
          sum += weights[n * regressors_ + m] * deltas_[n];
        input_gradient[m] = sum;
      }
    }
    return out;
  }

 private:
  void backpropagate(const double* weights, const double* phi, double* gradient) {
    // Offsets of each layer's weight block.
    std::size_t offsets[3] = {0, 0, 0};
    std::size_t inputs = regressors_;
    std::size_t position = 0;
    for (std::size_t l = 0; l < hidden_.size(); ++l) {
      offsets[l] = position;
      position += hidden_[l] * inputs + hidden_[l];
      inputs = hidden_[l];
    }
    const std::size_t last = hidden_.size() - 1;
    const std::size_t last_start = activations_.size() - hidden_[last];
    const double* a_last = activations_.data() + last_start;
    const double* output_weights = weights + position;
    for (std::size_t n = 0; n < inputs; ++n)
      gradient[position + n] = a_last[n];
    gradient[position + inputs] = 1.0;
    for (std::size_t m = 0; m < regressors_; ++m)
      gradient[position + inputs + 1 + m] = phi[m];

    // Deltas from the last hidden layer backwards.
    for (std::size_t n = 0; n < hidden_[last]; ++n)
      deltas_[last_start + n] = output_weights[n] * (1.0 - a_last[n] * a_last[n]);
    std::size_t start = last_start;
    for (std::size_t l = hidden_.size(); l-- > 0;) {
      const std::size_t size = hidden_[l];
      const std::size_t layer_inputs = l == 0 ? regressors_ : hidden_[l - 1];
      const double* layer_input = l == 0 ? phi : activations_.data() + (start - hidden_[l - 1]);
      const double* delta = deltas_.data() + start;
      double* g = gradient + offsets[l];
      for (std::size_t n = 0; n < size; ++n) {
        for (std::size_t m = 0; m < layer_inputs; ++m)
          g[n * layer_inputs + m] = delta[n] * layer_input[m];
        g[size * layer_inputs + n] = delta[n];
      }
      if (l == 0) break;
      // Delta of the layer below: W_l^T delta times tanh'.
      const double* w = weights + offsets[l];
      const std::size_t below = start - layer_inputs;
      for (std::size_t m = 0; m < layer_inputs; ++m) {
        double sum = 0.0;
        for (std::size_t n = 0; n < size; ++n)
          sum += w[n * layer_inputs + m] * delta[n];
        const double a = activations_[below + m];
        deltas_[below + m] = sum * (1.0 - a * a);
      }
      start = below;
    }
  }

  std::size_t regressors_;
  std::vector<std::size_t> hidden_;
  std::vector<double> activations_;
  std::vector<double> deltas_;
};

// Residuals f(phi_k) - t_k of a block of rows, one parameter block (all weights).
class BlockResiduals final : public ceres::CostFunction {
 public:
  BlockResiduals(const Rows& rows, std::size_t begin, std::size_t end, std::size_t weights,
                 const std::vector<std::size_t>& hidden)
      : rows_(rows), begin_(begin), end_(end), network_(rows.width, hidden) {
    set_num_residuals(static_cast<int>(end - begin));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(weights));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const auto weights = static_cast<std::size_t>(parameter_block_sizes()[0]);
    for (std::size_t k = begin_; k < end_; ++k) {
      double* gradient = jacobians != nullptr && jacobians[0] != nullptr
                             ? jacobians[0] + (k - begin_) * weights
                             : nullptr;
      const double out = network_.evaluate(parameters[0], &rows_.phi[k * rows_.width], gradient);
      residuals[k - begin_] = out - rows_.target[k];
      if (!std::isfinite(residuals[k - begin_])) return false;
    }
    return true;
  }

 private:
  const Rows& rows_;
  std::size_t begin_;
  std::size_t end_;
  mutable Network network_;  // scratch only; Ceres evaluates single-threaded here
};

// Free-run (simulation) residuals over the training rows: the output-lag regressors hold the
// network's own earlier outputs, from the measured lags of the first row on. The Jacobian comes
// from forward sensitivities (real-time recurrent learning): with S_k = d y_k / d theta,
//     S_k = d f / d theta + sum_i (d f / d y_{k-i}) S_{k-i},
// so one pass costs O(N n_y P) on top of the network.
class FreeRunResiduals final : public ceres::CostFunction {
 public:
  FreeRunResiduals(const Rows& rows, std::size_t first_output_lag, std::size_t output_lags,
                   std::size_t weights, const std::vector<std::size_t>& hidden)
      : rows_(rows),
        first_lag_(first_output_lag),
        lags_(output_lags),
        network_(rows.width, hidden) {
    set_num_residuals(static_cast<int>(rows.count()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(weights));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const auto weights = static_cast<std::size_t>(parameter_block_sizes()[0]);
    const bool jacobian = jacobians != nullptr && jacobians[0] != nullptr;
    std::vector<double> phi(rows_.phi.begin(),
                            rows_.phi.begin() + static_cast<std::ptrdiff_t>(rows_.width));
    std::vector<double> lags(phi.begin() + static_cast<std::ptrdiff_t>(first_lag_),
                             phi.begin() + static_cast<std::ptrdiff_t>(first_lag_ + lags_));
    std::vector<double> input_gradient(rows_.width);
    std::vector<double> gradient(weights);
    std::vector<double> ring(jacobian ? lags_ * weights : 0, 0.0);  // S of y_{k-1..k-n_y}
    for (std::size_t k = 0; k < rows_.count(); ++k) {
      std::copy_n(&rows_.phi[k * rows_.width], rows_.width, phi.begin());
      std::copy(lags.begin(), lags.end(), phi.begin() + static_cast<std::ptrdiff_t>(first_lag_));
      const double out =
          network_.evaluate(parameters[0], phi.data(), jacobian ? gradient.data() : nullptr,
                            jacobian ? input_gradient.data() : nullptr);
      if (!std::isfinite(out)) return false;
      residuals[k] = out - rows_.target[k];
      if (jacobian) {
        double* row = jacobians[0] + k * weights;
        std::copy(gradient.begin(), gradient.end(), row);
        for (std::size_t i = 1; i <= lags_ && i <= k; ++i) {
          const double factor = input_gradient[first_lag_ + i - 1];
          const double* previous = &ring[((k - i) % lags_) * weights];
          for (std::size_t j = 0; j < weights; ++j)
            row[j] += factor * previous[j];
        }
        std::copy(row, row + weights, &ring[(k % lags_) * weights]);
      }
      for (std::size_t i = lags_; i > 1; --i)
        lags[i - 1] = lags[i - 2];
      lags[0] = out;
    }
    return true;
  }

 private:
  const Rows& rows_;
  std::size_t first_lag_;
  std::size_t lags_;
  mutable Network network_;
};

// sqrt(weight) * theta_i for the hidden-layer weights and the output weights (not the ARX part).
class Ridge final : public ceres::CostFunction {
 public:
  Ridge(std::size_t weights, std::size_t penalised, double weight)
      : penalised_(penalised), factor_(std::sqrt(weight)) {
    set_num_residuals(static_cast<int>(penalised));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(weights));
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const auto weights = static_cast<std::size_t>(parameter_block_sizes()[0]);
    for (std::size_t i = 0; i < penalised_; ++i)
      residuals[i] = factor_ * parameters[0][i];
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      std::fill(jacobians[0], jacobians[0] + penalised_ * weights, 0.0);
      for (std::size_t i = 0; i < penalised_; ++i)
        jacobians[0][i * weights + i] = factor_;
    }
    return true;
  }

 private:
  std::size_t penalised_;
  double factor_;
};

// Least-squares ARX start for c and l; Glorot-uniform hidden weights; small output weights.
void initial_weights(const Rows& rows, const Narx::Params& p, std::uint64_t seed,
                     std::vector<double>& weights) {
  std::mt19937_64 generator(seed);
  std::size_t position = 0;
  std::size_t inputs = rows.width;
  for (const std::size_t size : p.hidden_sizes) {
    const double limit = std::sqrt(6.0 / static_cast<double>(inputs + size));
    std::uniform_real_distribution<double> uniform(-limit, limit);
    for (std::size_t i = 0; i < size * inputs; ++i)
      weights[position++] = uniform(generator);
    for (std::size_t i = 0; i < size; ++i)
      weights[position++] = 0.0;
    inputs = size;
  }
  std::uniform_real_distribution<double> small(-0.1 / std::sqrt(double(inputs)),
                                               0.1 / std::sqrt(double(inputs)));
  for (std::size_t i = 0; i < inputs; ++i)
    weights[position++] = small(generator);

  // ARX: [1 phi] [c; l] = t, with a tiny ridge against collinear lags.
  const auto n = static_cast<Eigen::Index>(rows.count());
  const auto width = static_cast<Eigen::Index>(rows.width);
  Eigen::MatrixXd design(n, width + 1);
  design.col(0).setOnes();
  design.rightCols(width) =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          rows.phi.data(), n, width);
  const Eigen::Map<const Eigen::VectorXd> target(rows.target.data(), n);
  Eigen::MatrixXd normal = design.transpose() * design;
  normal.diagonal().array() += 1e-9 * static_cast<double>(n);
  const Eigen::VectorXd arx = normal.ldlt().solve(design.transpose() * target);
  for (Eigen::Index i = 0; i <= width; ++i)
    weights[position++] = std::isfinite(arx[i]) ? arx[i] : 0.0;
}

// Free-run error of `model` over a record part, from `state` (advanced); infinity when the run
// diverges.
double free_run_rmse(const Narx& model, Narx::State& state, std::span<const double> input,
                     std::span<const double> output) {
  double sum = 0.0;
  for (std::size_t k = 0; k < input.size(); ++k) {
    const double e = model.step(state, input[k]) - output[k];
    sum += e * e;
  }
  const double rmse = std::sqrt(sum / static_cast<double>(input.size()));
  return std::isfinite(rmse) ? rmse : std::numeric_limits<double>::infinity();
}

// Keeps the weights with the lowest free-run error on the monitor part; stops after `patience`
// iterations without improvement.
class EarlyStopping final : public ceres::IterationCallback {
 public:
  EarlyStopping(const Narx::Params& shape, const std::vector<double>& weights, Narx::State start,
                std::span<const double> input, std::span<const double> output, std::size_t patience)
      : shape_(shape),
        weights_(weights),
        start_(std::move(start)),
        input_(input),
        output_(output),
        patience_(patience) {}

  //! Continues from an earlier stage: only better than `best_error` counts as progress.
  void start_from(std::vector<double> best, double best_error) {
    best_ = std::move(best);
    best_error_ = best_error;
    stale_ = 0;
    stopped_ = false;
    stage_ = 2;
  }

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    // A rejected step leaves the weights as they were: no improvement, nothing to evaluate.
    const bool moved = summary.iteration == 0 || summary.step_is_successful;
    const double error = moved ? monitor_error() : best_error_;
    if (error < best_error_) {
      best_error_ = error;
      best_ = weights_;
      best_iteration_ = static_cast<std::size_t>(summary.iteration);
      best_stage_ = stage_;
      stale_ = 0;
    } else if (++stale_ >= patience_) {
      stopped_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }

  double monitor_error() const {
    auto params = shape_;
    params.weights = weights_;
    const Narx model(std::move(params));
    auto state = start_;
    return free_run_rmse(model, state, input_, output_);
  }

  const std::vector<double>& best() const { return best_; }
  double best_error() const { return best_error_; }
  std::size_t best_iteration() const { return best_iteration_; }
  //! 1: one-step stage, 2: simulation-error stage.
  std::size_t best_stage() const { return best_stage_; }
  bool stopped() const { return stopped_; }

 private:
  const Narx::Params& shape_;
  const std::vector<double>& weights_;
  Narx::State start_;
  std::span<const double> input_;
  std::span<const double> output_;
  std::size_t patience_;
  std::vector<double> best_;
  double best_error_ = std::numeric_limits<double>::infinity();
  std::size_t best_iteration_ = 0;
  std::size_t stage_ = 1;
  std::size_t best_stage_ = 1;
  std::size_t stale_ = 0;
  bool stopped_ = false;
};

std::size_t penalised_count(const Narx::Params& p, std::size_t regressors) {
  // Everything before c: hidden layers and output weights.
  return Narx::network_parameter_count(regressors, p.hidden_sizes) - 1 - regressors;
}

double one_step_cost(const Rows& rows, const Narx::Params& p, const std::vector<double>& weights) {
  Network network(rows.width, p.hidden_sizes);
  double sum = 0.0;
  for (std::size_t k = 0; k < rows.count(); ++k) {
    const double e =
        (network.evaluate(weights.data(), &rows.phi[k * rows.width], nullptr) - rows.target[k]) *
        p.output_scale;
    sum += e * e;
  }
  return 0.5 * sum;
}

// The ridge penalty on the network weights (not on the linear term), when asked for.
void add_ridge(ceres::Problem& problem, const Narx::Params& shape, std::size_t regressors,
               const Rows& rows, const NarxFitOptions& options, std::vector<double>& weights) {
  if (options.regularization <= 0.0) return;
  problem.AddResidualBlock(new Ridge(weights.size(), penalised_count(shape, regressors),
                                     options.regularization * static_cast<double>(rows.count())),
                           nullptr, weights.data());
}

// Stage 2 of the fit: Levenberg-Marquardt on the free-run error from the stage-1 `weights`
// (advanced in place; with early stopping, the best weights on its monitor part).
ceres::Solver::Summary simulation_error_stage(const Rows& rows, const Narx::Params& shape,
                                              std::size_t regressors, const NarxFitOptions& options,
                                              ceres::Solver::Options& solver,
                                              EarlyStopping* stopping,
                                              std::vector<double>& weights) {
  ceres::Problem problem;
  problem.AddResidualBlock(new FreeRunResiduals(rows, 1 + shape.input_lags, shape.output_lags,
                                                weights.size(), shape.hidden_sizes),
                           nullptr, weights.data());
  add_ridge(problem, shape, regressors, rows, options, weights);
  solver.max_num_iterations = static_cast<int>(options.simulation_iterations);
  if (stopping) stopping->start_from(weights, stopping->best_error());
  detail::StagnationStop stagnation;
  solver.callbacks.back() = &stagnation;  // a fresh cost history for this stage
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (stagnation.stopped()) summary.message = stagnation.message();
  if (stopping && !stopping->best().empty()) weights = stopping->best();
  return summary;
}

// The free-run errors of the fitted model over the fit part from rest, continued into the
// validation part when it follows (else from rest at its start), and the one-step-ahead errors.
// False when the model diverges on the fit part (the report then says so).
bool add_free_run_errors(NarxFit& result, std::span<const double> input,
                         std::span<const double> output, std::span<const double> validation_input,
                         std::span<const double> validation_output, bool continue_into_validation) {
  auto state = result.initial_state;
  std::vector<double> simulated(input.size());
  simulate(result.model, state, input, simulated);
  if (!std::all_of(simulated.begin(), simulated.end(), [](double y) { return std::isfinite(y); })) {
    result.report.termination = Termination::failed;
    result.report.message = "the fitted model diverges in free run on the fit part";
    result.report.fit.samples = input.size();
    result.report.fit.rmse = result.report.fit.nrmse_percent = result.report.fit.max_error =
        std::numeric_limits<double>::infinity();
    return false;
  }
  result.report.fit = error_metrics(output, simulated);
  auto one_step_state = result.initial_state;
  result.one_step_fit =
      error_metrics(output, narx_one_step_prediction(result.model, one_step_state, input, output));
  if (!validation_input.empty()) {
    auto validation_state =
        continue_into_validation
            ? state
            : result.model.state_at_rest(validation_input.front(), validation_output.front());
    auto one_step_validation_state = continue_into_validation ? one_step_state : validation_state;
    std::vector<double> predicted(validation_input.size());
    simulate(result.model, validation_state, validation_input, predicted);
    if (std::all_of(predicted.begin(), predicted.end(),
                    [](double y) { return std::isfinite(y); })) {
      result.report.validation = error_metrics(validation_output, predicted);
    } else {
      result.report.validation = ErrorMetrics{
          validation_input.size(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }
    result.one_step_validation = error_metrics(
        validation_output, narx_one_step_prediction(result.model, one_step_validation_state,
                                                    validation_input, validation_output));
  }
  return true;
}

// What every training run of one fit shares: the structure, the training rows and the
// early-stopping monitor part (empty: no early stopping).
struct Training {
  const Narx::Params& shape;
  std::size_t regressors;
  const Rows& rows;
  const NarxFitOptions& options;
  Narx::State monitor_start;
  std::span<const double> monitor_input;
  std::span<const double> monitor_output;
  // The whole fit part (training and monitor rows), which every run must follow in free run.
  std::span<const double> fit_input;
  std::span<const double> fit_output;
};

// A free run that has left the measured output range by more than this many of its widths has
// run away: it describes nothing the record holds (free_run_check.hpp's rule for the dynamics).
constexpr double kNarxRunawayWidths = 10.0;
// How much stronger the ridge of the second attempt is when every start ran away.
constexpr double kStableRidgeFactor = 1e3;

// The first sample at which the NARX of `shape` with `weights`, run free from rest at the first
// sample of `input`, leaves the range of `output` by more than kNarxRunawayWidths widths (or is
// not finite); none when it stays.
std::optional<std::size_t> free_run_exit(const Narx::Params& shape,
                                         const std::vector<double>& weights,
                                         std::span<const double> input,
                                         std::span<const double> output) {
  Narx::Params params = shape;
  params.weights = weights;
  const Narx model(params);
  auto state = model.state_at_rest(input.front(), output.front());
  std::vector<double> simulated(input.size());
  simulate(model, state, input, simulated);
  const auto [low, high] = std::minmax_element(output.begin(), output.end());
  const double margin = kNarxRunawayWidths * (*high - *low);
  for (std::size_t k = 0; k < simulated.size(); ++k) {
    if (!(simulated[k] >= *low - margin && simulated[k] <= *high + margin)) return k;
  }
  return std::nullopt;
}

// One training run from the initial weights of one seed (a start of the multistart engine,
// multistart_driver.hpp): the one-step stage, then the simulation-error stage, each with early
// stopping on the monitor part.
struct NarxRun {
  std::vector<double> weights;
  double initial_cost = 0.0;  // one-step cost of the initial weights
  ceres::Solver::Summary one_step;
  ceres::Solver::Summary simulation;
  bool simulation_stage = false;
  bool monitored = false;
  bool early_stopped = false;
  double monitor_error = std::numeric_limits<double>::infinity();
  std::size_t best_iteration = 0;
  std::size_t best_stage = 1;
  // The engine's ranking: the free-run error on the monitor part when there is one, else the
  // final cost of the last stage; every run is usable (a diverging model is reported later).
  double cost = 0.0;
  bool usable = true;  // false: it runs away in free run on the fit part
  std::optional<std::size_t> runaway_sample;
  bool finished = true;
  std::size_t iterations = 0;
};

NarxRun train(const Training& t, std::uint64_t seed, std::size_t max_iterations) {
  NarxRun run;
  std::vector<double> weights = t.shape.weights;
  initial_weights(t.rows, t.shape, seed, weights);
  ceres::Problem problem;
  for (std::size_t begin = 0; begin < t.rows.count(); begin += kRowsPerBlock) {
    const std::size_t end = std::min(t.rows.count(), begin + kRowsPerBlock);
    problem.AddResidualBlock(
        new BlockResiduals(t.rows, begin, end, weights.size(), t.shape.hidden_sizes), nullptr,
        weights.data());
  }
  add_ridge(problem, t.shape, t.regressors, t.rows, t.options, weights);
  run.initial_cost = one_step_cost(t.rows, t.shape, weights);

  auto solver = detail::levenberg_marquardt_options(max_iterations, detail::kFunctionTolerance);
  std::optional<EarlyStopping> stopping;
  if (!t.monitor_input.empty()) {
    stopping.emplace(t.shape, weights, t.monitor_start, t.monitor_input, t.monitor_output,
                     t.options.patience);
    solver.update_state_every_iteration = true;
    solver.callbacks.push_back(&*stopping);
  }
  detail::StagnationStop one_step_stagnation;
  solver.callbacks.push_back(&one_step_stagnation);
  ceres::Solve(solver, &problem, &run.one_step);
  if (one_step_stagnation.stopped()) run.one_step.message = one_step_stagnation.message();
  if (stopping && !stopping->best().empty()) weights = stopping->best();

  run.simulation_stage = t.options.simulation_iterations > 0 && t.shape.output_lags > 0;
  if (run.simulation_stage) {
    run.simulation = simulation_error_stage(t.rows, t.shape, t.regressors, t.options, solver,
                                            stopping ? &*stopping : nullptr, weights);
  }
  const auto& last = run.simulation_stage ? run.simulation : run.one_step;
  run.cost = last.final_cost;
  if (stopping) {
    run.monitored = true;
    run.early_stopped = stopping->stopped();
    run.monitor_error = stopping->best_error();
    run.best_iteration = stopping->best_iteration();
    run.best_stage = stopping->best_stage();
    run.cost = run.monitor_error;
  }
  if (!(run.cost < std::numeric_limits<double>::infinity())) {
    run.cost = std::numeric_limits<double>::max();
  }
  run.iterations = (run.one_step.iterations.empty() ? 0 : run.one_step.iterations.size() - 1) +
                   (run.simulation_stage && !run.simulation.iterations.empty()
                        ? run.simulation.iterations.size() - 1
                        : 0);
  run.runaway_sample = free_run_exit(t.shape, weights, t.fit_input, t.fit_output);
  run.usable = !run.runaway_sample;
  run.weights = std::move(weights);
  return run;
}

// The report of the kept run: method, how it ended, costs and its message.
void report_run(NarxFit& result, const NarxRun& run, const Rows& rows, const Narx::Params& shape,
                const NarxFitOptions& options) {
  auto& report = result.report;
  report.model = "narx";
  report.method =
      "levenberg-marquardt (ceres): one-step-ahead prediction error (backpropagated Jacobian)" +
      std::string(run.simulation_stage ? ", then simulation error (forward sensitivities)" : "") +
      std::string(run.monitored ? ", early stopping on the free-run error" : "") +
      (options.starts > 1 ? fmt::format("; the best of {} initialisations", options.starts) : "");
  const ceres::Solver::Summary& last = run.simulation_stage ? run.simulation : run.one_step;
  // Early stopping that ended the last stage is the method's own stopping rule: converged.
  report.termination =
      run.early_stopped ? Termination::converged : detail::termination_of_ceres(last);
  report.initial_cost = run.initial_cost;
  report.final_cost = one_step_cost(rows, shape, run.weights);
  report.parameters = run.weights.size();
  result.best_iteration = run.best_iteration;
  result.best_stage = run.best_stage;
  const std::string stopping_text =
      run.monitored
          ? fmt::format("; kept {} iteration {} (free-run RMSE {:.4g} on the early-stopping part)",
                        run.best_stage == 2 ? "simulation-error" : "one-step", run.best_iteration,
                        run.monitor_error)
          : "";
  report.message = fmt::format(
      "{}{}; one-step-ahead RMSE {:.4g} (fit){}",
      run.early_stopped ? fmt::format("free-run error on the early-stopping part not improved "
                                      "for {} iterations",
                                      options.patience)
                        : last.message,
      stopping_text, result.one_step_fit.rmse,
      result.one_step_validation
          ? fmt::format(", {:.4g} (validation)", result.one_step_validation->rmse)
          : "");
}

NarxFit fit_parts(std::span<const double> input, std::span<const double> output,
                  std::span<const double> validation_input,
                  std::span<const double> validation_output, bool continue_into_validation,
                  const NarxFitOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  auto shape = structure(input, output, options);
  const Narx shape_model(shape);  // validates the structure
  const std::size_t weight_count = shape.weights.size();
  const std::size_t warmup = std::max(shape.input_lags, shape.output_lags);

  // Training rows and the early-stopping monitor part at the end of the fit part.
  const auto monitor = static_cast<std::size_t>(
      std::llround(options.early_stopping_fraction * static_cast<double>(input.size())));
  const std::size_t train_end = input.size() - monitor;
  const std::size_t train_rows = train_end > warmup ? train_end - warmup : 0;
  if (train_rows < weight_count || (monitor > 0 && monitor < 2)) {
    throw Error(fmt::format("NARX fit: {} samples ({} training rows after the {}-sample warm-up "
                            "and the early-stopping part of {}) are too few for {} parameters; "
                            "give more data or a smaller network",
                            input.size(), train_rows, warmup, monitor, weight_count),
                "input");
  }
  const Rows rows =
      one_step_rows(shape_model, input.first(train_end), output.first(train_end), warmup);
  Training training{shape, shape_model.regressor_count(), rows, options, {}, {}, {}, input, output};
  if (monitor > 0) {
    training.monitor_start =
        shape_model.state_after(input.first(train_end), output.first(train_end));
    training.monitor_input = input.subspan(train_end);
    training.monitor_output = output.subspan(train_end);
  }
  // Every start is checked in free run on the fit part; when all of them run away, the starts
  // are trained again with a ridge kStableRidgeFactor times stronger (a smaller network gain).
  std::optional<NarxRun> first_unstable;
  std::size_t unstable_starts = 0;
  const auto train_all = [&](const NarxFitOptions& chosen) {
    const Training attempt{
        training.shape,         training.regressors,    training.rows,           chosen,
        training.monitor_start, training.monitor_input, training.monitor_output, training.fit_input,
        training.fit_output};
    return detail::run_multistart(
        chosen.starts,
        {.screen = false, .max_iterations = chosen.max_iterations, .progress = chosen.progress},
        [&](std::size_t s, std::size_t iterations) {
          auto run = train(attempt, chosen.seed + s, iterations);
          if (!run.usable) {
            ++unstable_starts;
            if (!first_unstable) first_unstable = run;
          }
          return run;
        },
        [](const NarxRun& run, std::size_t) { return run; });
  };
  auto runs = train_all(options);
  NarxFitOptions stronger = options;
  const bool retried = !runs.found;
  if (retried) {
    stronger.regularization =
        options.regularization > 0.0 ? options.regularization * kStableRidgeFactor : 1e-3;
    // The progress told has ended (done == total); the second attempt runs untold.
    stronger.progress = {};
    runs = train_all(stronger);
  }
  const bool stable = runs.found;
  const NarxRun& best = stable ? runs.best : *first_unstable;

  shape.weights = best.weights;
  NarxFit result{Narx(shape), {}, {}, {}, {}, 0, 1};
  result.initial_state = result.model.state_at_rest(input.front(), output.front());
  result.report.iterations = runs.iterations;
  const bool finite = add_free_run_errors(result, input, output, validation_input,
                                          validation_output, continue_into_validation);
  const auto diverged = result.report;
  report_run(result, best, rows, shape, retried && stable ? stronger : options);
  if (!finite) {
    result.report.termination = diverged.termination;
    result.report.message = diverged.message;
  }
  if (!stable) {
    const auto [low, high] = std::minmax_element(output.begin(), output.end());
    result.report.termination = Termination::failed;
    result.report.message = fmt::format(
        "unstable in free run: each of the {} trained starts (regularization {:g}, then {:g}) "
        "runs away on the fit part; the first left the output range [{:.6g}, {:.6g}] by more "
        "than {:g} widths at sample {} (try fewer output lags, a smaller network or more "
        "simulation_iterations)",
        unstable_starts, options.regularization, stronger.regularization, *low, *high,
        kNarxRunawayWidths, *first_unstable->runaway_sample);
  } else if (retried) {
    result.report.message +=
        fmt::format("; every start ran away in free run at regularization {:g}: refitted at {:g}",
                    options.regularization, stronger.regularization);
  }
  result.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace

NarxFit fit_narx(std::span<const double> input, std::span<const double> output,
                 const NarxFitOptions& options) {
  validate_options(options);
  validate_record(input, output, "");
  if (options.validate_fraction == 0.0) return fit_parts(input, output, {}, {}, false, options);
  const auto split = split_by_fraction(input.size(), options.validate_fraction);
  return fit_parts(input.subspan(split.fit_begin, split.fit_size()),
                   output.subspan(split.fit_begin, split.fit_size()),
                   input.subspan(split.validation_begin, split.validation_size()),
                   output.subspan(split.validation_begin, split.validation_size()), true, options);
}

NarxFit fit_narx(std::span<const double> input, std::span<const double> output,
                 std::span<const double> validation_input,
                 std::span<const double> validation_output, const NarxFitOptions& options) {
  validate_options(options);
  validate_record(input, output, "");
  validate_record(validation_input, validation_output, " validation");
  if (options.validate_fraction != 0.0) {
    throw Error(fmt::format("NARX fit: validate_fraction = {} must be 0 with a separate "
                            "validation record",
                            options.validate_fraction),
                "validate_fraction");
  }
  return fit_parts(input, output, validation_input, validation_output, false, options);
}

}  // namespace hyst
