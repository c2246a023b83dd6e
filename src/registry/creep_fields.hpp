#pragma once
// The model-file form the PI models with creep share (pi_creep, modified_pi_creep): the fields of
// the PI with creep, its state and the table of its weights in a description.

#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "field_table.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"
#include "model_adapter.hpp"

namespace hyst::detail {

// The fields of PrandtlIshlinskiiCreep::Params; its offset is `offset_name` in the file.
inline FieldTable<PrandtlIshlinskiiCreep::Params> pi_creep_fields(
    std::string_view offset_name, std::string_view offset_description) {
  using P = PrandtlIshlinskiiCreep::Params;
  return FieldTable<P>()
      .add("thresholds", &P::thresholds, "input units", "play half-widths 0 = r_0 < r_1 < ...")
      .add("weights", &P::weights, "output / input units", "p_j, one per threshold")
      .add("time_constants", &P::time_constants, "s", "creep lags tau_i > 0, increasing")
      .add("creep_weights", &P::creep_weights, "output / input units",
           "c_ij >= 0, row-major: one row of one weight per threshold for each time constant")
      .add("sample_time", &P::sample_time, "s", "Ts > 0 of the input samples")
      .add(offset_name, &P::offset, "output units", offset_description, Presence::optional);
}

// The fit options of the creep structure: lags, time constants, sample time and initial state.
template <class O>
FieldTable<O> add_creep_fit_options(FieldTable<O> table) {
  return table.add("lags", &O::lags, "", "number of creep lags when time_constants are not given")
      .add("time_constants", &O::time_constants, "s",
           "fixed creep time constants (default: log-spaced from 10 Ts to the record's length)")
      .add("sample_time", &O::sample_time, "s", "Ts of the record")
      .add("initial_state", &O::initial_state, pi_initial_state_from_string,
           "virgin (plays and lags at 0) or periodic (the record is one period in steady state)");
}

// {"play": [...], "creep": [...]}
inline nlohmann::json creep_state_to_json(const PrandtlIshlinskiiCreep::State& state) {
  return {{"play", state.play}, {"creep", state.creep}};
}

// The inverse's state: the forward model's (the inverse plays follow from it).
inline nlohmann::json creep_inverse_state_to_json(
    const InversePrandtlIshlinskiiCreep::State& state) {
  return creep_state_to_json(state.model);
}

// The state of `model` (any model whose make_state takes the plays and the lags), validated by it.
template <class Model>
typename Model::State creep_state_from_json(const Model& model, JsonFields& fields) {
  auto play = fields.numbers("play");
  auto creep = fields.numbers("creep");
  return state_at(fields, [&] { return model.make_state(std::move(play), std::move(creep)); });
}

// One row per play: threshold, weight and its creep weights; then the time constants.
inline std::string describe_plays_and_lags(const PrandtlIshlinskiiCreep& model) {
  const auto& p = model.params();
  std::string text = "   j   threshold r_j      weight p_j   creep weights c_ij (one per lag)\n";
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

}  // namespace hyst::detail
