// Registry entry of the generalized Prandtl-Ishlinskii model (GPI): its model-file form, its
// inverse (IGPI) and its fitter. The envelope kind is a template parameter of the model; the
// entry picks the instantiation from the "envelope" field at load time.

#include <fmt/format.h>

#include "actuator_force_capability.hpp"
#include "c_code_capability.hpp"
#include "hyst/identify/fit_generalized_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_generalized_prandtl_ishlinskii.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"
#include "model_adapter.hpp"
#include "model_entries.hpp"

namespace hyst::detail {
namespace {

FieldTable<GpiParams> gpi_parameter_table() {
  using P = GpiParams;
  const auto exponential = [](const P& p) { return p.density == GpiDensity::exponential; };
  const auto free_density = [](const P& p) { return p.density == GpiDensity::free; };
  return FieldTable<P>()
      .add("envelope", &P::envelope, envelope_kind_from_string, "tanh, arctan or linear")
      .add("ascending", &P::ascending, "",
           "gamma_l coefficients a0..a3 (tanh/arctan: a0 f(a1 v + a2) + a3; linear: a0 v + a1)")
      .add("descending", &P::descending, "", "gamma_r coefficients b0..b3, gamma_l <= gamma_r")
      .add("density", &P::density, gpi_density_from_string,
           "exponential (rho, tau, alpha, m) or free (thresholds, weights)")
      .add("rho", &P::rho, "", "exponential density p_j = rho exp(-tau r_j), rho > 0")
      .only_if(exponential, "with the free density")
      .add("tau", &P::tau, "1 / envelope units", "decay of the density")
      .only_if(exponential, "with the free density")
      .add("alpha", &P::alpha, "envelope units", "threshold spacing r_j = alpha j, alpha > 0")
      .only_if(exponential, "with the free density")
      .add("m", &P::m, "", "operators j = 0..m")
      .only_if(exponential, "with the free density")
      .add("thresholds", &P::thresholds, "envelope units", "free density: 0 = r_0 < r_1 < ...")
      .only_if(free_density, "with the exponential density")
      .add("weights", &P::weights, "", "free density: p_j")
      .only_if(free_density, "with the exponential density")
      .add("input_min", &P::input_min, "input units", "operating range (ordering checked on it)")
      .add("input_max", &P::input_max, "input units", "operating range")
      .add("initial_input", &P::initial_input, "input units", "at rest there initially",
           Presence::optional);
}

template <class E>
struct GpiCodec {
  using Model = GeneralizedPrandtlIshlinskii<E>;
  using Inverse = InverseGeneralizedPrandtlIshlinskii<E>;
  static constexpr std::string_view name = "gpi";

  static FieldTable<GpiParams> parameters() { return gpi_parameter_table(); }
  static nlohmann::json state_to_json(const Model&, const typename Model::State& state) {
    return {{"play", state.play}};
  }
  static typename Model::State state_from_json(const Model& model, JsonFields& fields) {
    return play_state_from_json(model, fields);
  }
  static std::size_t parameter_count(const Model& model) {
    const auto& p = model.params();
    const std::size_t envelope = p.ascending.size() + p.descending.size();
    return envelope + (p.density == GpiDensity::exponential ? 3 : 2 * model.size());
  }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    std::string text = fmt::format(
        "generalized Prandtl-Ishlinskii model: {} envelopes, {} density, {} operators, input "
        "range [{}, {}]\n",
        to_string(p.envelope), to_string(p.density), model.size(), p.input_min, p.input_max);
    text += fmt::format("  ascending envelope gamma_l coefficients:  {}\n",
                        fmt::join(p.ascending, ", "));
    text += fmt::format("  descending envelope gamma_r coefficients: {}\n",
                        fmt::join(p.descending, ", "));
    text += "   j   threshold r_j      weight p_j\n";
    for (std::size_t j = 0; j < model.size(); ++j) {
      text +=
          fmt::format("{:4}  {:14.8g}  {:14.8g}\n", j, model.thresholds()[j], model.weights()[j]);
    }
    return text;
  }
  static bool has_inverse(const Model&) { return true; }
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model,
                                                      const typename Model::State& state,
                                                      const InverseLimits& limits) {
    Inverse inverse(model, {limits.input_min, limits.input_max});
    auto inverse_state = inverse.state_consistent_with(state);
    const auto state_to_json = [](const typename Inverse::State& s) {
      return nlohmann::json{
          {"play", s.pi.play},
          {"envelope_value", s.u},
          {"branch", s.branch == LoopBranch::ascending ? "ascending" : "descending"}};
    };
    return std::make_unique<InverseAdapter<Inverse, decltype(state_to_json)>>(
        std::move(inverse), std::move(inverse_state), state_to_json);
  }
};

std::unique_ptr<DynamicModel> create_generalized_prandtl_ishlinskii(
    const nlohmann::json& params_json, const nlohmann::json* state_json) {
  const auto params = gpi_parameter_table().read(params_json, "params");
  return visit_envelope(params.envelope, [&]<class E>(E) {
    return make_dynamic_model<GpiCodec<E>>(params, state_json);
  });
}

// {"a0": ..., "tau": ...}: values by GPI parameter name (GpiParameter's spelling); with
// `every_one`, all eleven must be given.
using GpiBoundOverrides = std::array<std::optional<double>, kGpiParameterCount>;

