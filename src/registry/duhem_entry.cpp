// Registry entry of the Duhem (Coleman-Hodgdon) model: model-file form, numerical inverse, fitter.

#include <fmt/format.h>

#include "hyst/identify/fit_duhem.hpp"
#include "hyst/models/duhem.hpp"
#include "model_entries.hpp"
#include "monotone_inverse_codec.hpp"

namespace hyst::detail {
namespace {

struct DuhemCodec : CodecOf<Duhem, "duhem"> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("alpha", &P::alpha, "1 / input units", "> 0")
        .add("f_slope", &P::f_slope, "output / input units", "linear part of f, >= 0")
        .add("f_sat", &P::f_sat, "output units", "saturating part of f, >= 0")
        .add("v_sat", &P::v_sat, "input units", "saturation scale, > 0")
        .add("g_peak", &P::g_peak, "output / input units",
             "peak of g above f_slope, <= f_sat / v_sat")
        .add("substeps", &P::substeps, "", "minimum RK4 steps per sample", Presence::optional)
        .add("max_input_step", &P::max_input_step, "input units",
             "largest RK4 step, 0 = automatic: 1 / alpha", Presence::optional)
        .add("tolerance", &P::tolerance, "",
             "> 0: adaptive Dormand-Prince with this error tolerance", Presence::optional);
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

FieldTable<DuhemFitOptions> duhem_fit_option_table() {
  using O = DuhemFitOptions;
  return add_multistart_options(
      FieldTable<O>(Presence::optional).add("substeps", &O::substeps, "", "RK4 steps per sample"));
}

}  // namespace

ModelEntry duhem_entry() {
  auto entry = entry_of<DuhemCodec>(
      "Duhem (Coleman-Hodgdon): y' = alpha|v'|(f(v) - y) + g(v) v'; RK4 in the input; Ceres fit");
  set_fitter<DuhemCodec>(entry, duhem_fit_option_table(), &fit_duhem);
  entry.example_params = {
      {"alpha", 1.0}, {"f_slope", 0.5}, {"f_sat", 1.0}, {"v_sat", 1.0}, {"g_peak", 0.5}};
  return entry;
}

}  // namespace hyst::detail
