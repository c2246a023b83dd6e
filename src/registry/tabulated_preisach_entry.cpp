// Registry entry of the Preisach model with a tabulated Everett function (everett_table.hpp), the
// model identified from first-order reversal curves (fit_preisach_forcs; 'hyst fit preisach
// --forc FILE' writes it): its model-file form and its numerical inverse. It has no fitter of
// input/output records (the relay grid 'preisach' has), no C export and is no actuator force.

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "hyst/inverse/inverse_preisach.hpp"
#include "hyst/models/preisach.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"
#include "preisach_state_json.hpp"
#include "tabulated_preisach_model.hpp"

namespace hyst::detail {
namespace {

struct TabulatedPreisachCodec
    : PreisachCodecCommon<TabulatedPreisach, InverseTabulatedPreisach, "tabulated_preisach"> {
  static FieldTable<P> parameters() {
    using E = TabulatedEverett::Params;
    const auto everett =
        FieldTable<E>()
            .add("levels", &E::levels, "input units",
                 "x_0 < x_1 < ... < x_K (K >= 1): the table's levels; inputs outside act as "
                 "saturation")
            .add("values", &E::values, "output units",
                 "E(x_a, x_c) for c < a, K(K+1)/2 values at index a(a-1)/2 + c; every cell weight "
                 "E[i+1,j] - E[i,j] - E[i+1,j+1] + E[i,j+1] >= 0");
    return preisach_parameter_table<P>(everett);
  }
  static std::size_t parameter_count(const Model& model) {
    return model.params().everett.values.size() + 1;
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "Preisach model with a tabulated Everett function: {} levels on [{}, {}] ({} values), "
        "total weight F0 = {}, offset {}, output range [{}, {}], initial state {}\n",
        p.everett.levels.size(), model.lower(), model.upper(), p.everett.values.size(),
        model.total_weight(), p.offset, model.output_min(), model.output_max(),
        to_string(p.initial_state));
  }
};

}  // namespace

std::unique_ptr<DynamicModel> tabulated_preisach_model(TabulatedPreisach model) {
  auto state = model.initial_state();
  return std::make_unique<ModelAdapter<TabulatedPreisachCodec>>(std::move(model), std::move(state));
}

ModelEntry tabulated_preisach_entry() {
  auto entry = entry_of<TabulatedPreisachCodec>(
      "Preisach with a tabulated Everett function (bilinear between levels): the model "
      "identified from FORCs by 'hyst fit preisach --forc FILE'; numerical inverse");
  // Four uniform cells over [-1, 1], each cell weight 0.1: E(x_a, x_c) = 0.1 (a-c)(a-c+1)/2,
  // total weight 1 (the output spans [-1, 1]).
  std::vector<double> values;
  for (int a = 1; a <= 4; ++a) {
    for (int c = 0; c < a; ++c)
      values.push_back(0.1 * (a - c) * (a - c + 1) / 2.0);
  }
  entry.example_params = {{"levels", {-1.0, -0.5, 0.0, 0.5, 1.0}},
                          {"values", values},
                          {"offset", 0.0},
                          {"initial_state", "negative_saturation"}};
  return entry;
}

}  // namespace hyst::detail