GpiBoundOverrides gpi_values_from_json(const nlohmann::json& json, const std::string& path,
                                       bool every_one) {
  JsonFields fields(json, path);
  GpiBoundOverrides values{};
  for (std::size_t i = 0; i < kGpiParameterCount; ++i) {
    const auto name = to_string(static_cast<GpiParameter>(i));
    if (every_one || fields.has(name)) values[i] = fields.number(name);
  }
  fields.finish();
  return values;
}

template <class Values>
nlohmann::json gpi_values_to_json(const Values& values) {
  auto json = nlohmann::json::object();
  for (std::size_t i = 0; i < kGpiParameterCount; ++i) {
    const std::optional<double> value = values[i];
    if (value) json[std::string(to_string(static_cast<GpiParameter>(i)))] = *value;
  }
  return json;
}

// "lower" or "upper": bound overrides by parameter name.
void add_gpi_bounds(FieldTable<GpiFitOptions>& table, std::string_view name,
                    GpiBoundOverrides GpiFitOptions::*member) {
  const std::string key(name);
  table.add_custom(
      {key,
       "object",
       "",
       fmt::format("{} bounds by parameter, e.g. {{\"tau\": 0, \"alpha\": 1e-4}} (default: "
                   "scaled to the data; rho is the gauge and keeps its start value)",
                   name),
       {}},
      Presence::optional,
      [key, member](JsonFields& fields, GpiFitOptions& options) {
        options.*member = gpi_values_from_json(*fields.raw(key), fields.path_of(key), false);
      },
      [key, member](const GpiFitOptions& options, nlohmann::json& json) {
        json[key] = gpi_values_to_json(options.*member);
      });
}

FieldTable<GpiFitOptions> generalized_prandtl_ishlinskii_fit_option_table() {
  using O = GpiFitOptions;
  FieldTable<O> table(Presence::optional);
  table.add("m", &O::m, "", "operators j = 0..m")
      .add("initial_state", &O::initial_state, gpi_initial_state_from_string,
           "rest (at the first input, rising) or periodic")
      .add("input_min", &O::input_min, "input units", "operating range (default: the data's)")
      .add("input_max", &O::input_max, "input units", "operating range (default: the data's)")
      .add_custom(
          {"starts",
           "array of objects",
           "",
           "starting points {a0, a1, a2, a3, b0, b1, b2, b3, rho, tau, alpha} (default: "
           "derived from the data)",
           {}},
          Presence::optional,
          [](JsonFields& fields, O& options) {
            const auto& list = *fields.raw("starts");
            if (!list.is_array()) {
              throw Error(fmt::format("{}: expected an array of objects, got {}",
                                      fields.path_of("starts"), describe_json(list)));
            }
            options.starts.clear();
            for (std::size_t s = 0; s < list.size(); ++s) {
              const auto values = gpi_values_from_json(
                  list[s], fmt::format("{}[{}]", fields.path_of("starts"), s), true);
              auto& start = options.starts.emplace_back();
              for (std::size_t i = 0; i < kGpiParameterCount; ++i)
                start[i] = *values[i];
            }
          },
          [](const O& options, nlohmann::json& json) {
            if (options.starts.empty()) return;
            auto& list = json["starts"] = nlohmann::json::array();
            for (const auto& start : options.starts)
              list.push_back(gpi_values_to_json(start));
          });
  table = add_multistart_options(std::move(table));
  add_gpi_bounds(table, "lower", &O::lower);
  add_gpi_bounds(table, "upper", &O::upper);
  return table;
}

}  // namespace

ModelEntry generalized_prandtl_ishlinskii_entry() {
  ModelEntry entry;
  entry.name = "gpi";
  entry.description =
      "generalized Prandtl-Ishlinskii (MSMA): plays on tanh/arctan/linear envelopes, exponential "
      "density; analytic inverse (IGPI); nonlinear fit (Ceres)";
  entry.parameters = gpi_parameter_table().schema();
  entry.create = &create_generalized_prandtl_ishlinskii;
  set_fitter<GpiCodec<TanhEnvelope>>(entry, generalized_prandtl_ishlinskii_fit_option_table(),
                                     [](auto input, auto output, const auto& options) {
                                       return fit_generalized_prandtl_ishlinskii(input, output,
                                                                                 options);
                                     });
  // The parameter set of the reference checks (pi_check.py).
  entry.example_params = {{"envelope", "tanh"},
                          {"ascending", {2.0, 0.8, -0.1, 0.05}},
                          {"descending", {2.0, 0.8, 0.25, 0.05}},
                          {"density", "exponential"},
                          {"rho", 0.6},
                          {"tau", 0.9},
                          {"alpha", 0.12},
                          {"m", 8},
                          {"input_min", -3.0},
                          {"input_max", 3.0},
                          {"initial_input", 0.0}};
  entry.c_code =
      c_code_of<GpiCodec<TanhEnvelope>, GpiCodec<ArctanEnvelope>, GpiCodec<LinearEnvelope>>();
  entry.actuator_force = actuator_force_of<GpiCodec<TanhEnvelope>, GpiCodec<ArctanEnvelope>,
                                           GpiCodec<LinearEnvelope>>();
  return entry;
}

}  // namespace hyst::detail
