#include "hyst/identify/fit_generalized_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "detail/multistart_fit.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/data_split.hpp"

namespace hyst {
namespace {

using Model = GeneralizedPrandtlIshlinskii<TanhEnvelope>;
template <class T>
using Kernel = GpiKernel<TanhEnvelope, T>;

constexpr std::array<std::string_view, kGpiParameterCount> kParameterNames{
    "a0", "a1", "a2", "a3", "b0", "b1", "b2", "b3", "rho", "tau", "alpha"};
constexpr std::size_t kRho = static_cast<std::size_t>(GpiParameter::rho);
constexpr std::size_t kMaxM = 200;
constexpr std::size_t kPenaltyGrid = 64;

double range_of(std::span<const double> samples) {
  const auto [lowest, highest] = std::minmax_element(samples.begin(), samples.end());
  return *highest - *lowest;
}

void require_varying(std::span<const double> samples, std::string_view name, std::string_view why) {
  if (!(range_of(samples) > 0.0)) {
    throw Error(fmt::format("GPI fit: the {} is constant (all {} samples = {}); {}", name,
                            samples.size(), samples.front(), why));
  }
}

// A record in messages: "GPI fit" or "GPI fit validation" for a single record, "GPI fit record 2"
// or "GPI fit validation record 2" when there are several.
std::string gpi_record_name(std::string_view kind, std::size_t index, std::size_t count) {
  std::string name = "GPI fit";
  if (!kind.empty()) name += fmt::format(" {}", kind);
  if (count > 1) name += fmt::format(" record {}", index);
  return name;
}

// " (record 2)" when there are several records, "" otherwise.
std::string record_suffix(std::size_t index, std::size_t count) {
  return count == 1 ? std::string() : fmt::format(" (record {})", index);
}

// The part of one record the cost runs over: a warm-up (the whole record for `periodic`), then the
// fitted samples, from rest at the record's first input.
struct Segment {
  std::span<const double> warmup;
  std::span<const double> input;
  std::span<const double> output;
  double rest_input = 0.0;
};

double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// The cost of the fit, templated on the scalar: double for residuals only, ceres::Jet for the
// Jacobian. Residuals: GPI_theta[v][k] - y[k] over every segment, then the ordering penalties.
class CostFunctor {
 public:
  CostFunctor(std::vector<Segment> segments, std::size_t m, std::vector<double> grid,
              double penalty_weight)
      : segments_(std::move(segments)),
        m_(m),
        grid_(std::move(grid)),
        penalty_weight_(penalty_weight) {
    for (const auto& segment : segments_)
      samples_ += segment.input.size();
  }

  std::size_t samples() const { return samples_; }
  std::size_t residuals() const { return samples_ + grid_.size(); }

  template <class T>
  bool operator()(const T* theta, T* residuals) const {
    const std::size_t n = m_ + 1;
    std::vector<T> r(n), p(n), z(n);
    const T* a = theta;
    const T* b = theta + 4;
    Kernel<T>::exponential_density(theta[8], theta[9], theta[10], m_, r.data(), p.data());
    T* out = residuals;
    for (const auto& segment : segments_) {
      Kernel<T>::rest_state(a, b, segment.rest_input, LoopBranch::ascending, n, z.data());
      for (double v : segment.warmup)
        Kernel<T>::step(a, b, r.data(), p.data(), n, z.data(), v);
      for (std::size_t k = 0; k < segment.input.size(); ++k) {
        *out++ = Kernel<T>::step(a, b, r.data(), p.data(), n, z.data(), segment.input[k]) -
                 segment.output[k];
      }
    }
    for (double v : grid_) {
      const T excess = TanhEnvelope::value(a, v) - TanhEnvelope::value(b, v);
      *out++ = excess > 0.0 ? penalty_weight_ * excess : T(0.0);
    }
    return true;
  }

