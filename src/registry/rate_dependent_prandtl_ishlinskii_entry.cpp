// Registry entry of the rate-dependent Prandtl-Ishlinskii model: its model-file form and its
// weight fit (fixed thresholds and rate gain). No inverse.

#include <fmt/format.h>

#include "hyst/identify/fit_rate_dependent_prandtl_ishlinskii.hpp"
#include "hyst/models/rate_dependent_prandtl_ishlinskii.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

struct RateDependentPiCodec {
  using Model = RateDependentPrandtlIshlinskii;
  static constexpr std::string_view name = "rate_dependent_pi";

  static nlohmann::json params_to_json(const Model& model) {
    const auto& p = model.params();
    return {{"thresholds", p.thresholds},   {"weights", p.weights},
            {"rate_gain", p.rate_gain},     {"sample_time", p.sample_time},
            {"rate_filter", p.rate_filter}, {"offset", p.offset}};
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"play", state.play}, {"input", state.input}, {"rate", state.rate}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    auto play = fields.numbers("play");
    const double input = fields.number("input");
    const double rate = fields.number("rate");
    return state_at(fields, [&] { return model.make_state(std::move(play), input, rate); });
  }
  static std::size_t parameter_count(const Model& model) { return model.size() + 2; }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    std::string text = fmt::format(
        "Rate-dependent Prandtl-Ishlinskii model: {} play operators, thresholds r_j + {} |dv/dt| "
        "(j >= 1), sample time {} s, rate filter {} s, offset {}\n"
        "   j   threshold r_j      weight p_j\n",
        model.size(), p.rate_gain, p.sample_time, p.rate_filter, p.offset);
    for (std::size_t j = 0; j < model.size(); ++j)
      text += fmt::format("{:4}  {:14.8g}  {:14.8g}\n", j, p.thresholds[j], p.weights[j]);
    return text;
  }
  static bool has_inverse(const Model&) { return false; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model&, const Model::State&,
                                                      const InverseLimits&) {
    throw Error("the rate-dependent PI model has no inverse in hyst");
  }
};

std::unique_ptr<DynamicModel> create_rate_dependent_prandtl_ishlinskii(
    const nlohmann::json& params_json, const nlohmann::json* state_json) {
  JsonFields fields(params_json, "params");
  RateDependentPrandtlIshlinskii::Params params;
  params.thresholds = fields.numbers("thresholds");
  params.weights = fields.numbers("weights");
  params.rate_gain = fields.number("rate_gain");
  params.sample_time = fields.number("sample_time");
  params.rate_filter = fields.number_or("rate_filter", 0.0);
  params.offset = fields.number_or("offset", 0.0);
  fields.finish();
  return make_dynamic_model<RateDependentPiCodec>(std::move(params), state_json);
}

FitOutcome fit_rate_dependent_prandtl_ishlinskii_request(const FitRequest& request) {
  JsonFields fields(request.options, "fit options");
  RateDependentPiFitOptions options;
  options.operators = fields.count_or("operators", options.operators);
  if (fields.has("thresholds")) options.thresholds = fields.numbers("thresholds");
  options.rate_gain = fields.number_or("rate_gain", options.rate_gain);
  options.sample_time = fields.number_or("sample_time", options.sample_time);
  options.rate_filter = fields.number_or("rate_filter", options.rate_filter);
  options.fit_offset = fields.boolean_or("fit_offset", options.fit_offset);
  options.min_linear_weight = fields.number_or("min_linear_weight", options.min_linear_weight);
  fields.finish();
  options.validate_fraction = request.validate_fraction;
  auto result = fit_rate_dependent_prandtl_ishlinskii(request.input, request.output, options);
  auto initial = result.model.initial_state();
  return {std::make_unique<ModelAdapter<RateDependentPiCodec>>(std::move(result.model),
                                                               std::move(initial)),
          std::move(result.report)};
}

}  // namespace

ModelEntry rate_dependent_prandtl_ishlinskii_entry() {
  ModelEntry entry;
  entry.name = std::string(RateDependentPiCodec::name);
  entry.description =
      "rate-dependent PI: play thresholds r_j + beta |dv/dt|, loops widen with frequency; "
      "weights by NNLS for a fixed beta";
  entry.parameters = {
      {"thresholds", "array of numbers", "input units",
       "nominal (zero-rate) half-widths 0 = r_0 < r_1 < ..."},
      {"weights", "array of numbers", "output / input units", "p_j, one per threshold"},
      {"rate_gain", "number", "s", "beta >= 0: threshold increase per unit |dv/dt|"},
      {"sample_time", "number", "s", "Ts > 0 of the input samples"},
      {"rate_filter", "number", "s", "time constant >= 0 of the rate low-pass (default 0)"},
      {"offset", "number", "output units", "y_off (default 0)"},
  };
  entry.fit_options = {
      {"operators", "whole number", "", "number of plays when thresholds are not given (10)"},
      {"thresholds", "array of numbers", "input units", "fixed nominal thresholds (uniform)"},
      {"rate_gain", "number", "s", "fixed beta >= 0 (0: the classical PI)"},
      {"sample_time", "number", "s", "Ts of the record (1)"},
      {"rate_filter", "number", "s", "rate low-pass time constant (0)"},
      {"fit_offset", "boolean", "", "fit the output offset (true)"},
      {"min_linear_weight", "number", "", "lower bound of p_0, keeps p_0 > 0"},
  };
  entry.create = &create_rate_dependent_prandtl_ishlinskii;
  entry.fit = &fit_rate_dependent_prandtl_ishlinskii_request;
  entry.example_params = {{"thresholds", {0.0, 0.2, 0.4, 0.6}},
                          {"weights", {1.0, 0.6, 0.4, 0.2}},
                          {"rate_gain", 0.002},
                          {"sample_time", 1e-3},
                          {"rate_filter", 0.0},
                          {"offset", 0.0}};
  return entry;
}

}  // namespace hyst::detail
