#include "hyst/models/duhem.hpp"

#include <algorithm>
#include <limits>

#include "detail/parameter_rules.hpp"

namespace hyst {

Duhem::Duhem(Params params) : params_(params) {
  const detail::ParameterRules rules{"Duhem"};
  rules.greater(params_.alpha, 0.0, "alpha", "alpha");
  rules.at_least(params_.f_slope, 0.0, "f_slope", "f_slope");
  rules.at_least(params_.f_sat, 0.0, "f_sat", "f_sat");
  rules.greater(params_.v_sat, 0.0, "v_sat", "v_sat");
  rules.finite(params_.g_peak, "g_peak", "g_peak");
  if (params_.g_peak > params_.f_sat / params_.v_sat) {
    throw Error(fmt::format("Duhem g_peak = {} must be <= f_sat / v_sat = {} (f' >= g, "
                            "Coleman-Hodgdon)",
                            params_.g_peak, params_.f_sat / params_.v_sat),
                "g_peak");
  }
  if (params_.f_slope + std::min(params_.g_peak, 0.0) < 0.0) {
    throw Error(fmt::format("Duhem g(0) = f_slope + g_peak = {} must be >= 0",
                            params_.f_slope + params_.g_peak),
                "g_peak");
  }
  rules.count_in(params_.substeps, 1, 100000, "substeps", "substeps");
  rules.at_least(params_.max_input_step, 0.0, "max_input_step", "max_input_step");
  rules.integration_tolerance(params_.tolerance);
}

Duhem::State Duhem::make_state(double input, double output) const {
  const detail::ParameterRules rules{"Duhem state"};
  rules.finite(input, "input", "input");
  rules.finite(output, "output", "output");
  return {input, output};
}

double Duhem::coleman_hodgdon_margin() const {
  // f' - g = (f_sat / v_sat - g_peak) sech^2(v / v_sat) >= 0; the integral is taken by the
  // trapezoidal rule up to where the integrand is negligible.
  const double d = params_.f_sat / params_.v_sat - params_.g_peak;
  const double a = params_.alpha;
  const double end = 40.0 * params_.v_sat;
  const int points = 4000;
  double margin = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 200; ++i) {
    const double v = 20.0 * params_.v_sat * i / 200.0;
    const double h = (end - v) / points;
    double integral = 0.0;
    for (int j = 0; j <= points; ++j) {
      const double zeta = v + j * h;
      const double sech = 1.0 / std::cosh(zeta / params_.v_sat);
      // e^(a v) e^(-a zeta) folded together to avoid overflow.
      const double term = d * sech * sech * std::exp(-a * (zeta - v));
      integral += (j == 0 || j == points ? 0.5 : 1.0) * term * h;
    }
    margin = std::min(margin, g(v) - a * integral);
  }
  return margin;
}

}  // namespace hyst
