// Registry entry of the Jiles-Atherton model: model-file form, numerical inverse (H from B),
// fitter.

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/identify/fit_jiles_atherton.hpp"
#include "hyst/models/jiles_atherton.hpp"
#include "model_entries.hpp"
#include "monotone_inverse_codec.hpp"

namespace hyst::detail {
namespace {

struct JilesAthertonCodec : CodecOf<JilesAtherton, "jiles_atherton"> {
  static FieldTable<P> parameters() {
    return FieldTable<P>()
        .add("ms", &P::ms, "A/m", "saturation magnetisation M_s > 0")
        .add("a", &P::a, "A/m", "anhysteretic shape, > 0")
        .add("k", &P::k, "A/m", "pinning, > 0")
        .add("c", &P::c, "-", "reversibility in [0, 1)")
        .add("alpha", &P::alpha, "-", "coupling >= 0, alpha M_s / (3 a) < 1")
        .add("variant", &P::variant, jiles_atherton_variant_from_string,
             "original or venkataraman (COMSOL, Altair Flux)", Presence::optional)
        .add("max_field_step", &P::max_field_step, "A/m",
             "> 0: fixed RK4 steps in H of at most this; 0 = RK4 under error control",
             Presence::optional)
        .add("tolerance", &P::tolerance, "A/m",
             "> 0: adaptive Dormand-Prince with this error tolerance", Presence::optional);
  }
  static nlohmann::json state_to_json(const Model&, const Model::State& state) {
    return {{"field", state.field},
            {"magnetisation", state.magnetisation},
            {"irreversible", state.irreversible},
            {"direction", state.direction}};
  }
  // "irreversible" and "direction" may be left out (files written before they were stored):
  // M_irr then follows from M, and the direction is +1.
  static Model::State state_from_json(const Model& model, JsonFields& fields) {
    const double field = fields.number("field");
    const double magnetisation = fields.number("magnetisation");
    if (!fields.has("irreversible") && !fields.has("direction")) {
      return state_at(fields, [&] { return model.state_at(field, magnetisation); });
    }
    const double irreversible = fields.number("irreversible");
    const double direction = fields.number("direction");
    return state_at(fields,
                    [&] { return model.state_at(field, magnetisation, irreversible, direction); });
  }
  static std::size_t parameter_count(const Model&) { return 5; }
  static std::string describe(const Model& model) {
    const auto& p = model.params();
    return fmt::format(
        "Jiles-Atherton model ({} variant): M_s = {} A/m, a = {} A/m, k = {} A/m, c = {}, "
        "alpha = {}\n  input H [A/m], output B [T]; {}\n",
        to_string(p.variant), p.ms, p.a, p.k, p.c, p.alpha,
        p.tolerance > 0.0
            ? fmt::format("adaptive Dormand-Prince in H, tolerance {} A/m", p.tolerance)
        : p.max_field_step > 0.0
            ? fmt::format("RK4 in H with steps <= {} A/m", p.max_field_step)
            : fmt::format("RK4 in H under error control, error estimate <= {} A/m per step",
                          JilesAtherton::default_step_error * p.ms));
  }
  static bool has_inverse(const Model&) { return true; }  // dB/dH >= mu0 > 0
  static std::unique_ptr<DynamicInverse> make_inverse(const Model& model, const Model::State& state,
                                                      const InverseLimits& limits) {
    return make_monotone_inverse<JilesAthertonCodec>(model, state, limits, state.field);
  }
};

// The entry's default differs from the C++ options': a record given to `hyst fit` starts
// demagnetised unless the user says it is one loop in steady state.
// The fit option initial_state, in the words of the other fitters: periodic or not.
constexpr EnumNames<bool, 2> kJaStartNames{{{false, "demagnetised"}, {true, "periodic"}}};

JilesAthertonFitOptions demagnetised_start() {
  JilesAthertonFitOptions options;
  options.periodic = false;
  return options;
}

FieldTable<JilesAthertonFitOptions> jiles_atherton_fit_option_table() {
  using O = JilesAthertonFitOptions;
  return add_multistart_options(
      FieldTable<O>(Presence::optional, demagnetised_start())
          .add("variant", &O::variant, jiles_atherton_variant_from_string,
               "original or venkataraman")
          .add_custom(
              {"initial_state", "string", "",
               "demagnetised (at H = 0) or periodic (the record is one loop in steady "
               "state), as the initial_state of the other fitters",
               "demagnetised"},
              Presence::optional,
              [](JsonFields& fields, O& options) {
                options.periodic = fields.parsed("initial_state", [](std::string_view text) {
                  return value_named(text, kJaStartNames, "initial state");
                });
              },
              [](const O& options, nlohmann::json& json) {
                json["initial_state"] = name_of(options.periodic, kJaStartNames);
              })
          .add("periodic", &O::periodic, "",
               "the same as initial_state = periodic (true) or demagnetised (false)")
          .add("max_field_step", &O::max_field_step, "A/m",
               "> 0: fixed RK4 steps in H of at most min(this, k / 20) while fitting; 0 = RK4 "
               "under error control")
          .add("starts", &O::starts, parameter_table<JilesAthertonCodec>(),
               "starting points {ms, a, k, c, alpha}; default: derived from the data"));
}

FitOutcome fit_jiles_atherton_request(const FitRequest& request) {
  const auto options = jiles_atherton_fit_option_table().read(request.options, "fit options");
  if (!(request.validate_fraction >= 0.0 && request.validate_fraction < 1.0)) {
    throw Error(fmt::format("validate_fraction = {} must be in [0, 1)", request.validate_fraction),
                "validate_fraction");
  }
  const auto n_fit = static_cast<std::size_t>(
      std::round(static_cast<double>(request.input.size()) * (1.0 - request.validate_fraction)));
  const BhLoop record{request.input.first(n_fit), request.output.first(n_fit)};
  auto result = fit_jiles_atherton(std::span(&record, 1), {}, options);
  if (n_fit < request.input.size()) {
    // The held-out tail continues the simulation of the whole record.
    const auto b = simulate_bh_loop(result.model, request.input, options.periodic);
    result.report.validation =
        error_metrics(request.output.subspan(n_fit), std::span(b).subspan(n_fit));
  }
  auto state = result.model.initial_state();
  if (options.periodic) {
    for (double h : request.input.first(n_fit))
      result.model.step(state, h);
  }
  return {std::make_unique<ModelAdapter<JilesAthertonCodec>>(result.model, state),
          std::move(result.report)};
}

}  // namespace

ModelEntry jiles_atherton_entry() {
  auto entry = entry_of<JilesAthertonCodec>(
      "Jiles-Atherton: B(H) of ferromagnets, original or Venkataraman variant; Ceres fit");
  entry.fit_options = jiles_atherton_fit_option_table().schema();
  entry.fit = &fit_jiles_atherton_request;
  entry.input_unit = std::string("A/m");  // H
  entry.output_unit = std::string("T");   // B
  entry.example_params = {{"ms", 1e5}, {"a", 0.5},      {"k", 0.4},
                          {"c", 0.2},  {"alpha", 1e-6}, {"variant", "original"}};
  return entry;
}

}  // namespace hyst::detail
