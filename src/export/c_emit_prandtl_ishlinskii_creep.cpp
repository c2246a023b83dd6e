// C emitters of the PI model with creep and of the modified PI model with creep, with their exact
// inverses (prandtl_ishlinskii_creep.hpp, modified_prandtl_ishlinskii_creep.hpp and their
// inverses). The modified model is the same code with the dead zones, the output offset and
// limits after the step and the inverse dead zones before the inverse step. The lags' decays
// a_i = exp(-Ts / tau_i) are exported as the library computed them, so the C step repeats the
// library's operations in its order.

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "c_emitters.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp"

namespace hyst::detail {
namespace {

// C has no empty arrays: a model without lags keeps one unused element.
std::vector<double> padded_for_c(std::vector<double> values) {
  if (values.empty()) values.push_back(0.0);
  return values;
}

constexpr std::string_view kCreepTypes = R"(#define @_OPERATORS %N%
#define @_LAGS %L%
/* Storage of the lags: @_LAGS * @_OPERATORS, at least 1 (C has no empty arrays). */
#define @_CREEP_SIZE %SIZE%
%DEAD_ZONE_SIZE%
/* Parameters: thresholds r_j [input units], weights p_j, the lags' time constants tau_i [s] and
   their decays a_i = exp(-Ts / tau_i) at the sample time Ts (fitted: %TS% s;
   @_set_sample_time() sets another), creep weights c_ij (row i: lag, column j: play) and the
   offset y_off. */
typedef struct {
  @_real thresholds[@_OPERATORS];
  @_real weights[@_OPERATORS];
  @_real time_constants[@_CREEP_SIZE];
  @_real decay[@_CREEP_SIZE];
  @_real creep_weights[@_CREEP_SIZE];
  @_real offset;
%LEAK_FIELDS%%SHAPE_FIELDS%} @_params;

/* State: the play outputs w_j and the lags z_ij [input units]%LEAK_STATE_NOTE%. */
typedef struct {
  @_real play[@_OPERATORS];
  @_real creep[@_CREEP_SIZE];
%LEAK_STATE%} @_state;
)";

constexpr std::string_view kCreepModelFunctions =
    R"(/* One play operator, as the library's play_step(). */
static @_real @_play(@_real input, @_real threshold, @_real previous) {
  const @_real upper = input + threshold;
  const @_real lower = input - threshold;
  const @_real clipped = previous < upper ? previous : upper;
  return lower < clipped ? clipped : lower;
}

static void @_copy(@_real *to, const @_real *from, unsigned int n) {
  unsigned int k;
  for (k = 0; k < n; ++k) to[k] = from[k];
}

void @_init(@_state *state) {
  @_copy(state->play, @_PLAY_INIT, @_OPERATORS);
  @_copy(state->creep, @_CREEP_INIT, @_CREEP_SIZE);
%LEAK_INIT%}

void @_reset(@_state *state) {
  @_copy(state->play, @_PLAY_RESET, @_OPERATORS);
  @_copy(state->creep, @_CREEP_RESET, @_CREEP_SIZE);
%LEAK_RESET%}

void @_set_sample_time(@_params *params, double sample_time) {
%SET_DECAYS%}

@_real @_step(const @_params *params, @_state *state, @_real input) {
  @_real output = params->offset;
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) {
    state->play[j] = @_play(input, params->thresholds[j], state->play[j]);
    output += params->weights[j] * state->play[j];
  }
%LAG_STEP%%LEAK_STEP%%SHAPE%  return output;
}
)";

constexpr std::string_view kCreepInverseTypes = R"(
/* Inverse parameters: the inverse PI operator (thresholds rh_j, weights ph_j) of the
   instantaneous weights p_j + sum_i c_ij (1 - a_i), those weights themselves, the input
   limits. */
typedef struct {
  @_real thresholds[@_OPERATORS];
  @_real weights[@_OPERATORS];
  @_real instantaneous[@_OPERATORS];
  @_real input_min;
  @_real input_max;
%INVERSE_SHAPE_FIELDS%} @_inverse_params;

/* State of the inverse: the model's state and the inverse operator's plays wh_j. */
typedef struct {
  @_state model;
  @_real play[@_OPERATORS];
} @_inverse_state;
)";

