// Registry entry of the Bouc-Wen model: its model-file form, its numerical inverse and its fitter.

#include <string>

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "c_code_capability.hpp"
#include "hyst/identify/fit_bouc_wen.hpp"
#include "hyst/models/bouc_wen.hpp"
#include "model_entries.hpp"
#include "monotone_inverse_codec.hpp"

namespace hyst::detail {
namespace {

struct BoucWenCodec : CodecOf<BoucWen, "bouc_wen"> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("a", &P::a, "-", "A > 0", Presence::optional)
        .add("beta", &P::beta, "", "beta - gamma >= 0 and beta + gamma > 0")
        .add("gamma", &P::gamma, "", "see beta")
        .add("n", &P::n, "-", "exponent >= 1", Presence::optional)
        .add("stiffness", &P::stiffness, "output / input units", "k > 0", Presence::optional)
        .add("alpha_k", &P::alpha_k, "-", "share of the linear spring in [0, 1]",
             Presence::optional)
        .add("substeps", &P::substeps, "", "minimum RK4 steps per sample", Presence::optional)
        .add("max_input_step", &P::max_input_step, "input units", "largest RK4 step, 0 = none",
             Presence::optional)
        .add("tolerance", &P::tolerance, "",
             "n != 1, > 0: adaptive Dormand-Prince with this tolerance", Presence::optional);
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"input", state.input}, {"z", state.hysteretic}};
  }
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    const double input = fields.number("input");
    const double z = fields.number("z");
    return model.make_state(input, z);
  }
  static std::size_t parameter_count(const Model&) { return 5; }  // rho, sigma, n, kx, kw
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    const auto w = model.normalised();
    return fmt::format(
        "Bouc-Wen model: A = {}, beta = {}, gamma = {}, n = {}, k = {}, alpha_k = {}\n"
        "  normalised: rho = {:.8g}, sigma = {:.8g}, kx = {:.8g}, kw = {:.8g}; |z| <= z0 = {:.8g}\n"
        "  integration: {}\n",
        p.a, p.beta, p.gamma, p.n, p.stiffness, p.alpha_k, w.rho, w.sigma, w.kx, w.kw,
        model.z_bound(),
        p.n == 1.0 ? std::string("exact solution per sample (n = 1)")
        : p.tolerance > 0.0
            ? fmt::format("adaptive Dormand-Prince in the input, tolerance {}", p.tolerance)
            : fmt::format("RK4 in the input, {} sub-steps per sample, max input step {}",
                          p.substeps, p.max_input_step));
  }
  static bool has_inverse(const Model&) { return true; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    return make_monotone_inverse<BoucWenCodec>(model, state, limits, state.input);
  }
};

FieldTable<BoucWenFitOptions> bouc_wen_fit_option_table() {
  using O = BoucWenFitOptions;
  return add_multistart_options(
      FieldTable<O>(Presence::optional)
          .add("fit_n", &O::fit_n, "", "also fit the exponent n (false: n = 1)")
          .add("substeps", &O::substeps, "", "RK4 steps per sample"));
}

}  // namespace

ModelEntry bouc_wen_entry() {
  auto entry = entry_of<BoucWenCodec>(
      "Bouc-Wen: F = alpha_k k x + (1 - alpha_k) k z, bounded class; RK4 in the input; Ceres fit");
  set_fitter<BoucWenCodec>(entry, bouc_wen_fit_option_table(), &fit_bouc_wen);
  entry.example_params = {{"a", 1.0}, {"beta", 0.6},      {"gamma", 0.2},
                          {"n", 1.5}, {"stiffness", 1.0}, {"alpha_k", 0.3}};
  entry.c_code = c_code_of<BoucWenCodec>();
  entry.actuator_force = actuator_force_of<BoucWenCodec>();
  return entry;
}

}  // namespace hyst::detail
