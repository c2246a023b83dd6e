// Registry entry of the rate-dependent Prandtl-Ishlinskii model: its model-file form and its
// weight fit (fixed thresholds and rate gain). No inverse.

#include <fmt/format.h>

#include "hyst/identify/fit_rate_dependent_prandtl_ishlinskii.hpp"
#include "hyst/models/rate_dependent_prandtl_ishlinskii.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

struct RateDependentPiCodec : CodecOf<RateDependentPrandtlIshlinskii, "rate_dependent_pi">,
                              ContinuousTimeCodec<RateDependentPrandtlIshlinskii> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("thresholds", &P::thresholds, "input units",
             "nominal (zero-rate) half-widths 0 = r_0 < r_1 < ...")
        .add("weights", &P::weights, "output / input units", "p_j, one per threshold")
        .add("rate_gain", &P::rate_gain, "s", "beta >= 0: threshold increase per unit |dv/dt|")
        .add("sample_time", &P::sample_time, "s", "Ts > 0 of the input samples")
        .add("rate_filter", &P::rate_filter, "s", "time constant >= 0 of the rate low-pass",
             Presence::optional)
        .add("offset", &P::offset, "output units", "y_off", Presence::optional);
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

FieldTable<RateDependentPiFitOptions> rate_dependent_prandtl_ishlinskii_fit_option_table() {
  using O = RateDependentPiFitOptions;
  return add_play_weight_options(FieldTable<O>(Presence::optional))
      .add("rate_gain", &O::rate_gain, "s", "fixed beta >= 0 (0: the classical PI)")
      .add("sample_time", &O::sample_time, "s", "Ts of the record")
      .add("rate_filter", &O::rate_filter, "s", "rate low-pass time constant");
}

}  // namespace

ModelEntry rate_dependent_prandtl_ishlinskii_entry() {
  auto entry = entry_of<RateDependentPiCodec>(
      "rate-dependent PI: play thresholds r_j + beta |dv/dt|, loops widen with frequency; "
      "weights by NNLS for a fixed beta");
  set_fitter<RateDependentPiCodec>(entry, rate_dependent_prandtl_ishlinskii_fit_option_table(),
                                   &fit_rate_dependent_prandtl_ishlinskii);
  entry.example_params = {{"thresholds", {0.0, 0.2, 0.4, 0.6}},
                          {"weights", {1.0, 0.6, 0.4, 0.2}},
                          {"rate_gain", 0.002},
                          {"sample_time", 1e-3},
                          {"rate_filter", 0.0},
                          {"offset", 0.0}};
  return entry;
}

}  // namespace hyst::detail