constexpr std::string_view kCreepInverseFunctions = R"(
void @_inverse_init(@_inverse_state *state) {
  @_copy(state->model.play, @_PLAY_INVERSE_INIT, @_OPERATORS);
  @_copy(state->model.creep, @_CREEP_INVERSE_INIT, @_CREEP_SIZE);
  @_copy(state->play, @_INVERSE_PLAY_INIT, @_OPERATORS);
%LEAK_INVERSE_INIT%}

void @_inverse_reset(@_inverse_state *state) {
  @_copy(state->model.play, @_PLAY_RESET, @_OPERATORS);
  @_copy(state->model.creep, @_CREEP_RESET, @_CREEP_SIZE);
  @_copy(state->play, @_INVERSE_PLAY_RESET, @_OPERATORS);
%LEAK_INVERSE_RESET%}

/* After a limited input: the inverse plays from the model's, wh_j = S_j w_j + sum_{i>j} ph_i w_i
   with S_j the partial sums of the instantaneous weights. */
static void @_resynchronise(const @_inverse_params *params, @_inverse_state *state) {
  @_real total = #(0.0);
  @_real tail = #(0.0);
  @_real tail_weight = #(0.0);
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) total += params->instantaneous[j];
  for (j = @_OPERATORS; j-- > 0;) {
    state->play[j] = (total - tail_weight) * state->model.play[j] + tail;
    tail += params->instantaneous[j] * state->model.play[j];
    tail_weight += params->instantaneous[j];
  }
}

@_real @_inverse_step(const @_inverse_params *params, @_inverse_state *state, @_real target) {
  const @_params *model = &@_PARAMS;
  @_real memory = #(0.0);
  @_real sum = #(0.0);
  @_real shifted;
  @_real input;
  unsigned int j;
  /* A NaN target holds the last input: the inverse's plays stay, the model steps on with it. */
  if (target == target) {
    target = @_bounded_target(target);
%LAG_MEMORY%%LEAK_MEMORY%    shifted = %TARGET% - model->offset - memory;
    for (j = 0; j < @_OPERATORS; ++j)
      state->play[j] = @_play(shifted, params->thresholds[j], state->play[j]);
  }
  for (j = 0; j < @_OPERATORS; ++j) sum += params->weights[j] * state->play[j];
  input = @_clamp(sum, params->input_min, params->input_max);
  @_step(model, &state->model, input);
  if (input != sum) @_resynchronise(params, state);
  return input;
}
)";

// a_i = exp(-Ts / tau_i) as the library computes it (in double precision).
constexpr std::string_view kSetDecays = R"(  unsigned int i;
  for (i = 0; i < @_LAGS; ++i)
    params->decay[i] = (@_real)exp(-sample_time / (double)params->time_constants[i]);
)";

// The lags' part of the step and of the inverse's creep memory; none without lags (a loop to 0
// would be a comparison the C compiler warns about).
constexpr std::string_view kLagStep = R"(  {
    unsigned int i;
    for (i = 0; i < @_LAGS; ++i) {
      const @_real a = params->decay[i];
      for (j = 0; j < @_OPERATORS; ++j) {
        const unsigned int ij = i * @_OPERATORS + j;
        state->creep[ij] = a * state->creep[ij] + (#(1.0) - a) * state->play[j];
        output += params->creep_weights[ij] * state->creep[ij];
      }
    }
  }
)";

constexpr std::string_view kLagMemory = R"(  {
    unsigned int i;
    for (i = 0; i < @_LAGS; ++i) {
      for (j = 0; j < @_OPERATORS; ++j) {
        const unsigned int ij = i * @_OPERATORS + j;
        memory += model->creep_weights[ij] * model->decay[i] * state->model.creep[ij];
      }
    }
  }
)";

std::string with_lags(std::string_view text, std::string_view key, std::string_view lag_text,
                      std::size_t lags) {
  return CWriter::fill(text, {{key, lags > 0 ? std::string(lag_text) : std::string()}});
}

