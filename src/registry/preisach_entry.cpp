// Registry entry of the discrete Preisach model (relay grid, fast Everett form): its model-file
// form, its numerical inverse and its NNLS fitter.

#include <cmath>

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "c_code_capability.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_preisach.hpp"
#include "hyst/inverse/inverse_preisach.hpp"
#include "hyst/models/preisach.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"
#include "preisach_state_json.hpp"

namespace hyst::detail {
namespace {

struct PreisachCodec : PreisachCodecCommon<Preisach, InversePreisach, "preisach"> {
  static FieldTable<P> parameters() {
    return preisach_parameter_table<P>(relay_grid_everett_table());
  }
  static std::size_t parameter_count(const Model& model) {
    return model.params().everett.weights.size() + 1;
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "Preisach model: {} levels on [{}, {}] ({} relays, {} layout), total weight F0 = {}, "
        "offset {}, output range [{}, {}], initial state {}\n",
        p.everett.levels, p.everett.lower, p.everett.upper, p.everett.weights.size(),
        to_string(p.everett.layout), model.total_weight(), p.offset, model.output_min(),
        model.output_max(), to_string(p.initial_state));
  }
};

using PreisachAdapter = ModelAdapter<PreisachCodec>;

FieldTable<PreisachWeightFitOptions> preisach_fit_option_table() {
  using O = PreisachWeightFitOptions;
  return add_grid_options(FieldTable<O>(Presence::optional), "N threshold levels")
      .add("layout", &O::layout, preisach_grid_layout_from_string, "cell_centred or endpoints")
      .add("initial_state", &O::initial_state, preisach_initial_state_from_string,
           "state the record starts from")
      .add("smoothness", &O::smoothness, "", "Tikhonov weight on neighbouring relay weights")
      .add("fit_offset", &O::fit_offset, "", "fit the output offset");
}

}  // namespace

ModelEntry preisach_entry() {
  auto entry = entry_of<PreisachCodec>(
      "Preisach: weighted relays on a triangular grid, fast Everett form (cost independent of "
      "the grid); numerical inverse; weights by NNLS");
  set_fitter<PreisachCodec>(entry, preisach_fit_option_table(), &fit_preisach_weights);
  // The unweighted 231-relay model of the seed paper (mu = 1 for every relay).
  entry.example_params = {{"levels", 21},
                          {"lower", -1.0},
                          {"upper", 1.0},
                          {"weights", std::vector<double>(231, 1.0)},
                          {"layout", "cell_centred"},
                          {"offset", 0.0},
                          {"initial_state", "negative_saturation"}};
  entry.c_code = c_code_of<PreisachCodec>();
  entry.actuator_force = actuator_force_of<PreisachCodec>();
  return entry;
}

}  // namespace hyst::detail
