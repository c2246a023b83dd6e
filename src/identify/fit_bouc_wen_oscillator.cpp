#include "hyst/identify/fit_bouc_wen_oscillator.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "detail/multistart_fit.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

constexpr std::size_t kOscillatorParameters = 7;  // m, c, k, alpha, beta gamma, beta delta, nu
constexpr int kNu = 6;
using OscillatorVector = std::array<double, kOscillatorParameters>;

OscillatorVector physical_of(const BoucWenOscillator::Params& p) {
  return {p.mass, p.damping, p.stiffness, p.alpha, p.beta * p.gamma, p.beta * p.delta, p.nu};
}

// Residuals of all records for scaled parameters q (physical = scale * q), divided by y_scale.
class SimulationError {
 public:
  SimulationError(std::span<const BoucWenOscillatorRecord> records, OscillatorVector scale,
                  double input_sample_time, std::size_t substeps, double y_scale)
      : records_(records.begin(), records.end()),
        scale_(scale),
        dt_(input_sample_time),
        substeps_(substeps),
        y_scale_(y_scale) {
    for (const auto& record : records_)
      residuals_ += record.output.size() - record.skip;
  }
  std::size_t residuals() const { return residuals_; }

  template <class T>
  bool operator()(const T* q, T* residuals) const {
    const detail::BoucWenOscillatorCoefficients<T> p{
        q[0] * scale_[0], q[1] * scale_[1], q[2] * scale_[2], q[3] * scale_[3],
        q[4] * scale_[4], q[5] * scale_[5], q[6] * scale_[6]};
    const bool nu_is_one = p.nu == 1.0;
    std::size_t r = 0;
    for (const auto& record : records_) {
      std::array<T, 3> x{T(0.0), T(0.0), T(0.0)};
      double previous = record.input.front();
      const std::size_t n = record.output.size();
      for (std::size_t k = 0; k < n; ++k) {
        // Output sample k belongs to input sample k * oversampling: advance up to it.
        for (std::size_t index = (k == 0 ? 0 : (k - 1) * record.oversampling + 1);
             index <= k * record.oversampling; ++index) {
          const double u = record.input[index];
          detail::bouc_wen_oscillator_advance(p, x, previous, u, dt_, substeps_, true, nu_is_one);
          previous = u;
        }
        if (k >= record.skip) residuals[r++] = (x[0] - record.output[k]) / y_scale_;
      }
    }
    return true;
  }

 private:
  std::vector<BoucWenOscillatorRecord> records_;
  OscillatorVector scale_;
  double dt_;
  std::size_t substeps_;
  double y_scale_;
  std::size_t residuals_ = 0;
};

}  // namespace

std::vector<double> simulate_bouc_wen_oscillator(const BoucWenOscillator& model,
                                                 std::span<const double> input,
                                                 std::size_t oversampling) {
  if (oversampling < 1 || input.size() % oversampling != 0) {
    throw Error(fmt::format("input length {} is not a multiple of oversampling {}", input.size(),
                            oversampling),
                "oversampling");
  }
  require_finite(input, "input");
  std::vector<double> output(input.size() / oversampling);
  auto state = model.initial_state();
  if (!input.empty()) state.previous_input = input.front();
  for (std::size_t i = 0; i < input.size(); ++i) {
    const double y = model.step(state, input[i]);
    if (i % oversampling == 0) output[i / oversampling] = y;
  }
  return output;
}

std::vector<BoucWenOscillator::Params> bouc_wen_oscillator_starts(std::span<const double> input,
                                                                  std::span<const double> output,
                                                                  double sample_time) {
  require_same_size(input.size(), "input", output.size(), "output");
  if (output.size() < 10) throw Error("Bouc-Wen oscillator fit needs at least 10 samples");
  const std::size_t n = output.size() - 2;
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd b(n);
  const double ts = sample_time;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = i + 1;
    a(static_cast<Eigen::Index>(i), 0) =
        (output[k + 1] - 2.0 * output[k] + output[k - 1]) / (ts * ts);
    a(static_cast<Eigen::Index>(i), 1) = (output[k + 1] - output[k - 1]) / (2.0 * ts);
    a(static_cast<Eigen::Index>(i), 2) = output[k];
    b(static_cast<Eigen::Index>(i)) = input[k];
  }
  const Eigen::Vector3d mck = a.colPivHouseholderQr().solve(b);
  double y_max = 0.0;
  for (double y : output)
    y_max = std::max(y_max, std::abs(y));
  if (!(y_max > 0.0)) throw Error("Bouc-Wen oscillator fit: the output is zero", "output");
  // Guard against a non-physical linear fit (noise, too few samples).
  const double total_stiffness = mck(2) > 0.0 ? mck(2) : 1.0;
  const double mass = mck(0) > 0.0 ? mck(0) : total_stiffness * ts * ts;
  const double damping = std::max(mck(1), 0.0);
  std::vector<BoucWenOscillator::Params> starts;
  for (double split : {0.3, 0.6}) {
    for (auto [g, d] : {std::pair{0.4, -0.6}, std::pair{0.4, 0.2}}) {
      BoucWenOscillator::Params p;
      p.mass = mass;
      p.damping = damping;
      p.stiffness = split * total_stiffness;
      p.alpha = (1.0 - split) * total_stiffness;
      p.beta = 1.0 / y_max;
      p.gamma = g;
      p.delta = d;
      p.nu = 1.0;
      p.sample_time = sample_time;
      starts.push_back(p);
    }
  }
  return starts;
}

