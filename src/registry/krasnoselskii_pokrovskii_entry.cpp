// Registry entry of the Krasnosel'skii-Pokrovskii model: its model-file form and its NNLS
// fitter. No inverse.

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "hyst/identify/fit_krasnoselskii_pokrovskii.hpp"
#include "hyst/models/krasnoselskii_pokrovskii.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

struct KpCodec : CodecOf<KrasnoselskiiPokrovskii, "kp"> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("levels", &P::levels, "", "N cells: N(N+1)/2 kernels")
        .add("lower", &P::lower, "input units", "lower end of the grid (all kernels -1 below)")
        .add("upper", &P::upper, "input units", "upper end of the grid (all kernels +1 above)")
        .add("weights", &P::weights, "output units",
             "mu >= 0 per kernel, kernel (i, j) at index i(i+1)/2 + j")
        .add("ramp_cells", &P::ramp_cells, "", "ramp width of the kernels in cells",
             Presence::optional)
        .add("offset", &P::offset, "output units", "y_off", Presence::optional);
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"kernels", state.kernels}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    auto kernels = fields.numbers("kernels");
    return state_at(fields, [&] { return model.make_state(std::move(kernels)); });
  }
  static std::size_t parameter_count(const Model& model) { return model.kernel_count() + 1; }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "Krasnosel'skii-Pokrovskii model: {} cells on [{}, {}] ({} kernels, ramp {} cells), "
        "total weight {}, offset {}\n",
        p.levels, p.lower, p.upper, model.kernel_count(), p.ramp_cells, model.total_weight(),
        p.offset);
  }
  static bool has_inverse(const Model&) { return false; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model&, const Model::State&,
                                                      const InverseLimits&) {
    throw Error("the KP model has no inverse in hyst (use the Preisach model's numerical one)");
  }
};

FieldTable<KpFitOptions> krasnoselskii_pokrovskii_fit_option_table() {
  using O = KpFitOptions;
  return add_grid_options(FieldTable<O>(Presence::optional), "N cells")
      .add("ramp_cells", &O::ramp_cells, "", "ramp width in cells")
      .add("fit_offset", &O::fit_offset, "", "fit the output offset");
}

}  // namespace

ModelEntry krasnoselskii_pokrovskii_entry() {
  auto entry = entry_of<KpCodec>(
      "Krasnosel'skii-Pokrovskii: ramped relays on a triangular grid, continuous output; weights "
      "by NNLS");
  set_fitter<KpCodec>(entry, krasnoselskii_pokrovskii_fit_option_table(),
                      &fit_krasnoselskii_pokrovskii);
  entry.example_params = {{"levels", 6},       {"lower", -1.0},
                          {"upper", 1.0},      {"weights", std::vector<double>(21, 1.0 / 21.0)},
                          {"ramp_cells", 1.0}, {"offset", 0.0}};
  entry.actuator_force = actuator_force_of<KpCodec>();
  return entry;
}

}  // namespace hyst::detail