std::string creep_state_table(const CWriter& writer, std::string_view name, std::string_view size,
                              const std::vector<double>& values) {
  return CWriter::fill("static const @_real @_%NAME%[%SIZE%] = %V%;\n",
                       {{"NAME", std::string(name)},
                        {"SIZE", std::string(size)},
                        {"V", writer.table(padded_for_c(values))}});
}

// What follows the PI with creep in the modified model: S, its inverse, y_off and the limits.
struct Shaping {
  DeadZoneSuperposition::Params dead_zone;
  DeadZoneSuperposition::Params inverse;  // empty when S is not invertible
  double offset = 0.0;
  double output_min = 0.0;
  double output_max = 0.0;
};

// The fields and statements of the shaping, or none for the PI with creep.
struct ShapingText {
  std::string size;
  std::string fields;
  std::string step;
  std::string inverse_fields;
  std::string target = "target";
};

ShapingText shaping_text(const std::optional<Shaping>& shaping, const CWriter& writer) {
  if (!shaping) return {};
  ShapingText text;
  text.size = fmt::format("#define @_DEAD_ZONES {}\n", shaping->dead_zone.thresholds.size());
  text.fields =
      "  @_real dead_zone_thresholds[@_DEAD_ZONES]; /* S: d_i [output units] */\n"
      "  @_real dead_zone_weights[@_DEAD_ZONES];    /* g_i */\n"
      "  @_real output_offset;                      /* y_off */\n";
  text.step =
      "  output = params->output_offset + @_dead_zones(params->dead_zone_thresholds,\n"
      "                                                params->dead_zone_weights, output);\n" +
      c_output_limits(writer, shaping->output_min, shaping->output_max);
  text.inverse_fields =
      "  @_real dead_zone_thresholds[@_DEAD_ZONES]; /* S^-1: d'_i */\n"
      "  @_real dead_zone_weights[@_DEAD_ZONES];    /* g'_i */\n"
      "  @_real output_offset;                      /* y_off */\n";
  text.target =
      "@_dead_zones(params->dead_zone_thresholds, params->dead_zone_weights,\n"
      "                         target - params->output_offset)";
  return text;
}

// The leakage drift L += Ts (g v + i0), y += L of a PI with creep: its fields and statements, or
// none without leakage (the code of a model without it stays as it was).
struct LeakageText {
  std::string fields;
  std::string state;
  std::string state_note;
  std::string step;
  std::string set_sample_time;
  std::string memory;
  std::string values;
};

LeakageText leakage_text(const PrandtlIshlinskiiCreep& model, const CWriter& writer) {
  if (!model.has_leakage()) return {};
  const auto& p = model.params();
  return {
      "  @_real leakage_conductance; /* g [output units / (input units s)] */\n"
      "  @_real leakage_current;     /* i0 [output units / s] */\n"
      "  @_real sample_time;         /* Ts [s] of the leakage's integration */\n",
      "  @_real leakage;\n",
      " and the leakage L [output units]",
      "  state->leakage += params->sample_time *\n"
      "                    (params->leakage_conductance * input + params->leakage_current);\n"
      "  output += state->leakage;\n",
      "  params->sample_time = (@_real)sample_time;\n",
      "    memory += state->model.leakage + model->sample_time * model->leakage_current;\n",
      CWriter::fill(",\n    %G%, %I%, %TS%", {{"G", writer.number(p.leakage_conductance)},
                                              {"I", writer.number(p.leakage_current)},
                                              {"TS", writer.number(p.sample_time)}})};
}

// `name` = value; for the leakage of a state (none without leakage).
std::string leakage_assignment(const PrandtlIshlinskiiCreep& model, std::string_view name,
                               double value, const CWriter& writer) {
  if (!model.has_leakage()) return {};
  return fmt::format("  {} = {};\n", name, writer.number(value));
}

