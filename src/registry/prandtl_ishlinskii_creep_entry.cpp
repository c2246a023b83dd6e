// Registry entry of the PI model with creep: its model-file form, its exact inverse and its
// joint NNLS fit of hysteresis and creep weights.

#include <fmt/format.h>

#include "c_code_capability.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii_creep.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

nlohmann::json creep_state_to_json(const PrandtlIshlinskiiCreep::State& state) {
  return {{"play", state.play}, {"creep", state.creep}};
}

nlohmann::json creep_inverse_state_to_json(const InversePrandtlIshlinskiiCreep::State& state) {
  return creep_state_to_json(state.model);
}

struct PiCreepCodec : CodecOf<PrandtlIshlinskiiCreep, "pi_creep"> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("thresholds", &P::thresholds, "input units", "play half-widths 0 = r_0 < r_1 < ...")
        .add("weights", &P::weights, "output / input units", "p_j, one per threshold")
        .add("time_constants", &P::time_constants, "s", "creep lags tau_i > 0, increasing")
        .add("creep_weights", &P::creep_weights, "output / input units",
             "c_ij >= 0, row-major: one row of one weight per threshold for each time constant")
        .add("sample_time", &P::sample_time, "s", "Ts > 0 of the input samples")
        .add("offset", &P::offset, "output units", "y_off", Presence::optional);
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return creep_state_to_json(state);
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    auto play = fields.numbers("play");
    auto creep = fields.numbers("creep");
    return state_at(fields, [&] { return model.make_state(std::move(play), std::move(creep)); });
  }
  static std::size_t parameter_count(const Model& model) {
    return model.size() * (1 + model.lags()) + 1;
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    std::string text = fmt::format(
        "Prandtl-Ishlinskii model with creep: {} play operators, {} creep lags, sample time {} s, "
        "offset {}\n   j   threshold r_j      weight p_j   creep weights c_ij (one per lag)\n",
        model.size(), model.lags(), p.sample_time, p.offset);
    for (std::size_t j = 0; j < model.size(); ++j) {
      text += fmt::format("{:4}  {:14.8g}  {:14.8g}", j, p.thresholds[j], p.weights[j]);
      for (std::size_t i = 0; i < model.lags(); ++i)
        text += fmt::format("  {:12.6g}", p.creep_weights[i * model.size() + j]);
      text += '\n';
    }
    text += "  time constants tau_i [s]:";
    for (double tau : p.time_constants)
      text += fmt::format(" {:.6g}", tau);
    return text + '\n';
  }
  static bool has_inverse(const Model& model) {
    return PrandtlIshlinskii({model.params().thresholds, model.instantaneous_weights(), 0.0})
        .is_invertible();
  }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    InversePrandtlIshlinskiiCreep inverse(model, {limits.input_min, limits.input_max});
    auto inverse_state = inverse.state_consistent_with(state);
    return std::make_unique<
        InverseAdapter<InversePrandtlIshlinskiiCreep, decltype(&creep_inverse_state_to_json)>>(
        std::move(inverse), std::move(inverse_state), &creep_inverse_state_to_json);
  }
};

FieldTable<PiCreepFitOptions> prandtl_ishlinskii_creep_fit_option_table() {
  using O = PiCreepFitOptions;
  return add_play_weight_options(FieldTable<O>(Presence::optional))
      .add("lags", &O::lags, "", "number of creep lags when time_constants are not given")
      .add("time_constants", &O::time_constants, "s",
           "fixed creep time constants (default: log-spaced from 10 Ts to the record's length)")
      .add("sample_time", &O::sample_time, "s", "Ts of the record")
      .add("initial_state", &O::initial_state, pi_initial_state_from_string,
           "virgin (plays and lags at 0) or periodic (the record is one period in steady state)");
}

PiCreepFit fit_one_record(std::span<const double> input, std::span<const double> output,
                          const PiCreepFitOptions& options) {
  return fit_prandtl_ishlinskii_creep(input, output, options);
}

}  // namespace

ModelEntry prandtl_ishlinskii_creep_entry() {
  auto entry = entry_of<PiCreepCodec>(
      "PI with Kuhnen creep: plays driving first-order lags (exactly discretised), hysteresis and "
      "creep weights by one NNLS; exact inverse");
  set_fitter<PiCreepCodec>(entry, prandtl_ishlinskii_creep_fit_option_table(), &fit_one_record);
  entry.c_code = c_code_of<PiCreepCodec>();
  entry.example_params = {{"thresholds", {0.0, 0.25, 0.5}},
                          {"weights", {1.0, 0.5, 0.25}},
                          {"time_constants", {0.01, 0.1}},
                          {"creep_weights", {0.1, 0.05, 0.02, 0.05, 0.02, 0.01}},
                          {"sample_time", 1e-3},
                          {"offset", 0.0}};
  return entry;
}

}  // namespace hyst::detail
