#include "hyst/identify/fit_jiles_atherton.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "detail/multistart_fit.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/scalar_value.hpp"

namespace hyst {
namespace {

constexpr std::size_t kJaParameters = 5;  // M_s, a, k, c, alpha
using JaVector = std::array<double, kJaParameters>;
// Step error (relative to M_s) of the simulations that only rank parameter sets (start costs,
// global stage, screening): 100 times the model's default, i.e. loops within ~1e-5 M_s, far below
// any measured misfit; the refinement runs at the model's default.
constexpr double kScreeningStepError = 100.0 * JilesAtherton::default_step_error;

// Forward-mode derivatives for the simulation inside the fit: a value and its N partial
// derivatives in a plain array, with only the operations the Jiles-Atherton integration uses, so
// that the compiler inlines them (ceres::Jet's Eigen vectors of length 5 are not). The value part
// is computed by the same double operations as the double simulation.
template <int N>
struct Partials {
  std::array<double, static_cast<std::size_t>(N)> d{};
  double& operator[](std::size_t i) { return d[i]; }
  double operator[](std::size_t i) const { return d[i]; }
  double& operator[](int i) { return d[static_cast<std::size_t>(i)]; }
  double operator[](int i) const { return d[static_cast<std::size_t>(i)]; }
};

template <int N>
[[gnu::always_inline]] inline Partials<N> operator*(double s, const Partials<N>& x) {
  Partials<N> r;
  for (int i = 0; i < N; ++i)
    r[i] = s * x[i];
  return r;
}

template <int N>
struct Dual {
  using Derivatives = Partials<N>;
  double a = 0.0;
  Derivatives v{};
  Dual() = default;
  explicit Dual(double value) : a(value) {}
  Dual(double value, const Derivatives& derivatives) : a(value), v(derivatives) {}
  [[gnu::always_inline]] Dual& operator+=(const Dual& y) {
    a += y.a;
    for (int i = 0; i < N; ++i)
      v[i] += y.v[i];
    return *this;
  }
  [[gnu::always_inline]] Dual& operator-=(const Dual& y) {
    a -= y.a;
    for (int i = 0; i < N; ++i)
      v[i] -= y.v[i];
    return *this;
  }
};

template <int N>
[[gnu::always_inline]] inline Dual<N> operator+(const Dual<N>& x, const Dual<N>& y) {
  Dual<N> r = x;
  return r += y;
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator-(const Dual<N>& x, const Dual<N>& y) {
  Dual<N> r = x;
  return r -= y;
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator+(double s, const Dual<N>& x) {
  return {s + x.a, x.v};
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator-(double s, const Dual<N>& x) {
  return {s - x.a, -1.0 * x.v};
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator-(const Dual<N>& x, double s) {
  return {x.a - s, x.v};
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator*(const Dual<N>& x, const Dual<N>& y) {
  Dual<N> r(x.a * y.a);
  for (int i = 0; i < N; ++i)
    r.v[i] = x.a * y.v[i] + y.a * x.v[i];
  return r;
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator*(double s, const Dual<N>& x) {
  return {s * x.a, s * x.v};
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator*(const Dual<N>& x, double s) {
  return {x.a * s, s * x.v};
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator/(const Dual<N>& x, const Dual<N>& y) {
  const double inv = 1.0 / y.a;
  Dual<N> r(x.a / y.a);
  for (int i = 0; i < N; ++i)
    r.v[i] = (x.v[i] - r.a * y.v[i]) * inv;
  return r;
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator/(double s, const Dual<N>& y) {
  const double inv = 1.0 / y.a;
  Dual<N> r(s / y.a);
  for (int i = 0; i < N; ++i)
    r.v[i] = -r.a * y.v[i] * inv;
  return r;
}
template <int N>
[[gnu::always_inline]] inline Dual<N> operator/(const Dual<N>& x, double s) {
  const double inv = 1.0 / s;
  return {x.a / s, inv * x.v};
}
template <int N>
[[gnu::always_inline]] inline bool operator<(const Dual<N>& x, double s) {
  return x.a < s;
}
template <int N>
[[gnu::always_inline]] inline bool operator>(const Dual<N>& x, double s) {
  return x.a > s;
}
template <int N>
[[gnu::always_inline]] inline bool operator<(const Dual<N>& x, const Dual<N>& y) {
  return x.a < y.a;
}

JaVector physical_of(const JilesAtherton::Params& p) {
  return {p.ms, p.a, p.k, p.c, p.alpha};
}

// Steady-state loop in any scalar type; writes one B per sample when `out` is not null.
template <class T>
void run_loop(const detail::JilesAthertonCoefficients<T>& p, JilesAthertonVariant variant,
              std::span<const double> field, const detail::JaIntegration& integration,
              bool periodic, T* out) {
  T m(0.0);
  T m_irr(0.0);
  double h = 0.0;
  auto advance = [&](double target) {
    const double dh = target - h;
    if (dh != 0.0) {
      detail::ja_advance(p, variant, h, dh, integration, m, m_irr);
      h = target;
    }
  };
  if (periodic) {
    advance(field.front());
    for (double value : field)
      advance(value);
  }
  for (std::size_t k = 0; k < field.size(); ++k) {
    advance(field[k]);
    out[k] = kMu0 * (field[k] + m);
  }
}

class LoopError {
 public:
  LoopError(std::span<const BhLoop> loops, JaVector scale, JilesAthertonVariant variant,
            double max_step, double step_error, double b_scale, bool periodic)
      : loops_(loops.begin(), loops.end()),
        scale_(scale),
        variant_(variant),
        max_step_(max_step),
        step_error_(step_error),
        b_scale_(b_scale),
        periodic_(periodic) {
    for (const auto& loop : loops_)
      residuals_ += loop.input.size();
  }
  std::size_t residuals() const { return residuals_; }

  bool operator()(const double* q, double* residuals) const {
    const detail::JilesAthertonCoefficients<double> p{
        q[0] * scale_[0], q[1] * scale_[1], q[2] * scale_[2], q[3] * scale_[3], q[4] * scale_[4]};
    return evaluate(p, residuals);
  }

  // Jacobian: the simulation runs in Dual numbers and is copied into Ceres' Jets.
  template <int N>
  bool operator()(const ceres::Jet<double, N>* q, ceres::Jet<double, N>* residuals) const {
    static_assert(N == static_cast<int>(kJaParameters));
    std::array<Dual<N>, kJaParameters> x;
    for (std::size_t i = 0; i < kJaParameters; ++i) {
      x[i].a = q[i].a * scale_[i];
      for (int j = 0; j < N; ++j)
        x[i].v[static_cast<std::size_t>(j)] = q[i].v[j] * scale_[i];
    }
    const detail::JilesAthertonCoefficients<Dual<N>> p{x[0], x[1], x[2], x[3], x[4]};
    std::vector<Dual<N>> out(residuals_);
    if (!evaluate(p, out.data())) return false;
    for (std::size_t r = 0; r < residuals_; ++r) {
      residuals[r].a = out[r].a;
      for (int j = 0; j < N; ++j)
        residuals[r].v[j] = out[r].v[static_cast<std::size_t>(j)];
    }
    return true;
  }

 private:
  template <class T>
  bool evaluate(const detail::JilesAthertonCoefficients<T>& p, T* residuals) const {
    if (!(p.ms > 0.0 && p.a > 0.0 && p.k > 0.0)) return false;
    if (!(p.alpha * p.ms / (3.0 * p.a) < 0.99)) return false;
    JilesAtherton::Params values;
    values.ms = scalar_value(p.ms);
    values.k = scalar_value(p.k);
    // dM/dH ~ 1/k: a fixed RK4 step must stay well below k, or the integration turns unstable.
    if (max_step_ > 0.0) values.max_field_step = std::min(max_step_, values.k / 20.0);
    auto integration = JilesAtherton::integration_of(values);
    integration.step_error = step_error_ * values.ms;
    std::size_t r = 0;
    for (const auto& loop : loops_) {
      run_loop(p, variant_, loop.input, integration, periodic_, residuals + r);
      for (std::size_t k = 0; k < loop.input.size(); ++k, ++r) {
        residuals[r] = (residuals[r] - loop.output[k]) / b_scale_;
        if (!std::isfinite(scalar_value(residuals[r]))) return false;
      }
    }
    return true;
  }

 private:
  std::vector<BhLoop> loops_;
  JaVector scale_;
  JilesAthertonVariant variant_;
  double max_step_;
  double step_error_;  // of the controlled RK4 steps, relative to M_s
  double b_scale_;
  bool periodic_;
  std::size_t residuals_ = 0;
};

void check_loop(const BhLoop& loop, std::string_view what, std::size_t index) {
  const std::string name = fmt::format("{}[{}]", what, index);
  require_same_size(loop.input.size(), name + ".input (H)", loop.output.size(),
                    name + ".output (B)");
  if (loop.input.size() < 8) {
    throw Error(fmt::format("{} has {} samples, at least 8 needed", name, loop.input.size()));
  }
  require_finite(loop.input, name + ".input (H)");
  require_finite(loop.output, name + ".output (B)");
  const auto [lo, hi] = std::minmax_element(loop.input.begin(), loop.input.end());
  if (!(*hi > *lo)) throw Error(fmt::format("{}: the field H (input) is constant", name), "input");
}

std::vector<double> concatenate_measured(std::span<const BhLoop> loops) {
  std::vector<double> all;
  for (const auto& loop : loops)
    all.insert(all.end(), loop.output.begin(), loop.output.end());
  return all;
}

std::vector<double> concatenate_simulated(const JilesAtherton& model, std::span<const BhLoop> loops,
                                          bool periodic) {
  std::vector<double> all;
  for (const auto& loop : loops) {
    const auto b = simulate_bh_loop(model, loop.input, periodic);
    all.insert(all.end(), b.begin(), b.end());
  }
  return all;
}

}  // namespace

std::vector<double> simulate_bh_loop(const JilesAtherton& model, std::span<const double> field,
                                     bool periodic) {
  require_not_empty(field.size(), "field");
  require_finite(field, "field");
  const auto& p = model.params();
  const detail::JilesAthertonCoefficients<double> c{p.ms, p.a, p.k, p.c, p.alpha};
  std::vector<double> b(field.size());
  run_loop(c, p.variant, field, model.integration(), periodic, b.data());
  return b;
}

std::vector<JilesAtherton::Params> jiles_atherton_starts(const BhLoop& loop,
                                                         JilesAthertonVariant variant) {
  check_loop(loop, "loops", 0);
  double m_max = 0.0;
  for (std::size_t k = 0; k < loop.input.size(); ++k)
    m_max = std::max(m_max, std::abs(loop.output[k] / kMu0 - loop.input[k]));
  // Coercive field: |H| where B changes sign (mean over the crossings), linearly interpolated.
  double coercive = 0.0;
  int crossings = 0;
  const std::size_t n = loop.input.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double b0 = loop.output[k];
    const double b1 = loop.output[(k + 1) % n];
    if ((b0 < 0.0) != (b1 < 0.0) && b1 != b0) {
      const double h0 = loop.input[k];
      const double h1 = loop.input[(k + 1) % n];
      coercive += std::abs(h0 + (h1 - h0) * (-b0) / (b1 - b0));
      ++crossings;
    }
  }
  const auto [lo, hi] = std::minmax_element(loop.input.begin(), loop.input.end());
  coercive = crossings > 0 ? coercive / crossings : 0.0;
  if (!(coercive > 0.0)) coercive = 0.05 * (*hi - *lo);
  if (!(m_max > 0.0)) throw Error("Jiles-Atherton fit: the loop has no magnetisation");
  std::vector<JilesAtherton::Params> starts;
  for (double a_factor : {1.0, 3.0}) {
    for (double c : {0.2, 0.8}) {
      for (double coupling : {0.0, 1.0}) {
        JilesAtherton::Params p;
        p.ms = 1.1 * m_max;
        p.a = a_factor * coercive;
        p.k = coercive;
        p.c = c;
        p.alpha = coupling * p.a / p.ms;
        p.variant = variant;
        starts.push_back(p);
      }
    }
  }
  return starts;
}

JilesAthertonFit fit_jiles_atherton(std::span<const BhLoop> loops,
                                    std::span<const BhLoop> validation,
                                    const JilesAthertonFitOptions& options) {
  const auto clock_start = std::chrono::steady_clock::now();
  if (loops.empty()) throw Error("Jiles-Atherton fit: no loop", "loops");
  if (!(options.max_field_step >= 0.0 && std::isfinite(options.max_field_step))) {
    throw Error(fmt::format("Jiles-Atherton fit: max_field_step = {} must be finite and >= 0",
                            options.max_field_step),
                "max_field_step");
  }
  if (!(options.function_tolerance > 0.0 && std::isfinite(options.function_tolerance))) {
    throw Error(fmt::format("Jiles-Atherton fit: function_tolerance = {} must be finite and > 0",
                            options.function_tolerance),
                "function_tolerance");
  }
  for (std::size_t i = 0; i < loops.size(); ++i)
    check_loop(loops[i], "loops", i);
  for (std::size_t i = 0; i < validation.size(); ++i)
    check_loop(validation[i], "validation", i);
  double b_sum = 0.0;
  std::size_t count = 0;
  for (const auto& loop : loops) {
    for (double b : loop.output) {
      b_sum += b * b;
      ++count;
    }
  }
  const double b_scale = std::sqrt(b_sum / static_cast<double>(count));
  if (!(b_scale > 0.0)) throw Error("Jiles-Atherton fit: B is zero", "output");
  const double max_step = options.max_field_step;

  auto starts = options.starts;
  if (starts.empty()) starts = jiles_atherton_starts(loops.front(), options.variant);
  for (auto& start : starts) {
    start.variant = options.variant;
    JilesAtherton{start};  // validates
  }
  const JaVector first = physical_of(starts.front());
  JaVector scale{first[0], first[1], first[2], 1.0,
                 first[4] > 0.0 ? first[4] : first[1] / first[0]};
  const auto ms = detail::multistart_options<kJaParameters>({0.1, 1e-3, 0.05, 0.0, 0.0},
                                                            {10.0, 1e3, 1e3, 0.99, 1e3}, options);
  std::vector<JaVector> physical_starts;
  for (const auto& start : starts)
    physical_starts.push_back(physical_of(start));
  const auto q_starts = detail::scaled_starts(physical_starts, scale);
  const LoopError functor(loops, scale, options.variant, max_step,
                          JilesAtherton::default_step_error, b_scale, options.periodic);
  const LoopError screening(loops, scale, options.variant, max_step, kScreeningStepError, b_scale,
                            options.periodic);
  const auto result = detail::multistart_fit(screening, functor, q_starts, ms, "Jiles-Atherton");

  JilesAtherton::Params fitted;
  fitted.ms = result.q[0] * scale[0];
  fitted.a = result.q[1] * scale[1];
  fitted.k = result.q[2] * scale[2];
  fitted.c = result.q[3] * scale[3];
  fitted.alpha = result.q[4] * scale[4];
  fitted.variant = options.variant;
  if (max_step > 0.0) fitted.max_field_step = std::min(max_step, fitted.k / 20.0);
  JilesAtherton model(fitted);

  FitReport report =
      detail::report_of(result, b_scale, kJaParameters, "jiles_atherton",
                        "levenberg-marquardt (ceres, autodiff through RK4), steady-state loops");
  report.fit = error_metrics(concatenate_measured(loops),
                             concatenate_simulated(model, loops, options.periodic));
  if (!validation.empty()) {
    report.validation = error_metrics(concatenate_measured(validation),
                                      concatenate_simulated(model, validation, options.periodic));
  }
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return {model, report, starts.size(), result.best_start};
}

}  // namespace hyst