// The code of a PI with creep `model`, followed by `shaping` when it has one.
CModelCode emit_creep_code(const PrandtlIshlinskiiCreep& model,
                           const PrandtlIshlinskiiCreep::State& state,
                           const std::optional<Shaping>& shaping, bool has_inverse,
                           const CWriter& writer, const CExportOptions& options) {
  const auto& p = model.params();
  const auto reset = model.initial_state();
  const ShapingText text = shaping_text(shaping, writer);
  const LeakageText leak = leakage_text(model, writer);
  CModelCode code;
  code.has_inverse = has_inverse;
  code.sample_time = p.sample_time;
  // The modified model's S gives the output its units; the PI part's are then S's input units.
  const CUnit pi_unit = shaping ? CUnit::none : CUnit::output;
  const CUnit weight_unit = shaping ? CUnit::none : CUnit::output_per_input;
  code.parameters = {c_array("thresholds", p.thresholds, CUnit::input, "play thresholds r_j",
                             CRule::increasing_from_zero),
                     c_array("weights", p.weights, weight_unit, "play weights p_j")};
  code.resamplable = true;
  if (model.lags() > 0) {
    code.parameters.push_back(c_array("time_constants", p.time_constants, CUnit::seconds,
                                      "lag time constants tau_i [s]", CRule::positive));
    code.parameters.push_back(c_array("creep_weights", p.creep_weights, weight_unit,
                                      "creep weights c_ij (row i: lag, column j: play)"));
  }
  code.parameters.push_back(c_scalar("offset", p.offset, pi_unit, "offset of the PI with creep"));
  if (model.has_leakage()) {
    code.parameters.push_back(c_scalar("leakage_conductance", p.leakage_conductance, CUnit::none,
                                       "leakage conductance g [output units / (input units s)]"));
    code.parameters.push_back(c_scalar("leakage_current", p.leakage_current, CUnit::none,
                                       "leakage offset current i0 [output units / s]"));
  }
  if (shaping) {
    code.parameters.push_back(c_array("dead_zone_thresholds", shaping->dead_zone.thresholds,
                                      CUnit::none, "dead-zone thresholds d_i", CRule::increasing));
    code.parameters.push_back(c_array("dead_zone_weights", shaping->dead_zone.weights, CUnit::none,
                                      "dead-zone weights g_i"));
    code.parameters.push_back(
        c_scalar("output_offset", shaping->offset, CUnit::output, "output offset y_off"));
  }
  const std::size_t creep_size = std::max<std::size_t>(1, model.size() * model.lags());
  code.state_check = "fmu_finite(s->play, @_OPERATORS) && fmu_finite(s->creep, @_CREEP_SIZE)";
  code.inverse_state_check =
      "fmu_finite(s->model.play, @_OPERATORS) && "
      "fmu_finite(s->model.creep, @_CREEP_SIZE) && "
      "fmu_finite(s->play, @_OPERATORS)";
  if (model.has_leakage()) {
    code.state_check += " && fmu_finite(&s->leakage, 1)";
    code.inverse_state_check += " && fmu_finite(&s->model.leakage, 1)";
  }
  code.header = CWriter::fill(std::string(kCreepTypes), {{"N", std::to_string(model.size())},
                                                         {"L", std::to_string(model.lags())},
                                                         {"SIZE", std::to_string(creep_size)},
                                                         {"TS", fmt::format("{}", p.sample_time)},
                                                         {"DEAD_ZONE_SIZE", text.size},
                                                         {"LEAK_FIELDS", leak.fields},
                                                         {"LEAK_STATE", leak.state},
                                                         {"LEAK_STATE_NOTE", leak.state_note},
                                                         {"SHAPE_FIELDS", text.fields}}) +
                c_model_declarations("every play and lag at 0",
                                     "updates the plays and the lags and returns the output.") +
                "/* The lags' decays at the sample time `sample_time` [s] > 0, from their time\n"
                "   constants: the step then runs at that sample time (the model is continuous "
                "in time). */\n"
                "void @_set_sample_time(@_params *params, double sample_time);\n";
  std::vector<double> decay = model.decay();
  decay.resize(creep_size, 0.0);
  std::string shaping_values;
  if (shaping) {
    shaping_values = CWriter::fill(",\n    %D%,\n    %G%,\n    %OFF%",
                                   {{"D", writer.table(shaping->dead_zone.thresholds)},
                                    {"G", writer.table(shaping->dead_zone.weights)},
                                    {"OFF", writer.number(shaping->offset)}});
  }
  code.source =
      (shaping ? std::string(c_dead_zone_function()) : std::string()) +
      CWriter::fill(
          "const @_params @_PARAMS = {\n    %R%,\n    %P%,\n    %TAU%,\n    %A%,\n    %C%,\n"
          "    %OFF%%LEAK%%SHAPING%};\n\n",
          {{"R", writer.table(p.thresholds)},
           {"P", writer.table(p.weights)},
           {"TAU", writer.table(padded_for_c(p.time_constants))},
           {"A", writer.table(decay)},
           {"C", writer.table(padded_for_c(p.creep_weights))},
           {"OFF", writer.number(p.offset)},
           {"LEAK", leak.values},
           {"SHAPING", shaping_values}}) +
      "/* The state stored in the model file (INIT) and the default initial state (RESET). */\n" +
      creep_state_table(writer, "PLAY_INIT", "@_OPERATORS", state.play) +
      creep_state_table(writer, "CREEP_INIT", "@_CREEP_SIZE", state.creep) +
      creep_state_table(writer, "PLAY_RESET", "@_OPERATORS", reset.play) +
      creep_state_table(writer, "CREEP_RESET", "@_CREEP_SIZE", reset.creep) + "\n" +
      CWriter::fill(
          with_lags(kCreepModelFunctions, "LAG_STEP", kLagStep, model.lags()),
          {{"SHAPE", text.step},
           {"LEAK_STEP", leak.step},
           {"LEAK_INIT", leakage_assignment(model, "state->leakage", state.leakage, writer)},
           {"LEAK_RESET", leakage_assignment(model, "state->leakage", 0.0, writer)},
           {"SET_DECAYS", model.lags() > 0 || model.has_leakage()
                              ? (model.lags() > 0 ? std::string(kSetDecays) : std::string()) +
                                    leak.set_sample_time
                              : "  (void)params;\n  (void)sample_time;\n"}});
  if (!code.has_inverse) return code;

  const InversePrandtlIshlinskiiCreep inverse(model,
                                              {options.limits.input_min, options.limits.input_max});
  const auto& ip = inverse.instantaneous_inverse().inverse_operator().params();
  const auto init = inverse.state_consistent_with(state);
  const auto initial = inverse.initial_state();
  code.inverse_parameters = {c_array("thresholds", ip.thresholds, pi_unit,
                                     "inverse play thresholds rh_j", CRule::increasing_from_zero),
                             c_array("weights", ip.weights, CUnit::none,
                                     "inverse play weights ph_j", CRule::partial_sums_positive),
                             c_array("instantaneous", model.instantaneous_weights(), weight_unit,
                                     "instantaneous weights p_j + sum_i c_ij (1 - a_i)"),
                             c_scalar("input_min", options.limits.input_min, CUnit::input,
                                      "lowest input returned", CRule::lower_limit),
                             c_scalar("input_max", options.limits.input_max, CUnit::input,
                                      "highest input returned", CRule::upper_limit)};
  if (shaping) {
    code.inverse_parameters.push_back(c_array("dead_zone_thresholds", shaping->inverse.thresholds,
                                              CUnit::output, "inverse dead-zone thresholds d'_i",
                                              CRule::increasing));
    code.inverse_parameters.push_back(c_array("dead_zone_weights", shaping->inverse.weights,
                                              CUnit::none, "inverse dead-zone weights g'_i"));
    code.inverse_parameters.push_back(
        c_scalar("output_offset", shaping->offset, CUnit::output, "output offset y_off"));
  }
  std::string inverse_shaping_values;
  if (shaping) {
    inverse_shaping_values = CWriter::fill(",\n    %D%,\n    %G%,\n    %OFF%",
                                           {{"D", writer.table(shaping->inverse.thresholds)},
                                            {"G", writer.table(shaping->inverse.weights)},
                                            {"OFF", writer.number(shaping->offset)}});
  }
  code.header +=
      CWriter::fill(kCreepInverseTypes, {{"INVERSE_SHAPE_FIELDS", text.inverse_fields}}) +
      c_inverse_declarations("");
  code.source +=
      "\n" +
      c_inverse_target_functions(
          writer, c_gain(ip.weights) * (shaping ? c_gain(shaping->inverse.weights) : 1.0)) +
      CWriter::fill(
          "const @_inverse_params @_INVERSE_PARAMS = {\n    %R%,\n    %P%,\n    %W%,\n"
          "    %MIN%, %MAX%%SHAPING%};\n\n",
          {{"R", writer.table(ip.thresholds)},
           {"P", writer.table(ip.weights)},
           {"W", writer.table(model.instantaneous_weights())},
           {"MIN", writer.number(options.limits.input_min)},
           {"MAX", writer.number(options.limits.input_max)},
           {"SHAPING", inverse_shaping_values}}) +
      creep_state_table(writer, "PLAY_INVERSE_INIT", "@_OPERATORS", init.model.play) +
      creep_state_table(writer, "CREEP_INVERSE_INIT", "@_CREEP_SIZE", init.model.creep) +
      creep_state_table(writer, "INVERSE_PLAY_INIT", "@_OPERATORS", init.plays.play) +
      creep_state_table(writer, "INVERSE_PLAY_RESET", "@_OPERATORS", initial.plays.play) +
      CWriter::fill(
          with_lags(kCreepInverseFunctions, "LAG_MEMORY", kLagMemory, model.lags()),
          {{"TARGET", text.target},
           {"LEAK_MEMORY", leak.memory},
           {"LEAK_INVERSE_INIT",
            leakage_assignment(model, "state->model.leakage", init.model.leakage, writer)},
           {"LEAK_INVERSE_RESET", leakage_assignment(model, "state->model.leakage", 0.0, writer)}});
  return code;
}

}  // namespace

