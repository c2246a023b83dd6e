// Registry entry of the Prandtl-Ishlinskii model: its model-file form, its inverse and its fitter.

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "c_code_capability.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"
#include "pi_batch_inverse.hpp"
#include "play_state_json.hpp"

namespace hyst::detail {
namespace {

// Plays from which the batch inverse (O(log m) per sample, with a stack of segments) is faster
// than the library's step inverse (O(m), one min and max per play): 9.3 against 15.5 ns per
// sample at 16 plays, 15.8 against 18.0 at 32, 34 against 21 at 64 (bench_prandtl_ishlinskii,
// BM_InversePiInvert and BM_RegistryPiInvert, docs/performance.md).
constexpr std::size_t kPiBatchInverseMinOperators = 40;

// The inverse PI of `hyst invert` and Python: the step inverse for few plays, batches in
// O(log m) per sample (pi_batch_inverse.hpp) for many.
class PiInverseAdapter final : public DynamicInverse {
 public:
  PiInverseAdapter(InversePrandtlIshlinskii inverse, PrandtlIshlinskii::State state)
      : inverse_(std::move(inverse)), state_(std::move(state)) {}
  InverseReport invert(std::span<const double> targets, std::span<double> inputs) override {
    if (inverse_.forward().size() < kPiBatchInverseMinOperators)
      return hyst::invert(inverse_, state_, targets, inputs);
    return invert_pi_batch(inverse_, state_, targets, inputs, workspace_);
  }
  nlohmann::json state() const override { return play_state_to_json(state_); }
  std::unique_ptr<DynamicInverse> clone() const override {
    return std::make_unique<PiInverseAdapter>(*this);
  }

 private:
  InversePrandtlIshlinskii inverse_;
  PrandtlIshlinskii::State state_;
  PiBatchWorkspace workspace_;
};

struct PrandtlIshlinskiiCodec : CodecOf<PrandtlIshlinskii, "pi"> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("thresholds", &P::thresholds, "input units",
             "play half-widths r_j: 0 = r_0 < r_1 < ... (r_0 = 0 is the linear term)")
        .add("weights", &P::weights, "output / input units",
             "p_j, one per threshold; invertible iff p_0 > 0 and all partial sums > 0")
        .add("offset", &P::offset, "output units", "y_off added to the output", Presence::optional);
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return play_state_to_json(state);
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    return play_state_from_json(model, fields);
  }
  static std::size_t parameter_count(const Model& model) {
    return model.size() + 1;  // the weights and the offset; the thresholds are chosen, not fitted
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    std::string text =
        fmt::format("Prandtl-Ishlinskii model: {} play operators, offset {}, {}invertible\n",
                    model.size(), p.offset, model.is_invertible() ? "" : "not ");
    text += "   j   threshold r_j      weight p_j\n";
    for (std::size_t j = 0; j < model.size(); ++j) {
      text += fmt::format("{:4}  {:14.8g}  {:14.8g}\n", j, p.thresholds[j], p.weights[j]);
    }
    return text;
  }
  static bool has_inverse(const Model& model) { return model.is_invertible(); }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    InversePrandtlIshlinskii inverse(model, {limits.input_min, limits.input_max});
    auto inverse_state = inverse.state_consistent_with(state);
    return std::make_unique<PiInverseAdapter>(std::move(inverse), std::move(inverse_state));
  }
};

using PrandtlIshlinskiiAdapter = ModelAdapter<PrandtlIshlinskiiCodec>;

FieldTable<PiFitOptions> prandtl_ishlinskii_fit_option_table() {
  using O = PiFitOptions;
  return add_play_weight_options(FieldTable<O>(Presence::optional))
      .add("initial_state", &O::initial_state, pi_initial_state_from_string,
           "virgin (plays at 0) or periodic (one period run first)");
}

}  // namespace

ModelEntry prandtl_ishlinskii_entry() {
  auto entry = entry_of<PrandtlIshlinskiiCodec>(
      "Prandtl-Ishlinskii: weighted sum of play operators; analytic inverse; weights by NNLS");
  set_fitter<PrandtlIshlinskiiCodec>(entry, prandtl_ishlinskii_fit_option_table(),
                                     [](auto input, auto output, const auto& options) {
                                       return fit_prandtl_ishlinskii(input, output, options);
                                     });
  entry.example_params = {
      {"thresholds", {0.0, 0.3, 0.7, 1.0}}, {"weights", {0.8, 0.5, 0.3, 0.2}}, {"offset", 0.0}};
  entry.c_code = c_code_of<PrandtlIshlinskiiCodec>();
  entry.actuator_force = actuator_force_of<PrandtlIshlinskiiCodec>();
  return entry;
}

}  // namespace hyst::detail
