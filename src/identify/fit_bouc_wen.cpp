#include "hyst/identify/fit_bouc_wen.hpp"

#include "detail/record_fit.hpp"

namespace hyst {
namespace {

// q = (rho, sigma, n, kx, kw), all scaled by `scale`.
struct BoucWenKernel {
  std::array<double, 5> scale;
  std::size_t substeps;

  template <class T>
  bool valid(const T* q) const {
    return q[0] > 0.0 && q[1] * scale[1] >= 0.5 && q[2] * scale[2] >= 1.0;
  }
  template <class T>
  T initial(const T*, double, double) const {
    return T(0.0);
  }
  template <class T>
  T advance(const T* q, T w, double v_prev, double v) const {
    const double dx = v - v_prev;
    if (dx == 0.0) return w;
    const T rho = q[0] * scale[0];
    const T sigma = q[1] * scale[1];
    return detail::bouc_wen_advance(rho, rho * sigma, rho * (1.0 - sigma), T(q[2] * scale[2]), w,
                                    dx, substeps);
  }
  template <class T>
  T output(const T* q, const T& w, double v) const {
    return q[3] * scale[3] * v + q[4] * scale[4] * w;
  }
};

}  // namespace

BoucWenFit fit_bouc_wen(std::span<const double> input, std::span<const double> output,
                        const BoucWenFitOptions& options) {
  const auto s = detail::record_scale(input, output);
  const BoucWenKernel kernel{{1.0 / s.input_span, 1.0, 1.0, s.slope, s.output_span},
                             options.substeps};
  auto ms = detail::multistart_options<5>({1e-3, 0.5, 1.0, 0.0, 0.0}, {1e3, 5.0, 5.0, 10.0, 10.0},
                                          options);
  if (!options.fit_n) ms.fixed = {2};
  std::vector<std::array<double, 5>> starts;
  for (double rho : {2.0, 8.0}) {
    for (double sigma : {0.6, 0.9})
      starts.push_back({rho, sigma, 1.0, 0.5, 0.5 / rho});
  }
  std::array<double, 5> q{};
  auto outcome = detail::fit_record(kernel, input, output, options.validate_fraction, starts, ms,
                                    "Bouc-Wen", q);
  BoucWen::Normalised w;
  w.rho = q[0] * kernel.scale[0];
  w.sigma = q[1];
  w.n = q[2];
  w.kx = q[3] * kernel.scale[3];
  w.kw = q[4] * kernel.scale[4];
  if (!(w.kx + w.kw * w.rho > 0.0)) {
    throw Error(
        "Bouc-Wen fit: the best fit is a constant output (kx = kw = 0, both at their lower "
        "bound): the output does not follow the input as a hysteretic spring; a record of a "
        "mass on a spring (displacement lagging the force) needs bouc_wen_oscillator",
        "output");
  }
  BoucWen model(BoucWen::from_normalised(w, options.substeps));
  outcome.report.model = "bouc_wen";
  outcome.report.method = "levenberg-marquardt (ceres, autodiff through RK4), normalised form";
  auto state = model.initial_state();
  state.input = input.front();
  return {model, state, outcome.report};
}

}  // namespace hyst
