#include "hyst/identify/fit_duhem.hpp"

#include "detail/record_fit.hpp"
#include "hyst/core/scalar_value.hpp"

namespace hyst {
namespace {

// q = (alpha, f_slope, f_sat, v_sat, r), physical = q * scale except r.
struct DuhemKernel {
  std::array<double, 5> scale;
  std::size_t substeps;

  template <class T>
  bool valid(const T* q) const {
    const T g_peak = q[4] * q[2] * scale[2] / (q[3] * scale[3]);
    return q[0] > 0.0 && q[3] > 0.0 && q[1] * scale[1] + g_peak >= 0.0;
  }
  template <class T>
  T initial(const T*, double, double y0) const {
    return T(y0);
  }
  template <class T>
  T advance(const T* q, T y, double v_prev, double v) const {
    const double dv = v - v_prev;
    if (dv == 0.0) return y;
    const T f_sat = q[2] * scale[2];
    const T v_sat = q[3] * scale[3];
    // The model's step rule (duhem.hpp): steps of at most 1 / alpha in v keep RK4 stable.
    const T alpha = q[0] * scale[0];
    return detail::duhem_advance(alpha, T(q[1] * scale[1]), f_sat, v_sat, T(q[4] * f_sat / v_sat),
                                 v_prev, y, dv,
                                 detail::substeps_for(dv, substeps, 1.0 / scalar_value(alpha)));
  }
  template <class T>
  T output(const T*, const T& y, double) const {
    return y;
  }
};

// q = (a, c, r), B1 = r c; the exact per-step solution.
struct BacklashLikeKernel {
  std::array<double, 3> scale;

  template <class T>
  bool valid(const T* q) const {
    return q[0] > 0.0 && q[1] > 0.0;
  }
  template <class T>
  T initial(const T*, double, double y0) const {
    return T(y0);
  }
  template <class T>
  T advance(const T* q, T w, double v_prev, double v) const {
    using std::exp;
    const double dv = v - v_prev;
    if (dv == 0.0) return w;
    const double s = dv > 0.0 ? 1.0 : -1.0;
    const T a = q[0] * scale[0];
    const T c = q[1] * scale[1];
    const T k_s = (q[2] * c - c) / (a * s);
    return c * v + k_s + (w - c * v_prev - k_s) * exp(-a * std::abs(dv));
  }
  template <class T>
  T output(const T*, const T& w, double) const {
    return w;
  }
};

}  // namespace

DuhemFit fit_duhem(std::span<const double> input, std::span<const double> output,
                   const DuhemFitOptions& options) {
  const auto s = detail::record_scale(input, output);
  const DuhemKernel kernel{{1.0 / s.input_span, s.slope, s.output_span, s.input_span, 1.0},
                           options.substeps};
  const auto ms = detail::multistart_options<5>({1e-3, 0.0, 0.0, 1e-3, -1.0},
                                                {1e3, 20.0, 20.0, 1e2, 1.0}, options);
  std::vector<std::array<double, 5>> starts;
  for (double alpha : {3.0, 15.0}) {
    for (double r : {0.0, 0.5})
      starts.push_back({alpha, 0.2, 0.4, 0.25, r});
  }
  std::array<double, 5> q{};
  auto outcome =
      detail::fit_record(kernel, input, output, options.validate_fraction, starts, ms, "Duhem", q);
  Duhem::Params p;
  p.alpha = q[0] * kernel.scale[0];
  p.f_slope = q[1] * kernel.scale[1];
  p.f_sat = q[2] * kernel.scale[2];
  p.v_sat = q[3] * kernel.scale[3];
  p.g_peak = q[4] * p.f_sat / p.v_sat * (1.0 - 1e-12);
  p.substeps = options.substeps;
  Duhem model(p);
  outcome.report.model = "duhem";
  outcome.report.method = "levenberg-marquardt (ceres, autodiff through RK4)";
  return {model, model.make_state(input.front(), output.front()), outcome.report};
}

BacklashLikeFit fit_backlash_like(std::span<const double> input, std::span<const double> output,
                                  const DuhemFitOptions& options) {
  const auto s = detail::record_scale(input, output);
  const BacklashLikeKernel kernel{{1.0 / s.input_span, s.slope, 1.0}};
  const auto ms = detail::multistart_options<3>({1e-3, 1e-3, -1.0}, {1e3, 1e2, 0.999}, options);
  std::vector<std::array<double, 3>> starts;
  for (double a : {3.0, 15.0}) {
    for (double r : {0.2, 0.7})
      starts.push_back({a, 1.0, r});
  }
  std::array<double, 3> q{};
  auto outcome = detail::fit_record(kernel, input, output, options.validate_fraction, starts, ms,
                                    "backlash-like", q);
  BacklashLike::Params p;
  p.a = q[0] * kernel.scale[0];
  p.c = q[1] * kernel.scale[1];
  p.b1 = q[2] * p.c;
  BacklashLike model(p);
  outcome.report.model = "backlash_like";
  outcome.report.method = "levenberg-marquardt (ceres, autodiff, exact steps)";
  return {model, model.state_at(input.front(), output.front()), outcome.report};
}

}  // namespace hyst
