// Registry entry of the Bouc-Wen oscillator of the nonlinear system identification benchmark:
// model-file form and fitter (no inverse: a dynamic system, not a static hysteresis map).

#include <fmt/format.h>

#include "hyst/identify/fit_bouc_wen_oscillator.hpp"
#include "hyst/models/bouc_wen_oscillator.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

struct BoucWenOscillatorCodec {
  using Model = BoucWenOscillator;
  static constexpr std::string_view name = "bouc_wen_oscillator";

  static nlohmann::json params_to_json(const Model& model) {
    const auto& p = model.params();
    return {{"mass", p.mass},
            {"damping", p.damping},
            {"stiffness", p.stiffness},
            {"alpha", p.alpha},
            {"beta", p.beta},
            {"gamma", p.gamma},
            {"delta", p.delta},
            {"nu", p.nu},
            {"sample_time", p.sample_time},
            {"substeps", p.substeps},
            {"tolerance", p.tolerance},
            {"input_between_samples", std::string(to_string(p.input_between_samples))}};
  }
  static Model::Params params_from_json(JsonFields& fields) {
    Model::Params p;
    p.mass = fields.number("mass");
    p.damping = fields.number("damping");
    p.stiffness = fields.number("stiffness");
    p.alpha = fields.number("alpha");
    p.beta = fields.number("beta");
    p.gamma = fields.number("gamma");
    p.delta = fields.number("delta");
    p.nu = fields.number_or("nu", p.nu);
    p.sample_time = fields.number("sample_time");
    p.substeps = fields.count_or("substeps", p.substeps);
    p.tolerance = fields.number_or("tolerance", p.tolerance);
    if (fields.has("input_between_samples")) {
      p.input_between_samples =
          fields.parsed("input_between_samples", input_between_samples_from_string);
    }
    return p;
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& s) {
    return {{"displacement", s.displacement},
            {"velocity", s.velocity},
            {"hysteretic_force", s.hysteretic_force},
            {"previous_input", s.previous_input}};
  }
  static Model::State state_from_json(const Model&, JsonFields& fields) {
    Model::State s;
    s.displacement = fields.number("displacement");
    s.velocity = fields.number("velocity");
    s.hysteretic_force = fields.number("hysteretic_force");
    s.previous_input = fields.number("previous_input");
    return s;
  }
  static std::size_t parameter_count(const Model&) { return 6; }  // m c k alpha bg bd
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "Bouc-Wen oscillator: m = {} kg, c = {} N s/m, k = {} N/m, alpha = {} N/m, beta = {}, "
        "gamma = {}, delta = {}, nu = {}\n  input force [N], output displacement [m]; Ts = {} s, "
        "{} RK4 steps per sample, input {} between samples\n",
        p.mass, p.damping, p.stiffness, p.alpha, p.beta, p.gamma, p.delta, p.nu, p.sample_time,
        p.substeps, to_string(p.input_between_samples));
  }
  static bool has_inverse(const Model&) { return false; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model&, const Model::State&,
                                                      const InverseLimits&) {
    throw Error("the Bouc-Wen oscillator has no inverse (a dynamic system)");
  }
};

FitOutcome fit_bouc_wen_oscillator_request(const FitRequest& request) {
  JsonFields fields(request.options, "fit options");
  BoucWenOscillatorFitOptions options;
  options.sample_time = fields.number_or("sample_time", options.sample_time);
  options.substeps = fields.count_or("substeps", 20);
  options.fit_nu = fields.boolean_or("fit_nu", options.fit_nu);
  options.global_evaluations = fields.count_or("global_evaluations", options.global_evaluations);
  options.max_iterations = fields.count_or("max_iterations", options.max_iterations);
  fields.finish();
  options.validate_fraction = request.validate_fraction;
  auto result = fit_bouc_wen_oscillator(request.input, request.output, options);
  auto state = result.model.initial_state();
  state.previous_input = request.input.front();
  return {std::make_unique<ModelAdapter<BoucWenOscillatorCodec>>(result.model, state),
          std::move(result.report)};
}

}  // namespace

ModelEntry bouc_wen_oscillator_entry() {
  ModelEntry entry;
  entry.name = std::string(BoucWenOscillatorCodec::name);
  entry.description =
      "Bouc-Wen oscillator (identification benchmark): force in, displacement out; Ceres fit";
  entry.parameters = {
      {"mass", "number", "kg", "m > 0"},
      {"damping", "number", "N s/m", "c >= 0"},
      {"stiffness", "number", "N/m", "k >= 0"},
      {"alpha", "number", "N/m", "> 0"},
      {"beta", "number", "", ">= 0 (gauge: only beta gamma and beta delta matter)"},
      {"gamma", "number", "-", "any"},
      {"delta", "number", "-", "any"},
      {"nu", "number", "-", ">= 1 (default 1)"},
      {"sample_time", "number", "s", "Ts > 0 (benchmark: 1/750)"},
      {"substeps", "whole number", "", "RK4 steps per sample (20)"},
      {"tolerance", "number", "", "> 0: adaptive Dormand-Prince with this error tolerance (0)"},
      {"input_between_samples", "string", "", "linear (default) or hold"},
  };
  entry.fit_options = {
      {"sample_time", "number", "s", "sample time of the record (1/750)"},
      {"substeps", "whole number", "", "RK4 steps per sample (20)"},
      {"fit_nu", "boolean", "", "also fit nu (false: nu = 1)"},
      {"max_iterations", "whole number", "", "Levenberg-Marquardt iterations (1000)"},
      {"global_evaluations", "whole number", "",
       "cost evaluations of the global search before the local starts, 0 = none (300)"},
  };
  entry.create = &create_from_json<BoucWenOscillatorCodec>;
  entry.fit = &fit_bouc_wen_oscillator_request;
  const auto p = BoucWenOscillator::benchmark();
  entry.example_params = {
      {"mass", p.mass},        {"damping", p.damping}, {"stiffness", p.stiffness},
      {"alpha", p.alpha},      {"beta", p.beta},       {"gamma", p.gamma},
      {"delta", p.delta},      {"nu", p.nu},           {"sample_time", p.sample_time},
      {"substeps", p.substeps}};
  return entry;
}

}  // namespace hyst::detail