CModelCode emit_c(const PrandtlIshlinskiiCreep& model, const PrandtlIshlinskiiCreep::State& state,
                  const CWriter& writer, const CExportOptions& options) {
  const bool invertible =
      PrandtlIshlinskii({model.params().thresholds, model.instantaneous_weights(), 0.0})
          .is_invertible();
  CModelCode code = emit_creep_code(model, state, std::nullopt, invertible, writer, options);
  code.title = fmt::format("Prandtl-Ishlinskii model with creep (pi_creep), {} plays, {} lags",
                           model.size(), model.lags());
  code.description =
      " *     y = y_off + sum_j p_j w_j + sum_ij c_ij z_ij,   z_ij = a_i z_ij + (1 - a_i) w_j\n"
      " * (include/hyst/models/prandtl_ishlinskii_creep.hpp), at the fitted sample time. Inverse,\n"
      " * when the instantaneous weights form an invertible PI: the creep memory subtracted, then\n"
      " * the analytic inverse PI (include/hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp).\n";
  if (model.has_leakage()) {
    code.description +=
        " * With the leakage drift L += Ts (g v + i0), y += L; the inverse subtracts L + Ts i0 "
        "with\n"
        " * the creep memory (g Ts is part of the instantaneous weight of play 0).\n";
  }
  return code;
}

