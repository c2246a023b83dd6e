// C emitter of the PI model with creep and its exact inverse (prandtl_ishlinskii_creep.hpp,
// inverse_prandtl_ishlinskii_creep.hpp). The lags' decays a_i = exp(-Ts / tau_i) are exported as
// the library computed them, so the C step repeats the library's operations in its order.

#include <algorithm>
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

/* Parameters: thresholds r_j [input units], weights p_j, the lags' decays a_i = exp(-Ts / tau_i)
   at the sample time Ts = %TS% s, creep weights c_ij (row i: lag, column j: play) and the
   offset y_off. */
typedef struct {
  @_real thresholds[@_OPERATORS];
  @_real weights[@_OPERATORS];
  @_real decay[@_CREEP_SIZE];
  @_real creep_weights[@_CREEP_SIZE];
  @_real offset;
} @_params;

/* State: the play outputs w_j and the lags z_ij [input units]. */
typedef struct {
  @_real play[@_OPERATORS];
  @_real creep[@_CREEP_SIZE];
} @_state;
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
}

void @_reset(@_state *state) {
  @_copy(state->play, @_PLAY_RESET, @_OPERATORS);
  @_copy(state->creep, @_CREEP_RESET, @_CREEP_SIZE);
}

@_real @_step(const @_params *params, @_state *state, @_real input) {
  @_real output = params->offset;
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) {
    state->play[j] = @_play(input, params->thresholds[j], state->play[j]);
    output += params->weights[j] * state->play[j];
  }
%LAG_STEP%  return output;
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
} @_inverse_params;

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
}

void @_inverse_reset(@_inverse_state *state) {
  @_copy(state->model.play, @_PLAY_RESET, @_OPERATORS);
  @_copy(state->model.creep, @_CREEP_RESET, @_CREEP_SIZE);
  @_copy(state->play, @_INVERSE_PLAY_RESET, @_OPERATORS);
}

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
%LAG_MEMORY%  shifted = target - model->offset - memory;
  for (j = 0; j < @_OPERATORS; ++j)
    state->play[j] = @_play(shifted, params->thresholds[j], state->play[j]);
  for (j = 0; j < @_OPERATORS; ++j) sum += params->weights[j] * state->play[j];
  input = sum;
  if (input < params->input_min) input = params->input_min;
  if (input > params->input_max) input = params->input_max;
  @_step(model, &state->model, input);
  if (input != sum) @_resynchronise(params, state);
  return input;
}
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

}  // namespace

CModelCode emit_c(const PrandtlIshlinskiiCreep& model, const PrandtlIshlinskiiCreep::State& state,
                  const CWriter& writer, const CExportOptions& options) {
  const auto& p = model.params();
  const auto reset = model.initial_state();
  CModelCode code;
  code.title = fmt::format("Prandtl-Ishlinskii model with creep (pi_creep), {} plays, {} lags",
                           model.size(), model.lags());
  code.description =
      " *     y = y_off + sum_j p_j w_j + sum_ij c_ij z_ij,   z_ij = a_i z_ij + (1 - a_i) w_j\n"
      " * (include/hyst/models/prandtl_ishlinskii_creep.hpp), at the fitted sample time. Inverse,\n"
      " * when the instantaneous weights form an invertible PI: the creep memory subtracted, then\n"
      " * the analytic inverse PI (include/hyst/inverse/inverse_prandtl_ishlinskii_creep.hpp).\n";
  const PrandtlIshlinskii instantaneous({p.thresholds, model.instantaneous_weights(), 0.0});
  code.has_inverse = instantaneous.is_invertible();
  const std::size_t creep_size = std::max<std::size_t>(1, model.size() * model.lags());
  code.header =
      CWriter::fill(std::string(kCreepTypes), {{"N", std::to_string(model.size())},
                                               {"L", std::to_string(model.lags())},
                                               {"SIZE", std::to_string(creep_size)},
                                               {"TS", fmt::format("{}", p.sample_time)}}) +
      c_model_declarations("every play and lag at 0",
                           "updates the plays and the lags and returns the output.");
  std::vector<double> decay = model.decay();
  decay.resize(creep_size, 0.0);
  code.source =
      CWriter::fill(
          "const @_params @_PARAMS = {\n    %R%,\n    %P%,\n    %A%,\n    %C%,\n"
          "    %OFF%};\n\n",
          {{"R", writer.table(p.thresholds)},
           {"P", writer.table(p.weights)},
           {"A", writer.table(decay)},
           {"C", writer.table(padded_for_c(p.creep_weights))},
           {"OFF", writer.number(p.offset)}}) +
      "/* The state stored in the model file (INIT) and the default initial state (RESET). */\n" +
      creep_state_table(writer, "PLAY_INIT", "@_OPERATORS", state.play) +
      creep_state_table(writer, "CREEP_INIT", "@_CREEP_SIZE", state.creep) +
      creep_state_table(writer, "PLAY_RESET", "@_OPERATORS", reset.play) +
      creep_state_table(writer, "CREEP_RESET", "@_CREEP_SIZE", reset.creep) + "\n" +
      with_lags(kCreepModelFunctions, "LAG_STEP", kLagStep, model.lags());
  if (!code.has_inverse) return code;

  const InversePrandtlIshlinskiiCreep inverse(model,
                                              {options.limits.input_min, options.limits.input_max});
  const auto& ip = inverse.instantaneous_inverse().inverse_operator().params();
  const auto init = inverse.state_consistent_with(state);
  const auto initial = inverse.initial_state();
  code.header += std::string(kCreepInverseTypes) + c_inverse_declarations("");
  code.source +=
      "\n" +
      CWriter::fill(
          "const @_inverse_params @_INVERSE_PARAMS = {\n    %R%,\n    %P%,\n    %W%,\n"
          "    %MIN%, %MAX%};\n\n",
          {{"R", writer.table(ip.thresholds)},
           {"P", writer.table(ip.weights)},
           {"W", writer.table(model.instantaneous_weights())},
           {"MIN", writer.number(options.limits.input_min)},
           {"MAX", writer.number(options.limits.input_max)}}) +
      creep_state_table(writer, "PLAY_INVERSE_INIT", "@_OPERATORS", init.model.play) +
      creep_state_table(writer, "CREEP_INVERSE_INIT", "@_CREEP_SIZE", init.model.creep) +
      creep_state_table(writer, "INVERSE_PLAY_INIT", "@_OPERATORS", init.plays.play) +
      creep_state_table(writer, "INVERSE_PLAY_RESET", "@_OPERATORS", initial.plays.play) +
      with_lags(kCreepInverseFunctions, "LAG_MEMORY", kLagMemory, model.lags());
  return code;
}

}  // namespace hyst::detail