 private:
  std::vector<Segment> segments_;
  std::size_t m_;
  std::vector<double> grid_;
  double penalty_weight_;
  std::size_t samples_ = 0;
};

// 0.5 sum (model - data)^2 over the data residuals only (no penalty).
double data_cost(const CostFunctor& functor, const GpiParameterVector& theta) {
  std::vector<double> residuals(functor.residuals());
  functor(theta.data(), residuals.data());
  double cost = 0.0;
  for (std::size_t k = 0; k < functor.samples(); ++k)
    cost += 0.5 * residuals[k] * residuals[k];
  return cost;
}

// The model's state at the start of a record: at rest at its first input, then (periodic) one run
// of the whole record.
Model::State record_state(const Model& model, std::span<const double> input, bool periodic) {
  auto state = model.state_at_rest(input.front());
  if (periodic) {
    for (double v : input)
      model.step(state, v);
  }
  return state;
}

void validate_gpi_options(const GpiFitOptions& options) {
  if (options.m < 1 || options.m > kMaxM) {
    throw Error(fmt::format("GPI fit m = {} must be in [1, {}]", options.m, kMaxM), "m");
  }
  if (options.screening_iterations < 1) {
    throw Error("GPI fit screening_iterations = 0 must be >= 1", "screening_iterations");
  }
  if (!(std::isfinite(options.function_tolerance) && options.function_tolerance > 0.0)) {
    throw Error(fmt::format("GPI fit function_tolerance = {} must be finite and > 0",
                            options.function_tolerance),
                "function_tolerance");
  }
}

// The records of a fit, checked: the fitted segments with their outputs joined, the ranges of the
// fitted parts, and the operating range of every input the model will see.
struct FitData {
  DataSplit split;
  bool periodic = false;
  std::vector<Segment> segments;
  std::vector<double> all_output;
  std::size_t widest = 0;  // the record with the largest output range sets the starts
  double fit_input_min = std::numeric_limits<double>::infinity();
  double fit_input_max = -std::numeric_limits<double>::infinity();
  double output_min = 0.0;
  double output_max = 0.0;
  double input_min = std::numeric_limits<double>::infinity();
  double input_max = -std::numeric_limits<double>::infinity();
};

void check_gpi_records(std::span<const GpiRecord> records, std::span<const GpiRecord> held_out,
                       const GpiFitOptions& options) {
  if (records.empty()) throw Error("GPI fit: no record to fit");
  for (std::size_t r = 0; r < records.size(); ++r)
    check_fit_record(records[r], gpi_record_name("", r, records.size()), {});
  for (std::size_t r = 0; r < held_out.size(); ++r)
    check_fit_record(held_out[r], gpi_record_name("validation", r, held_out.size()), {});
  if (options.validate_fraction != 0.0 && (records.size() > 1 || !held_out.empty())) {
    throw Error(fmt::format("GPI fit validate_fraction = {} must be 0 when separate validation "
                            "records are given or several records are fitted",
                            options.validate_fraction),
                "validate_fraction");
  }
  for (std::size_t r = 0; r < held_out.size(); ++r) {
    require_varying(held_out[r].output,
                    fmt::format("validation output{}", record_suffix(r, held_out.size())),
                    "its range normalises the validation NRMSE");
  }
}

void widen_to(double& lowest, double& highest, std::span<const double> samples) {
  const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
  lowest = std::min(lowest, *lo);
  highest = std::max(highest, *hi);
}

FitData fit_data(std::span<const GpiRecord> records, std::span<const GpiRecord> held_out,
                 const GpiFitOptions& options) {
  check_gpi_records(records, held_out, options);
  FitData data;
  try {
    data.split = split_by_fraction(records.front().input.size(), options.validate_fraction);
  } catch (const Error& error) {
    throw Error(fmt::format("GPI fit: {}", error.what()), "validate_fraction");
  }
  data.periodic = options.initial_state == GpiFitOptions::InitialState::periodic;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto& record = records[r];
    const std::size_t size = r == 0 ? data.split.fit_size() : record.input.size();
    Segment segment{data.periodic ? record.input : std::span<const double>{},
                    record.input.first(size), record.output.first(size), record.input.front()};
    const auto suffix = record_suffix(r, records.size());
    require_varying(segment.input, fmt::format("input of the fit part{}", suffix),
                    "the envelopes need a varying input");
    require_varying(segment.output, fmt::format("output of the fit part{}", suffix),
                    "there is no hysteresis to fit");
    data.all_output.insert(data.all_output.end(), segment.output.begin(), segment.output.end());
    if (range_of(segment.output) >
        range_of(data.segments.empty() ? segment.output : data.segments[data.widest].output)) {
      data.widest = r;
    }
    widen_to(data.fit_input_min, data.fit_input_max, segment.input);
    data.segments.push_back(segment);
  }
  if (data.all_output.size() < 2 * kGpiParameterCount) {
    throw Error(fmt::format("GPI fit: the fit part has {} samples, fewer than 2 * 11 = 22",
                            data.all_output.size()));
  }
  const auto [y_lo, y_hi] = std::minmax_element(data.all_output.begin(), data.all_output.end());
  data.output_min = *y_lo;
  data.output_max = *y_hi;
  for (const auto& record : records)
    widen_to(data.input_min, data.input_max, record.input);
  for (const auto& record : held_out)
    widen_to(data.input_min, data.input_max, record.input);
  // Operating range: every input the model will see, widened by 1 % of the span.
  const double margin = 0.01 * (data.input_max - data.input_min);
  data.input_min = options.input_min.value_or(data.input_min - margin);
  data.input_max = options.input_max.value_or(data.input_max + margin);
  if (!(std::isfinite(data.input_min) && std::isfinite(data.input_max) &&
        data.input_min < data.input_max)) {
    throw Error(fmt::format("GPI fit operating range [{}, {}] must be finite with input_min < "
                            "input_max",
                            data.input_min, data.input_max),
                "input_min");
  }
  return data;
}

// The default bounds of the data with the user's overrides. rho's are set later (the gauge).
std::array<GpiParameterVector, 2> fit_bounds(const FitData& data, const GpiFitOptions& options) {
  auto bounds = default_gpi_bounds(data.fit_input_min, data.fit_input_max, data.output_min,
                                   data.output_max, options.m);
  for (std::size_t i = 0; i < kGpiParameterCount; ++i) {
    if (options.lower[i]) bounds[0][i] = *options.lower[i];
    if (options.upper[i]) bounds[1][i] = *options.upper[i];
    if (i == kRho) continue;
    if (!(std::isfinite(bounds[0][i]) && std::isfinite(bounds[1][i]) &&
          bounds[0][i] < bounds[1][i])) {
      throw Error(fmt::format("GPI fit bounds of {}: lower = {} must be < upper = {} (both finite)",
                              kParameterNames[i], bounds[0][i], bounds[1][i]),
                  fmt::format("lower[{}]", kParameterNames[i]));
    }
  }
  return bounds;
}

// The user's starts (each inside the bounds), or the data-derived ones moved into them.
std::vector<GpiParameterVector> fit_starts(const FitData& data, const GpiFitOptions& options,
                                           const std::array<GpiParameterVector, 2>& bounds) {
  std::vector<GpiParameterVector> starts = options.starts;
  const bool derived_starts = starts.empty();
  if (derived_starts) {
    const auto& widest = data.segments[data.widest];
    starts = gpi_starting_points(widest.input, widest.output, options.m);
  }
  for (std::size_t s = 0; s < starts.size(); ++s) {
    for (std::size_t i = 0; i < kGpiParameterCount; ++i) {
      double& value = starts[s][i];
      if (i == kRho) {
        if (!(std::isfinite(value) && value > 0.0)) {
          throw Error(fmt::format("GPI fit start {}: rho = {} must be finite and > 0", s, value),
                      "starts");
        }
        continue;
      }
      if (derived_starts) {
        value = std::clamp(value, bounds[0][i], bounds[1][i]);
      } else if (!(value >= bounds[0][i] && value <= bounds[1][i])) {
        throw Error(fmt::format("GPI fit start {}: {} = {} lies outside its bounds [{}, {}]", s,
                                kParameterNames[i], value, bounds[0][i], bounds[1][i]),
                    "starts");
      }
    }
  }
  return starts;
}

// The cost, with the ordering penalty on a grid of the operating range.
CostFunctor gpi_cost_functor(const FitData& data, std::size_t m) {
  std::vector<double> grid(kPenaltyGrid);
  for (std::size_t g = 0; g < kPenaltyGrid; ++g) {
    grid[g] = data.input_min + (data.input_max - data.input_min) * static_cast<double>(g) /
                                   static_cast<double>(kPenaltyGrid - 1);
  }
  const double penalty_weight = 10.0 * std::sqrt(static_cast<double>(data.all_output.size()));
  return CostFunctor(data.segments, m, std::move(grid), penalty_weight);
}

// The engine's options: rho is the scale gauge (an exact symmetry), held at its start value, so
// its bounds only have to contain every start.
detail::MultistartOptions<kGpiParameterCount> engine_options(
    const GpiFitOptions& options, const std::array<GpiParameterVector, 2>& bounds,
    const std::vector<GpiParameterVector>& starts) {
  auto engine = detail::multistart_options(bounds[0], bounds[1], options);
  double rho_min = std::numeric_limits<double>::infinity(), rho_max = 0.0;
  for (const auto& start : starts) {
    rho_min = std::min(rho_min, start[kRho]);
    rho_max = std::max(rho_max, start[kRho]);
  }
  engine.lower[kRho] = 0.5 * rho_min;
  engine.upper[kRho] = 2.0 * rho_max;
  engine.fixed = {static_cast<int>(kRho)};
  return engine;
}

// The fitted parameters in the gauge sum_j p_j = 1 (returned in `factor`: the rescaling), with a
// violation of the ordering the penalty left (tiny; returned in `excess`) removed by raising
// gamma_r.
GpiParams fitted_params(const GpiParameterVector& theta, const FitData& data, std::size_t m,
                        double initial_input, double& factor, double& excess) {
  GpiParams params =
      gpi_params_from_vector(theta, m, data.input_min, data.input_max, initial_input);
  double weight_sum = 0.0;
  std::vector<double> r(m + 1), p(m + 1);
  Kernel<double>::exponential_density(params.rho, params.tau, params.alpha, m, r.data(), p.data());
  for (double pj : p)
    weight_sum += pj;
  factor = 1.0 / weight_sum;
  params = rescale_density(params, factor);
  excess = 0.0;
  for (std::size_t k = 0; k < kEnvelopeOrderingGrid; ++k) {
    const double v = data.input_min + (data.input_max - data.input_min) * static_cast<double>(k) /
                                          static_cast<double>(kEnvelopeOrderingGrid - 1);
    excess = std::max(excess, TanhEnvelope::value(params.ascending.data(), v) -
                                  TanhEnvelope::value(params.descending.data(), v));
  }
  if (excess > 0.0) {
    params.descending[3] += excess * (1 + 1e-9) + 1e-15 * std::abs(params.descending[3]);
  }
  return params;
}

// The parameters with their bounds, in the reported gauge (the iteration's scaled by `factor`).
std::vector<GpiFitParameter> reported_parameters(
    const GpiParams& params, const std::array<GpiParameterVector, 2>& bounds,
    const std::array<bool, kGpiParameterCount>& at_bound, double factor) {
  const GpiParameterVector reported = gpi_vector_from_params(params);
  std::vector<GpiFitParameter> parameters;
  for (std::size_t i = 0; i < kGpiParameterCount; ++i) {
    const auto parameter = static_cast<GpiParameter>(i);
    GpiFitParameter entry{parameter,    reported[i], bounds[0][i],
                          bounds[1][i], i == kRho,   at_bound[i]};
    if (parameter == GpiParameter::a0 || parameter == GpiParameter::a3 ||
        parameter == GpiParameter::b0 || parameter == GpiParameter::b3 ||
        parameter == GpiParameter::alpha) {
      entry.lower /= factor;
      entry.upper /= factor;
    } else if (parameter == GpiParameter::tau) {
      entry.lower *= factor;
      entry.upper *= factor;
    } else if (parameter == GpiParameter::rho) {
      entry.lower = entry.upper = reported[i];
    }
    parameters.push_back(entry);
  }
  return parameters;
}

// Errors of the fitted model, simulated as a user would run it, each record from its own state.
void add_errors(FitReport& report, const Model& model, std::span<const GpiRecord> records,
                std::span<const GpiRecord> held_out, const FitData& data) {
  std::vector<double> predicted;
  Model::State end_of_first;
  for (std::size_t r = 0; r < records.size(); ++r) {
    auto state = record_state(model, records[r].input, data.periodic);
    const auto part = simulate(model, state, data.segments[r].input);
    predicted.insert(predicted.end(), part.begin(), part.end());
    if (r == 0) end_of_first = state;
  }
  report.final_cost = 0.0;
  for (std::size_t k = 0; k < data.all_output.size(); ++k) {
    const double e = data.all_output[k] - predicted[k];
    report.final_cost += 0.5 * e * e;
  }
  report.fit = error_metrics(data.all_output, predicted);
  if (data.split.has_validation()) {
    const auto& record = records.front();
    const auto begin = data.split.validation_begin;
    const auto size = data.split.validation_size();
    report.validation =
        error_metrics(record.output.subspan(begin, size),
                      simulate(model, end_of_first, record.input.subspan(begin, size)));
  } else if (!held_out.empty()) {
    std::vector<double> measured, prediction;
    for (const auto& record : held_out) {
      auto state = record_state(model, record.input, data.periodic);
      const auto part = simulate(model, state, record.input);
      prediction.insert(prediction.end(), part.begin(), part.end());
      measured.insert(measured.end(), record.output.begin(), record.output.end());
    }
    report.validation = error_metrics(measured, prediction);
  }
}

GpiFit fit(std::span<const GpiRecord> records, std::span<const GpiRecord> held_out,
           const GpiFitOptions& options) {
  const auto clock_start = std::chrono::steady_clock::now();
  validate_gpi_options(options);
  const FitData data = fit_data(records, held_out, options);
  const auto bounds = fit_bounds(data, options);
  const auto starts = fit_starts(data, options, bounds);
  const CostFunctor functor = gpi_cost_functor(data, options.m);
  // Every start a few iterations; the best one is refined (multistart_fit.hpp).
  const auto engine = engine_options(options, bounds, starts);
  const auto result = detail::multistart_fit(functor, starts, engine, "GPI");

  double factor = 1.0, excess = 0.0;
  const GpiParams params =
      fitted_params(result.q, data, options.m, records.front().input.front(), factor, excess);
  GpiFit fit{Model(params), {}, {}, {}, starts.size(), result.best_start};
  fit.initial_state = record_state(fit.model, records.front().input, data.periodic);
  fit.parameters = reported_parameters(params, bounds, result.at_bound, factor);

  fit.report = detail::report_of(result, 1.0, kGpiParameterCount - 1, "gpi",
                                 "levenberg-marquardt (ceres, autodiff)");
  fit.report.message = fmt::format(
      "{} record(s), {} starting points, best: start {} ({} screening + {} refining iterations); "
      "ordering repair {:.3g}; ceres: {}",
      records.size(), starts.size(), result.best_start, options.screening_iterations,
      result.refining_iterations, excess, result.message);
  fit.report.initial_cost = data_cost(functor, starts[result.best_start]);
  add_errors(fit.report, fit.model, records, held_out, data);
  fit.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return fit;
}

}  // namespace

