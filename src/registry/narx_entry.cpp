// Registry entry of the neural NARX model with play-operator regressors: its model-file form and
// its fitter (no inverse: a black-box network has no analytic one).

#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hyst/identify/fit_narx.hpp"
#include "hyst/models/narx.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

// An array of whole numbers >= 1 (layer sizes).
std::vector<std::size_t> sizes(JsonFields& fields, std::string_view key) {
  const auto values = fields.numbers(key);
  std::vector<std::size_t> result;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!(values[i] >= 1.0 && values[i] <= 1e6 && std::floor(values[i]) == values[i])) {
      throw Error(fmt::format("{}[{}] = {}: expected a whole number >= 1", fields.path_of(key), i,
                              values[i]));
    }
    result.push_back(static_cast<std::size_t>(values[i]));
  }
  return result;
}

// Outputs are normalised by y_scale, which the fitter sets from the fit record; a free run a
// thousand scales away from it has left anything the model describes.
constexpr double kRunawayScales = 1e3;

struct NarxCodec {
  using Model = Narx;
  static constexpr std::string_view name = "narx";

  static nlohmann::json params_to_json(const Model& model) {
    const auto& p = model.params();
    return {{"input_lags", p.input_lags},
            {"output_lags", p.output_lags},
            {"play_thresholds", p.play_thresholds},
            {"hidden_sizes", p.hidden_sizes},
            {"weights", p.weights},
            {"input_offset", p.input_offset},
            {"input_scale", p.input_scale},
            {"output_offset", p.output_offset},
            {"output_scale", p.output_scale}};
  }
  static Model::Params params_from_json(JsonFields& fields) {
    Model::Params p;
    p.input_lags = fields.count("input_lags");
    p.output_lags = fields.count("output_lags");
    p.play_thresholds = fields.numbers("play_thresholds");
    p.hidden_sizes = sizes(fields, "hidden_sizes");
    p.weights = fields.numbers("weights");
    p.input_offset = fields.number_or("input_offset", 0.0);
    p.input_scale = fields.number_or("input_scale", 1.0);
    p.output_offset = fields.number_or("output_offset", 0.0);
    p.output_scale = fields.number_or("output_scale", 1.0);
    return p;
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"past_inputs", state.past_inputs},
            {"past_outputs", state.past_outputs},
            {"play", state.play}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    auto past_inputs = fields.numbers("past_inputs");
    auto past_outputs = fields.numbers("past_outputs");
    auto play = fields.numbers("play");
    return state_at(fields, [&] {
      return model.make_state(std::move(past_inputs), std::move(past_outputs), std::move(play));
    });
  }
  static std::size_t parameter_count(const Model& model) { return model.params().weights.size(); }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "NARX model: {} regressors (v[k], {} past inputs, {} past outputs, {} plays), hidden "
        "layers [{}] (tanh) plus a linear term, {} weights\n"
        "   play thresholds: [{}]\n"
        "   normalisation: input (v - {:.6g}) / {:.6g}, output (y - {:.6g}) / {:.6g}\n",
        model.regressor_count(), p.input_lags, p.output_lags, p.play_thresholds.size(),
        fmt::join(p.hidden_sizes, ", "), p.weights.size(), fmt::join(p.play_thresholds, ", "),
        p.input_offset, p.input_scale, p.output_offset, p.output_scale);
  }
  // The tanh layers are bounded, but the linear output lags can feed back unstably.
  static double runaway_limit(const Model& model) {
    return std::abs(model.params().output_offset) + kRunawayScales * model.params().output_scale;
  }
  static std::string runaway_explanation(const Model& model) {
    return fmt::format("{:g} output scales y_scale = {:g} from the output offset {:g}",
                       kRunawayScales, model.params().output_scale, model.params().output_offset);
  }
  static bool has_inverse(const Model&) { return false; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model&, const Model::State&,
                                                      const InverseLimits&) {
    throw Error(
        "the NARX model has no inverse (a black-box network); invert it numerically "
        "through a compensator loop instead");
  }
};

using NarxAdapter = ModelAdapter<NarxCodec>;

