// Registry entry of the backlash-like model (Su et al. 2000): model-file form, numerical inverse,
// fitter.

#include <fmt/format.h>

#include "hyst/identify/fit_duhem.hpp"
#include "hyst/models/backlash_like.hpp"
#include "model_entries.hpp"
#include "monotone_inverse_codec.hpp"

namespace hyst::detail {
namespace {

struct BacklashLikeCodec : CodecOf<BacklashLike, "backlash_like"> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("a", &P::a, "1 / input units", "rate of approach to the branches, > 0")
        .add("c", &P::c, "output / input units", "slope of the branches, > 0")
        .add("b1", &P::b1, "output / input units", "B1 < c; monotone (invertible) iff B1 >= c/2");
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"input", state.input}, {"output", state.output}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    const double input = fields.number("input");
    const double output = fields.number("output");
    return model.state_at(input, output);
  }
  static std::size_t parameter_count(const Model&) { return 3; }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "backlash-like model (Su et al. 2000): a = {}, c = {}, B1 = {}; {}monotone "
        "(B1 >= c/2); exact steps for input linear between samples\n",
        p.a, p.c, p.b1, model.is_monotone() ? "" : "not ");
  }
  static bool has_inverse(const Model& model) { return model.is_monotone(); }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    return make_monotone_inverse<BacklashLikeCodec>(model, state, limits, state.input);
  }
};

FieldTable<DuhemFitOptions> backlash_like_fit_option_table() {
  using O = DuhemFitOptions;
  return add_multistart_options(FieldTable<O>(Presence::optional));
}

}  // namespace

ModelEntry backlash_like_entry() {
  auto entry = entry_of<BacklashLikeCodec>(
      "backlash-like (Su et al. 2000): w' = a|v'|(c v - w) + B1 v'; exact steps");
  set_fitter<BacklashLikeCodec>(entry, backlash_like_fit_option_table(), &fit_backlash_like);
  entry.example_params = {{"a", 1.0}, {"c", 1.0}, {"b1", 0.6}};
  return entry;
}

}  // namespace hyst::detail