std::string_view to_string(GpiParameter parameter) {
  return kParameterNames[static_cast<std::size_t>(parameter)];
}

GpiParameter gpi_parameter_from_string(std::string_view text) {
  for (std::size_t i = 0; i < kGpiParameterCount; ++i) {
    if (kParameterNames[i] == text) return static_cast<GpiParameter>(i);
  }
  throw Error(
      fmt::format("unknown GPI parameter '{}' (expected a0..a3, b0..b3, rho, tau or "
                  "alpha)",
                  text));
}

GpiFitOptions::InitialState gpi_initial_state_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<GpiFitOptions::InitialState>, "GPI initial state",
                             "initial_state");
}

GpiParams gpi_params_from_vector(const GpiParameterVector& theta, std::size_t m, double input_min,
                                 double input_max, double initial_input) {
  return {.envelope = EnvelopeKind::tanh,
          .ascending = {theta[0], theta[1], theta[2], theta[3]},
          .descending = {theta[4], theta[5], theta[6], theta[7]},
          .density = GpiDensity::exponential,
          .rho = theta[8],
          .tau = theta[9],
          .alpha = theta[10],
          .m = m,
          .input_min = input_min,
          .input_max = input_max,
          .initial_input = initial_input};
}

GpiParameterVector gpi_vector_from_params(const GpiParams& params) {
  if (params.envelope != EnvelopeKind::tanh || params.density != GpiDensity::exponential ||
      params.ascending.size() != 4 || params.descending.size() != 4) {
    throw Error(fmt::format("GPI parameter vector: needs tanh envelopes with 4 coefficients each "
                            "and the exponential density (got envelope = {}, density = {})",
                            to_string(params.envelope), to_string(params.density)),
                "envelope");
  }
  const auto& a = params.ascending;
  const auto& b = params.descending;
  return {a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3], params.rho, params.tau, params.alpha};
}