NarxFitOptions narx_fit_options(const FitRequest& request) {
  JsonFields fields(request.options, "fit options");
  NarxFitOptions options;
  options.input_lags = fields.count_or("input_lags", options.input_lags);
  options.output_lags = fields.count_or("output_lags", options.output_lags);
  options.plays = fields.count_or("plays", options.plays);
  if (fields.has("play_thresholds")) options.play_thresholds = fields.numbers("play_thresholds");
  if (fields.has("hidden_sizes")) options.hidden_sizes = sizes(fields, "hidden_sizes");
  options.seed = fields.count_or("seed", options.seed);
  options.max_iterations = fields.count_or("max_iterations", options.max_iterations);
  options.simulation_iterations =
      fields.count_or("simulation_iterations", options.simulation_iterations);
  options.patience = fields.count_or("patience", options.patience);
  options.early_stopping_fraction =
      fields.number_or("early_stopping_fraction", options.early_stopping_fraction);
  options.regularization = fields.number_or("regularization", options.regularization);
  fields.finish();
  options.validate_fraction = request.validate_fraction;
  return options;
}

FitOutcome fit_narx_request(const FitRequest& request) {
  const auto options = narx_fit_options(request);
  auto result = fit_narx(request.input, request.output, options);
  return {std::make_unique<NarxAdapter>(result.model, result.initial_state),
          std::move(result.report)};
}

}  // namespace

ModelEntry narx_entry() {
  ModelEntry entry;
  entry.name = std::string(NarxCodec::name);
  entry.description =
      "NARX: tanh network on past inputs, past outputs and play operators (black box); LM fit";
  entry.parameters = {
      {"input_lags", "whole number", "", "n_u: past inputs v[k-1..k-n_u] (v[k] always used)"},
      {"output_lags", "whole number", "", "n_y: past outputs y[k-1..k-n_y]"},
      {"play_thresholds", "array of numbers", "input units", "r_i > 0, increasing"},
      {"hidden_sizes", "array of whole numbers", "", "one or two tanh hidden layers"},
      {"weights", "array of numbers", "",
       "per hidden layer W (row-major) then b; output weights, constant, linear weights"},
      {"input_offset", "number", "input units", "normalisation v_off (default 0)"},
      {"input_scale", "number", "input units", "normalisation v_scale > 0 (default 1)"},
      {"output_offset", "number", "output units", "normalisation y_off (default 0)"},
      {"output_scale", "number", "output units", "normalisation y_scale > 0 (default 1)"},
  };
  entry.fit_options = {
      {"input_lags", "whole number", "", "n_u (2)"},
      {"output_lags", "whole number", "", "n_y (2)"},
      {"plays", "whole number", "", "plays when thresholds are not given (4)"},
      {"play_thresholds", "array of numbers", "input units", "fixed play thresholds"},
      {"hidden_sizes", "array of whole numbers", "", "hidden layer sizes ([8])"},
      {"seed", "whole number", "", "seed of the initial weights (1)"},
      {"max_iterations", "whole number", "", "Levenberg-Marquardt iterations (100)"},
      {"simulation_iterations", "whole number", "",
       "LM iterations on the free-run error after the one-step fit (100)"},
      {"patience", "whole number", "", "early stopping: iterations without improvement (15)"},
      {"early_stopping_fraction", "number", "", "end of the fit part monitored in free run (0.2)"},
      {"regularization", "number", "", "ridge weight on the network weights (1e-6)"},
  };
  entry.create = &create_from_json<NarxCodec>;
  entry.fit = &fit_narx_request;
  // 1 past input, 1 past output, 1 play, 2 neurons: 4 regressors, 2*4+2 + 2+1 + 4 = 17 weights.
  entry.example_params = {
      {"input_lags", 1},
      {"output_lags", 1},
      {"play_thresholds", {0.5}},
      {"hidden_sizes", {2}},
      {"weights",
       {0.5, 0.1, 0.0, 0.3, -0.2, 0.0, 0.1, 0.4, 0.0, 0.0, 0.3, -0.2, 0.0, 0.4, 0.0, 0.3, 0.2}},
      {"input_offset", 0.0},
      {"input_scale", 1.0},
      {"output_offset", 0.0},
      {"output_scale", 1.0}};
  return entry;
}

}  // namespace hyst::detail
