// Registry entry of the Bouc-Wen oscillator of the nonlinear system identification benchmark:
// model-file form and fitter (no inverse: a dynamic system, not a static hysteresis map).

#include <fmt/format.h>

#include "hyst/identify/fit_bouc_wen_oscillator.hpp"
#include "hyst/models/bouc_wen_oscillator.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

struct BoucWenOscillatorCodec : CodecOf<BoucWenOscillator, "bouc_wen_oscillator">,
                                ContinuousTimeCodec<BoucWenOscillator> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("mass", &P::mass, "kg", "m > 0")
        .add("damping", &P::damping, "N s/m", "c >= 0")
        .add("stiffness", &P::stiffness, "N/m", "k >= 0")
        .add("alpha", &P::alpha, "N/m", "> 0")
        .add("beta", &P::beta, "", ">= 0 (gauge: only beta gamma and beta delta matter)")
        .add("gamma", &P::gamma, "-", "any")
        .add("delta", &P::delta, "-", "any")
        .add("nu", &P::nu, "-", ">= 1", Presence::optional)
        .add("sample_time", &P::sample_time, "s", "Ts > 0 (benchmark: 1/750)")
        .add("substeps", &P::substeps, "", "RK4 steps per sample", Presence::optional)
        .add("tolerance", &P::tolerance, "",
             "> 0: adaptive Dormand-Prince with this error tolerance", Presence::optional)
        .add("input_between_samples", &P::input_between_samples, input_between_samples_from_string,
             "linear or hold", Presence::optional);
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

// 20 RK4 steps per sample unless asked otherwise: a record given to `hyst fit` may be sampled
// more coarsely than the benchmark the C++ default is set for.
BoucWenOscillatorFitOptions with_substeps(std::size_t substeps) {
  BoucWenOscillatorFitOptions options;
  options.substeps = substeps;
  return options;
}

FieldTable<BoucWenOscillatorFitOptions> bouc_wen_oscillator_fit_option_table() {
  using O = BoucWenOscillatorFitOptions;
  return add_multistart_options(
      FieldTable<O>(Presence::optional, with_substeps(20))
          .add("sample_time", &O::sample_time, "s", "sample time of the record")
          .add("substeps", &O::substeps, "", "RK4 steps per sample")
          .add("fit_nu", &O::fit_nu, "", "also fit nu (false: nu = 1)")
          .add("starts", &O::starts, parameter_table<BoucWenOscillatorCodec>(),
               "starting points (model parameters); default: derived from the data"));
}

FitOutcome fit_bouc_wen_oscillator_request(const FitRequest& request) {
  auto options = bouc_wen_oscillator_fit_option_table().read(request.options, "fit options");
  options.validate_fraction = request.validate_fraction;
  auto result = fit_bouc_wen_oscillator(request.input, request.output, options);
  auto state = result.model.initial_state();
  state.previous_input = request.input.front();
  return {std::make_unique<ModelAdapter<BoucWenOscillatorCodec>>(result.model, state),
          std::move(result.report)};
}

}  // namespace

ModelEntry bouc_wen_oscillator_entry() {
  auto entry = entry_of<BoucWenOscillatorCodec>(
      "Bouc-Wen oscillator (identification benchmark): force in, displacement out; Ceres fit");
  entry.fit_options = bouc_wen_oscillator_fit_option_table().schema();
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