BoucWenOscillatorFit fit_bouc_wen_oscillator(std::span<const BoucWenOscillatorRecord> records,
                                             const BoucWenOscillatorFitOptions& options) {
  const auto clock_start = std::chrono::steady_clock::now();
  if (records.empty()) throw Error("Bouc-Wen oscillator fit: no record", "records");
  for (std::size_t i = 0; i < records.size(); ++i) {
    check_fit_record(records[i], fmt::format("records[{}]", i),
                     {.min_samples = 2, .oversampling = true, .skip = true});
  }
  if (!(options.sample_time > 0.0)) {
    throw Error(fmt::format("sample_time = {} must be > 0", options.sample_time), "sample_time");
  }
  if (options.substeps < 1 || options.substeps > 1000) {
    throw Error(fmt::format("substeps = {} must be in [1, 1000]", options.substeps), "substeps");
  }
  const std::size_t oversampling = records.front().oversampling;
  const double input_dt = options.sample_time / static_cast<double>(oversampling);

  std::vector<BoucWenOscillator::Params> starts = options.starts;
  if (starts.empty()) {
    const auto& first = records.front();
    std::vector<double> coarse_input(first.output.size());
    for (std::size_t k = 0; k < coarse_input.size(); ++k)
      coarse_input[k] = first.input[k * first.oversampling];
    starts = bouc_wen_oscillator_starts(coarse_input, first.output, options.sample_time);
  }
  for (const auto& start : starts)
    BoucWenOscillator{start};  // validates

  // Scale: the first start's magnitudes; bounds in scaled units.
  const OscillatorVector first = physical_of(starts.front());
  OscillatorVector scale{};
  for (std::size_t i = 0; i < kOscillatorParameters; ++i)
    scale[i] = first[i] != 0.0 ? std::abs(first[i]) : 1.0;
  // beta gamma and beta delta share one scale, so that their sign can change freely.
  const double product_scale = std::max(std::abs(first[4]), std::abs(first[5]));
  scale[4] = scale[5] = product_scale > 0.0 ? product_scale : 1.0;
  scale[kNu] = 1.0;
  auto ms = detail::multistart_options<kOscillatorParameters>(
      {1e-3, 0.0, 0.0, 1e-3, -1e3, -1e3, 1.0},
      {1e3, 1e3 + 1e3 * (first[1] == 0.0), 1e2, 1e2, 1e3, 1e3, 4.0}, options);
  if (!options.fit_nu) ms.fixed = {kNu};
  std::vector<OscillatorVector> physical_starts;
  for (const auto& start : starts)
    physical_starts.push_back(physical_of(start));
  const auto q_starts = detail::scaled_starts(physical_starts, scale);

  double sum_squares = 0.0;
  std::size_t count = 0;
  for (const auto& record : records) {
    for (std::size_t k = record.skip; k < record.output.size(); ++k) {
      sum_squares += record.output[k] * record.output[k];
      ++count;
    }
  }
  const double y_scale = std::sqrt(sum_squares / static_cast<double>(count));
  if (!(y_scale > 0.0)) throw Error("Bouc-Wen oscillator fit: the output is zero", "output");
  const SimulationError functor(records, scale, input_dt, options.substeps, y_scale);
  const auto result = detail::multistart_fit(functor, q_starts, ms, "Bouc-Wen oscillator");

  BoucWenOscillator::Params fitted = starts.front();
  const double beta = fitted.beta > 0.0 ? fitted.beta : 1.0;
  fitted.mass = result.q[0] * scale[0];
  fitted.damping = result.q[1] * scale[1];
  fitted.stiffness = result.q[2] * scale[2];
  fitted.alpha = result.q[3] * scale[3];
  fitted.beta = beta;
  fitted.gamma = result.q[4] * scale[4] / beta;
  fitted.delta = result.q[5] * scale[5] / beta;
  fitted.nu = result.q[kNu] * scale[kNu];
  fitted.sample_time = input_dt;
  fitted.substeps = options.substeps;
  fitted.input_between_samples = BoucWenOscillator::InputBetweenSamples::linear;
  BoucWenOscillator model(fitted);

  FitReport report =
      detail::report_of(result, y_scale, options.fit_nu ? 7 : 6, "bouc_wen_oscillator",
                        "levenberg-marquardt (ceres, autodiff through RK4), simulation error");
  std::vector<double> measured, predicted;
  for (const auto& record : records) {
    const auto simulated = simulate_bouc_wen_oscillator(model, record.input, record.oversampling);
    measured.insert(measured.end(),
                    record.output.begin() + static_cast<std::ptrdiff_t>(record.skip),
                    record.output.end());
    predicted.insert(predicted.end(), simulated.begin() + static_cast<std::ptrdiff_t>(record.skip),
                     simulated.end());
  }
  report.fit = error_metrics(measured, predicted);
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return {model, report, starts.size(), result.best_start};
}

BoucWenOscillatorFit fit_bouc_wen_oscillator(std::span<const double> input,
                                             std::span<const double> output,
                                             const BoucWenOscillatorFitOptions& options) {
  require_same_size(input.size(), "input", output.size(), "output");
  if (!(options.validate_fraction >= 0.0 && options.validate_fraction < 1.0)) {
    throw Error(fmt::format("validate_fraction = {} must be in [0, 1)", options.validate_fraction),
                "validate_fraction");
  }
  const auto n_fit = static_cast<std::size_t>(
      std::round(static_cast<double>(input.size()) * (1.0 - options.validate_fraction)));
  const BoucWenOscillatorRecord record{input.first(n_fit), output.first(n_fit), 1, 0};
  auto fit = fit_bouc_wen_oscillator(std::span(&record, 1), options);
  if (n_fit < input.size()) {
    const auto simulated = simulate_bouc_wen_oscillator(fit.model, input, 1);
    fit.report.validation =
        error_metrics(output.subspan(n_fit), std::span(simulated).subspan(n_fit));
  }
  return fit;
}

}  // namespace hyst
