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

// Outputs are normalised by y_scale, which the fitter sets from the fit record; a free run a
// thousand scales away from it has left anything the model describes.
constexpr double kRunawayScales = 1e3;

struct NarxCodec : CodecOf<Narx, "narx"> {
  static constexpr TimeDependence time_dependence = TimeDependence::discrete;
  static std::optional<double> sample_time(const Model& model) {
    const double seconds = model.params().sample_time;
    return seconds > 0.0 ? std::optional<double>(seconds) : std::nullopt;
  }
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("input_lags", &P::input_lags, "", "n_u: past inputs v[k-1..k-n_u] (v[k] always used)")
        .add("output_lags", &P::output_lags, "", "n_y: past outputs y[k-1..k-n_y]")
        .add("play_thresholds", &P::play_thresholds, "input units", "r_i > 0, increasing")
        .add("hidden_sizes", &P::hidden_sizes, "", "one or two tanh hidden layers")
        .add("weights", &P::weights, "",
             "per hidden layer W (row-major) then b; output weights, constant, linear weights")
        .add("input_offset", &P::input_offset, "input units", "normalisation v_off",
             Presence::optional)
        .add("input_scale", &P::input_scale, "input units", "normalisation v_scale > 0",
             Presence::optional)
        .add("output_offset", &P::output_offset, "output units", "normalisation y_off",
             Presence::optional)
        .add("output_scale", &P::output_scale, "output units", "normalisation y_scale > 0",
             Presence::optional)
        .add("sample_time", &P::sample_time, "s",
             "Ts of the samples the lags count; 0: not stated (any record is run sample by "
             "sample)",
             Presence::optional);
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

FieldTable<NarxFitOptions> narx_fit_option_table() {
  using O = NarxFitOptions;
  return FieldTable<O>(Presence::optional)
      .add("input_lags", &O::input_lags, "", "n_u")
      .add("output_lags", &O::output_lags, "", "n_y")
      .add("plays", &O::plays, "", "plays when thresholds are not given")
      .add("play_thresholds", &O::play_thresholds, "input units",
           "fixed play thresholds (default: spread over half the input range)")
      .add("hidden_sizes", &O::hidden_sizes, "", "hidden layer sizes")
      .add("seed", &O::seed, "", "seed of the initial weights")
      .add("starts", &O::starts, "", "initialisations trained (seed, seed + 1, ...)")
      .add("max_iterations", &O::max_iterations, "", "Levenberg-Marquardt iterations")
      .add("simulation_iterations", &O::simulation_iterations, "",
           "LM iterations on the free-run error after the one-step fit")
      .add("patience", &O::patience, "", "early stopping: iterations without improvement")
      .add("early_stopping_fraction", &O::early_stopping_fraction, "",
           "end of the fit part monitored in free run")
      .add("regularization", &O::regularization, "", "ridge weight on the network weights")
      .add("sample_time", &O::sample_time, "s",
           "Ts of the record, stored in the model (0: not stated)");
}

}  // namespace

ModelEntry narx_entry() {
  auto entry = entry_of<NarxCodec>(
      "NARX: tanh network on past inputs, past outputs and play operators (black box); LM fit");
  set_fitter<NarxCodec>(entry, narx_fit_option_table(),
                        [](auto input, auto output, const auto& options) {
                          return fit_narx(input, output, options);
                        });
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