CModelCode emit_c(const ModifiedPrandtlIshlinskiiCreep& model,
                  const ModifiedPrandtlIshlinskiiCreep::State& state, const CWriter& writer,
                  const CExportOptions& options) {
  const auto& p = model.params();
  const bool invertible = model.is_invertible();
  Shaping shaping{p.dead_zone, {}, p.offset, p.output_min, p.output_max};
  if (invertible) shaping.inverse = model.dead_zone().inverse().params();
  CModelCode code =
      emit_creep_code(model.hysteresis_creep(), state, shaping, invertible, writer, options);
  code.title = fmt::format(
      "modified Prandtl-Ishlinskii model with creep (modified_pi_creep), {} plays, {} lags, {} "
      "dead zones",
      model.hysteresis_creep().size(), model.hysteresis_creep().lags(), model.dead_zone().size());
  code.description =
      " *     y = y_off + S(q + sum_j p_j w_j + sum_ij c_ij z_ij),   S(x) = sum_i g_i S_{d_i}(x)\n"
      " * (include/hyst/models/modified_prandtl_ishlinskii_creep.hpp), at the fitted sample time;\n"
      " * params.offset is q, params.output_offset y_off. Inverse, when both parts are "
      "invertible:\n"
      " * S^-1 on the target, then the inverse of the PI with creep\n"
      " * (include/hyst/inverse/inverse_modified_prandtl_ishlinskii_creep.hpp).\n";
  return code;
}

}  // namespace hyst::detail
