// Registry entry of the Bouc-Wen model: its model-file form, its numerical inverse and its fitter.

#include <string>

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "c_code_capability.hpp"
#include "hyst/identify/fit_bouc_wen.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "model_entries.hpp"
#include "monotone_inverse_codec.hpp"

namespace hyst::detail {
namespace {

struct BoucWenCodec {
  using Model = BoucWen;
  static constexpr std::string_view name = "bouc_wen";

  static nlohmann::json params_to_json(const Model& model) {
    const auto& p = model.params();
    return {{"a", p.a},
            {"beta", p.beta},
            {"gamma", p.gamma},
            {"n", p.n},
            {"stiffness", p.stiffness},
            {"alpha_k", p.alpha_k},
            {"substeps", p.substeps},
            {"max_input_step", p.max_input_step},
            {"tolerance", p.tolerance}};
  }
  static Model::Params params_from_json(JsonFields& fields) {
    Model::Params p;
    p.a = fields.number_or("a", p.a);
    p.beta = fields.number("beta");
    p.gamma = fields.number("gamma");
    p.n = fields.number_or("n", p.n);
    p.stiffness = fields.number_or("stiffness", p.stiffness);
    p.alpha_k = fields.number_or("alpha_k", p.alpha_k);
    p.substeps = fields.count_or("substeps", p.substeps);
    p.max_input_step = fields.number_or("max_input_step", p.max_input_step);
    p.tolerance = fields.number_or("tolerance", p.tolerance);
    return p;
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"input", state.input}, {"z", state.hysteretic}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    const double input = fields.number("input");
    const double z = fields.number("z");
    return model.make_state(input, z);
  }
  static std::size_t parameter_count(const Model&) { return 5; }  // rho, sigma, n, kx, kw
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    const auto w = model.normalised();
    return fmt::format(
        "Bouc-Wen model: A = {}, beta = {}, gamma = {}, n = {}, k = {}, alpha_k = {}\n"
        "  normalised: rho = {:.8g}, sigma = {:.8g}, kx = {:.8g}, kw = {:.8g}; |z| <= z0 = {:.8g}\n"
        "  integration: {}\n",
        p.a, p.beta, p.gamma, p.n, p.stiffness, p.alpha_k, w.rho, w.sigma, w.kx, w.kw,
        model.z_bound(),
        p.n == 1.0 ? std::string("exact solution per sample (n = 1)")
        : p.tolerance > 0.0
            ? fmt::format("adaptive Dormand-Prince in the input, tolerance {}", p.tolerance)
            : fmt::format("RK4 in the input, {} sub-steps per sample, max input step {}",
                          p.substeps, p.max_input_step));
  }
  static bool has_inverse(const Model&) { return true; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    return make_monotone_inverse<BoucWenCodec>(model, state, limits, state.input);
  }
};

BoucWen::Params bouc_wen_params_from_json(const nlohmann::json& params_json,
                                          const std::string& path) {
  JsonFields fields(params_json, path);
  auto params = BoucWenCodec::params_from_json(fields);
  fields.finish();
  return params;
}

std::unique_ptr<DynamicModel> create_bouc_wen(const nlohmann::json& params_json,
                                              const nlohmann::json* state_json) {
  return make_dynamic_model<BoucWenCodec>(bouc_wen_params_from_json(params_json, "params"),
                                          state_json);
}

FitOutcome fit_bouc_wen_request(const FitRequest& request) {
  JsonFields fields(request.options, "fit options");
  BoucWenFitOptions options;
  options.fit_n = fields.boolean_or("fit_n", options.fit_n);
  options.substeps = fields.count_or("substeps", options.substeps);
  options.global_evaluations = fields.count_or("global_evaluations", options.global_evaluations);
  options.max_iterations = fields.count_or("max_iterations", options.max_iterations);
  fields.finish();
  options.validate_fraction = request.validate_fraction;
  auto result = fit_bouc_wen(request.input, request.output, options);
  return {std::make_unique<ModelAdapter<BoucWenCodec>>(result.model, result.initial_state),
          std::move(result.report)};
}

}  // namespace

ModelEntry bouc_wen_entry() {
  ModelEntry entry;
  entry.name = std::string(BoucWenCodec::name);
  entry.description =
      "Bouc-Wen: F = alpha_k k x + (1 - alpha_k) k z, bounded class; RK4 in the input; Ceres fit";
  entry.parameters = {
      {"a", "number", "-", "A > 0 (default 1)"},
      {"beta", "number", "", "beta - gamma >= 0 and beta + gamma > 0"},
      {"gamma", "number", "", "see beta"},
      {"n", "number", "-", "exponent >= 1 (default 1)"},
      {"stiffness", "number", "output / input units", "k > 0 (default 1)"},
      {"alpha_k", "number", "-", "share of the linear spring in [0, 1] (default 0.5)"},
      {"substeps", "whole number", "", "minimum RK4 steps per sample (20)"},
      {"max_input_step", "number", "input units", "largest RK4 step, 0 = none (0)"},
      {"tolerance", "number", "", "n != 1, > 0: adaptive Dormand-Prince with this tolerance (0)"},
  };
  entry.fit_options = {
      {"fit_n", "boolean", "", "also fit the exponent n (false: n = 1)"},
      {"substeps", "whole number", "", "RK4 steps per sample (20)"},
      {"max_iterations", "whole number", "", "Levenberg-Marquardt iterations (100)"},
      {"global_evaluations", "whole number", "",
       "cost evaluations of the global search before the local starts, 0 = none (300)"},
  };
  entry.create = &create_bouc_wen;
  entry.fit = &fit_bouc_wen_request;
  entry.example_params = {{"a", 1.0}, {"beta", 0.6},      {"gamma", 0.2},
                          {"n", 1.5}, {"stiffness", 1.0}, {"alpha_k", 0.3}};
  entry.c_code = c_code_of<BoucWenCodec>();
  entry.actuator_force = actuator_force_of<BoucWenCodec>();
  return entry;
}

}  // namespace hyst::detail