std::array<GpiParameterVector, 2> default_gpi_bounds(double input_min, double input_max,
                                                     double output_min, double output_max,
                                                     std::size_t m) {
  const double dv = input_max - input_min;
  const double dy = output_max - output_min;
  const double reach = std::max(std::abs(input_min), std::abs(input_max)) + 2 * dv;
  const double slope_max = 200.0 / dv;
  const double shift = slope_max * reach + 10.0;  // |a2| = |a1 v_centre| within the reach
  const double level = std::max(std::abs(output_min), std::abs(output_max)) + 10 * dy;
  const double mm = static_cast<double>(std::max<std::size_t>(m, 1));
  // Order a0, a1, a2, a3, b0, b1, b2, b3, rho (unused: gauge), tau, alpha. tau <= 300 / dy with
  // alpha <= 2 dy / m keeps tau alpha m <= 600, so every weight rho exp(-tau alpha j) is a normal
  // number.
  // clang-format off
  GpiParameterVector lower{1e-3 * dy, 1e-2 / dv,  -shift, -level,
                           1e-3 * dy, 1e-2 / dv,  -shift, -level,
                           0.0,       0.0,        1e-6 * dy / mm};
  GpiParameterVector upper{10 * dy,   slope_max,  shift,  level,
                           10 * dy,   slope_max,  shift,  level,
                           0.0,       300.0 / dy, 2 * dy / mm};
  // clang-format on
  return {lower, upper};
}

