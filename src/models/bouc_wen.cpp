#include "hyst/models/bouc_wen.hpp"

#include "detail/parameter_rules.hpp"

namespace hyst {

BoucWen::BoucWen(Params params) : params_(params) {
  const detail::ParameterRules rules{"Bouc-Wen"};
  rules.greater(params_.a, 0.0, "A", "a");
  rules.finite(params_.beta, "beta", "beta");
  rules.finite(params_.gamma, "gamma", "gamma");
  if (!(params_.beta + params_.gamma > 0.0)) {
    throw Error(fmt::format("Bouc-Wen beta + gamma = {} + {} = {:.6g} must be > 0 (otherwise z is "
                            "unbounded)",
                            params_.beta, params_.gamma, params_.beta + params_.gamma),
                "gamma");
  }
  if (!(params_.beta - params_.gamma >= 0.0)) {
    throw Error(fmt::format("Bouc-Wen beta - gamma = {} - {} = {:.6g} must be >= 0 (sigma >= 1/2: "
                            "properly oriented, bounded loops)",
                            params_.beta, params_.gamma, params_.beta - params_.gamma),
                "beta");
  }
  rules.at_least(params_.n, 1.0, "exponent n", "n");
  rules.greater(params_.stiffness, 0.0, "stiffness k", "stiffness");
  rules.at_least(params_.alpha_k, 0.0, "alpha_k", "alpha_k");
  if (params_.alpha_k > 1.0) rules.fail("alpha_k", "alpha_k", params_.alpha_k, "must be <= 1");
  rules.count_in(params_.substeps, 1, 100000, "substeps", "substeps");
  rules.at_least(params_.max_input_step, 0.0, "max_input_step", "max_input_step");
  rules.integration_tolerance(params_.tolerance);
  z_bound_ = std::pow(params_.a / (params_.beta + params_.gamma), 1.0 / params_.n);
  max_input_step_ = params_.max_input_step > 0.0 ? params_.max_input_step
                                                 : z_bound_ / (4.0 * params_.n * params_.a);
}

BoucWen::Params BoucWen::from_normalised(const Normalised& w, std::size_t substeps,
                                         double max_input_step) {
  const detail::ParameterRules rules{"Bouc-Wen normalised"};
  rules.greater(w.rho, 0.0, "rho", "rho");
  rules.at_least(w.sigma, 0.5, "sigma", "sigma");
  rules.at_least(w.n, 1.0, "exponent n", "n");
  rules.finite(w.kx, "kx", "kx");
  rules.at_least(w.kw, 0.0, "kw", "kw");
  // Gauge A = 1: z0 = 1 / rho, beta + gamma = rho^n.
  Params p;
  p.a = 1.0;
  const double sum = std::pow(w.rho, w.n);
  p.beta = w.sigma * sum;
  p.gamma = (1.0 - w.sigma) * sum;
  p.n = w.n;
  const double hysteretic_gain = w.kw * w.rho;  // (1 - alpha_k) k
  p.stiffness = w.kx + hysteretic_gain;
  rules.greater(p.stiffness, 0.0, "kx + kw rho", "kx");
  p.alpha_k = w.kx / p.stiffness;
  if (p.alpha_k < 0.0 || p.alpha_k > 1.0) {
    throw Error(fmt::format("Bouc-Wen normalised kx = {} must be >= 0", w.kx), "kx");
  }
  p.substeps = substeps;
  p.max_input_step = max_input_step;
  return p;
}

BoucWen::Normalised BoucWen::normalised() const {
  Normalised w;
  w.rho = params_.a / z_bound_;
  w.sigma = params_.beta / (params_.beta + params_.gamma);
  w.n = params_.n;
  w.kx = params_.alpha_k * params_.stiffness;
  w.kw = (1.0 - params_.alpha_k) * params_.stiffness * z_bound_;
  return w;
}

BoucWen::State BoucWen::make_state(double input, double hysteretic) const {
  const detail::ParameterRules rules{"Bouc-Wen state"};
  rules.finite(input, "input", "input");
  rules.finite(hysteretic, "z", "z");
  if (std::abs(hysteretic) > z_bound_ * (1.0 + 1e-12)) {
    throw Error(
        fmt::format("Bouc-Wen state |z| = {} must be <= z0 = {}", std::abs(hysteretic), z_bound_),
        "z");
  }
  return {input, hysteretic};
}

}  // namespace hyst
