// Registry entry of the Duhem (Coleman-Hodgdon) model: model-file form, numerical inverse, fitter.

#include <fmt/format.h>

#include "hyst/identify/fit_duhem.hpp"
#include "hyst/models/duhem.hpp"
#include "model_entries.hpp"
#include "monotone_inverse_codec.hpp"

namespace hyst::detail {
namespace {

struct DuhemCodec {
  using Model = Duhem;
  static constexpr std::string_view name = "duhem";

  static nlohmann::json params_to_json(const Model& model) {
    const auto& p = model.params();
    return {{"alpha", p.alpha},
            {"f_slope", p.f_slope},
            {"f_sat", p.f_sat},
            {"v_sat", p.v_sat},
            {"g_peak", p.g_peak},
            {"substeps", p.substeps},
            {"max_input_step", p.max_input_step},
            {"tolerance", p.tolerance}};
  }
  static Model::Params params_from_json(JsonFields& fields) {
    Model::Params p;
    p.alpha = fields.number("alpha");
    p.f_slope = fields.number("f_slope");
    p.f_sat = fields.number("f_sat");
    p.v_sat = fields.number("v_sat");
    p.g_peak = fields.number("g_peak");
    p.substeps = fields.count_or("substeps", p.substeps);
    p.max_input_step = fields.number_or("max_input_step", p.max_input_step);
    p.tolerance = fields.number_or("tolerance", p.tolerance);
    return p;
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"input", state.input}, {"output", state.output}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    const double input = fields.number("input");
    const double output = fields.number("output");
    return model.make_state(input, output);
  }
  static std::size_t parameter_count(const Model&) { return 5; }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "Duhem model (Coleman-Hodgdon): alpha = {}, f(v) = {} v + {} tanh(v / {}), "
        "g(v) = {} + {} sech^2(v / {}); Coleman-Hodgdon margin {:.4g}\n"
        "  integration: {}\n",
        p.alpha, p.f_slope, p.f_sat, p.v_sat, p.f_slope, p.g_peak, p.v_sat,
        model.coleman_hodgdon_margin(),
        p.tolerance > 0.0
            ? fmt::format("adaptive Dormand-Prince in the input, tolerance {}", p.tolerance)
            : fmt::format("RK4 in the input, {} sub-steps per sample, max input step {}",
                          p.substeps, p.max_input_step));
  }
  static bool has_inverse(const Model& model) { return model.params().f_slope > 0.0; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    return make_monotone_inverse<DuhemCodec>(model, state, limits, state.input);
  }
};

FitOutcome fit_duhem_request(const FitRequest& request) {
  JsonFields fields(request.options, "fit options");
  DuhemFitOptions options;
  options.substeps = fields.count_or("substeps", options.substeps);
  options.global_evaluations = fields.count_or("global_evaluations", options.global_evaluations);
  options.max_iterations = fields.count_or("max_iterations", options.max_iterations);
  fields.finish();
  options.validate_fraction = request.validate_fraction;
  auto result = fit_duhem(request.input, request.output, options);
  return {std::make_unique<ModelAdapter<DuhemCodec>>(result.model, result.initial_state),
          std::move(result.report)};
}

}  // namespace

ModelEntry duhem_entry() {
  ModelEntry entry;
  entry.name = std::string(DuhemCodec::name);
  entry.description =
      "Duhem (Coleman-Hodgdon): y' = alpha|v'|(f(v) - y) + g(v) v'; RK4 in the input; Ceres fit";
  entry.parameters = {
      {"alpha", "number", "1 / input units", "> 0"},
      {"f_slope", "number", "output / input units", "linear part of f, >= 0"},
      {"f_sat", "number", "output units", "saturating part of f, >= 0"},
      {"v_sat", "number", "input units", "saturation scale, > 0"},
      {"g_peak", "number", "output / input units", "peak of g above f_slope, <= f_sat / v_sat"},
      {"substeps", "whole number", "", "minimum RK4 steps per sample (20)"},
      {"max_input_step", "number", "input units", "largest RK4 step, 0 = automatic: 1 / alpha (0)"},
      {"tolerance", "number", "", "> 0: adaptive Dormand-Prince with this error tolerance (0)"},
  };
  entry.fit_options = {
      {"substeps", "whole number", "", "RK4 steps per sample (20)"},
      {"max_iterations", "whole number", "", "Levenberg-Marquardt iterations (100)"},
      {"global_evaluations", "whole number", "",
       "cost evaluations of the global search before the local starts, 0 = none (300)"},
  };
  entry.create = &create_from_json<DuhemCodec>;
  entry.fit = &fit_duhem_request;
  entry.example_params = {
      {"alpha", 1.0}, {"f_slope", 0.5}, {"f_sat", 1.0}, {"v_sat", 1.0}, {"g_peak", 0.5}};
  return entry;
}

}  // namespace hyst::detail