std::vector<GpiParameterVector> gpi_starting_points(std::span<const double> input,
                                                    std::span<const double> output, std::size_t m) {
  check_fit_record({input, output}, "GPI fit", {});
  require_varying(input, "input", "the envelopes need a varying input");
  require_varying(output, "output", "there is no hysteresis to fit");
  if (m < 1) throw Error("GPI fit m = 0 must be >= 1", "m");
  const auto [v_lo, v_hi] = std::minmax_element(input.begin(), input.end());
  const auto [y_lo, y_hi] = std::minmax_element(output.begin(), output.end());
  const double dv = *v_hi - *v_lo, dy = *y_hi - *y_lo;
  const double y_centre = 0.5 * (*y_hi + *y_lo);
  double v_centre = 0.5 * (*v_hi + *v_lo);

  // Crossings of the output centre (input positions) and of the input centre (output values),
  // separately on rising and falling input.
  std::vector<double> up_v, down_v, up_y, down_y;
  bool rising = true;
  for (std::size_t k = 1; k < input.size(); ++k) {
    if (input[k] > input[k - 1]) rising = true;
    if (input[k] < input[k - 1]) rising = false;
    const double y0 = output[k - 1] - y_centre, y1 = output[k] - y_centre;
    if (y0 * y1 <= 0.0 && y0 != y1) {
      const double v = input[k - 1] + (input[k] - input[k - 1]) * y0 / (y0 - y1);
      (rising ? up_v : down_v).push_back(v);
    }
    const double v0 = input[k - 1] - v_centre, v1 = input[k] - v_centre;
    if (v0 * v1 <= 0.0 && v0 != v1) {
      const double y = output[k - 1] + (output[k] - output[k - 1]) * v0 / (v0 - v1);
      (rising ? up_y : down_y).push_back(y);
    }
  }
  double width = 0.1 * dv;  // horizontal loop width [input units]
  if (!up_v.empty() && !down_v.empty()) {
    const double up = median(up_v), down = median(down_v);
    if (up > down) width = std::min(up - down, 0.8 * dv);
    v_centre = 0.5 * (up + down);
  }
  double half_height = 0.05 * dy;  // half the vertical loop height [output units]
  if (!up_y.empty() && !down_y.empty()) {
    half_height = std::clamp(0.5 * (median(down_y) - median(up_y)), 0.005 * dy, 0.45 * dy);
  }

  const double mm = static_cast<double>(m);
  std::vector<GpiParameterVector> starts;
  for (const auto& [half_range, slope] : {std::pair{0.55 * dy, 4.0 / dv}, {1.0 * dy, 2.0 / dv}}) {
    for (double split : {1.0, 0.5}) {
      const double alpha = split == 1.0 ? 0.1 * half_height / mm : half_height / mm;
      const double tau = split == 1.0 ? 0.0 : 1.0 / (alpha * mm);
      double sum = 0.0;
      for (std::size_t j = 0; j <= m; ++j)
        sum += std::exp(-tau * alpha * static_cast<double>(j));
      const double a2 = -slope * (v_centre + split * width / 2);
      const double b2 = -slope * (v_centre - split * width / 2);
      starts.push_back({half_range, slope, a2, y_centre, half_range, slope, b2, y_centre, 1.0 / sum,
                        tau, alpha});
    }
  }
  return starts;
}

GpiFit fit_generalized_prandtl_ishlinskii(std::span<const double> input,
                                          std::span<const double> output,
                                          const GpiFitOptions& options) {
  const GpiRecord record{input, output};
  return fit(std::span<const GpiRecord>(&record, 1), {}, options);
}

GpiFit fit_generalized_prandtl_ishlinskii(std::span<const double> input,
                                          std::span<const double> output,
                                          std::span<const double> validation_input,
                                          std::span<const double> validation_output,
                                          const GpiFitOptions& options) {
  const GpiRecord record{input, output};
  const GpiRecord validation{validation_input, validation_output};
  return fit(std::span<const GpiRecord>(&record, 1), std::span<const GpiRecord>(&validation, 1),
             options);
}

GpiFit fit_generalized_prandtl_ishlinskii(std::span<const GpiRecord> records,
                                          std::span<const GpiRecord> validation,
                                          const GpiFitOptions& options) {
  return fit(records, validation, options);
}

}  // namespace hyst
