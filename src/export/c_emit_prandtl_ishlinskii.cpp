// C emitters of the classical and the modified Prandtl-Ishlinskii model with their analytic
// inverses (prandtl_ishlinskii.hpp, modified_prandtl_ishlinskii.hpp,
// inverse_prandtl_ishlinskii.hpp, inverse_modified_prandtl_ishlinskii.hpp).

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "c_emitters.hpp"
#include "hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"

namespace hyst::detail {
namespace {

constexpr std::string_view kCopyFunction = R"(/* Copies an exported play state. */
static void @_copy_play(@_real *play, const @_real *from) {
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) play[j] = from[j];
}

)";

// The state type both models share (after their own @_params struct).
constexpr std::string_view kStateType = R"(
/* State: the play outputs w_j [input units]. */
typedef struct {
  @_real play[@_OPERATORS];
} @_state;
)";

// The inverse state type both models share (after their own @_inverse_params struct).
constexpr std::string_view kInverseStateType = R"(
/* State of the inverse: its play outputs wh_j [output units]. */
typedef struct {
  @_real play[@_OPERATORS];
} @_inverse_state;
)";

std::string model_declarations() {
  return std::string(kStateType) +
         c_model_declarations("every w_j = 0", "updates every play and returns the output.");
}

std::string inverse_declarations() {
  return std::string(kInverseStateType) + c_inverse_declarations("");
}

// The input an inverse gave last, from its plays as they are: a NaN target holds it.
constexpr std::string_view kHeldInputFunction =
    R"(/* sum_j ph_j wh_j of the plays as they are: the input the last step returned, before its
   limits. A NaN target holds it (and leaves the plays alone). */
static @_real @_held_input(const @_real *weights, const @_real *play) {
  @_real sum = #(0.0);
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) sum += weights[j] * play[j];
  return sum;
}

)";

std::string inverse_functions(const CWriter& writer, double gain) {
  return c_inverse_target_functions(writer, gain) + std::string(kHeldInputFunction);
}

std::string state_tables(const CWriter& writer, std::string_view name,
                         const std::vector<double>& init, const std::vector<double>& reset) {
  return CWriter::fill(
      "/* The state stored in the model file (INIT) and the default initial state (RESET). */\n"
      "static const @_real @_%NAME%_INIT[@_OPERATORS] = %INIT%;\n"
      "static const @_real @_%NAME%_RESET[@_OPERATORS] = %RESET%;\n\n",
      {{"NAME", std::string(name)}, {"INIT", writer.table(init)}, {"RESET", writer.table(reset)}});
}

std::string model_state_functions(const CWriter& writer, const std::vector<double>& init,
                                  const std::vector<double>& reset) {
  return state_tables(writer, "PLAY", init, reset) +
         "void @_init(@_state *state) { @_copy_play(state->play, @_PLAY_INIT); }\n\n"
         "void @_reset(@_state *state) { @_copy_play(state->play, @_PLAY_RESET); }\n\n";
}

std::string inverse_state_functions(const CWriter& writer, const std::vector<double>& init,
                                    const std::vector<double>& reset) {
  return state_tables(writer, "INVERSE_PLAY", init, reset) +
         "void @_inverse_init(@_inverse_state *state) {\n"
         "  @_copy_play(state->play, @_INVERSE_PLAY_INIT);\n}\n\n"
         "void @_inverse_reset(@_inverse_state *state) {\n"
         "  @_copy_play(state->play, @_INVERSE_PLAY_RESET);\n}\n\n";
}

}  // namespace

CModelCode emit_c(const PrandtlIshlinskii& pi, const PrandtlIshlinskii::State& state,
                  const CWriter& writer, const CExportOptions& options) {
  const auto& p = pi.params();
  CModelCode code;
  code.title = fmt::format("Prandtl-Ishlinskii model (pi), {} play operators", pi.size());
  code.description =
      " *     y = y_off + sum_j p_j w_j,   w_j = max(v - r_j, min(v + r_j, w_j previous))\n"
      " * (include/hyst/models/prandtl_ishlinskii.hpp). Inverse, when p_0 > 0 and every partial\n"
      " * sum of the weights is > 0: the analytic inverse PI (Krejci & Kuhnen 2001),\n"
      " * v = sum_j ph_j wh_j on y - y_off "
      "(include/hyst/inverse/inverse_prandtl_ishlinskii.hpp).\n";
  code.has_inverse = pi.is_invertible();
  code.state_check = code.inverse_state_check = "fmu_finite(s->play, @_OPERATORS)";
  code.parameters = {c_array("thresholds", p.thresholds, CUnit::input, "play thresholds r_j",
                             CRule::increasing_from_zero),
                     c_array("weights", p.weights, CUnit::output_per_input, "play weights p_j"),
                     c_scalar("offset", p.offset, CUnit::output, "output offset y_off")};
  code.header = CWriter::fill(R"(#define @_OPERATORS %N%

/* Parameters: thresholds r_j [input units], weights p_j [output/input units], offset y_off
   [output units]. */
typedef struct {
  @_real thresholds[@_OPERATORS];
  @_real weights[@_OPERATORS];
  @_real offset;
} @_params;
)",
                              {{"N", std::to_string(pi.size())}}) +
                model_declarations();
  code.source = std::string(c_play_functions()) + std::string(kCopyFunction) +
                CWriter::fill("const @_params @_PARAMS = {\n    %R%,\n    %P%,\n    %OFF%};\n\n",
                              {{"R", writer.table(p.thresholds)},
                               {"P", writer.table(p.weights)},
                               {"OFF", writer.number(p.offset)}}) +
                model_state_functions(writer, state.play, pi.initial_state().play) +
                R"(@_real @_step(const @_params *params, @_state *state, @_real input) {
  return @_play_sum(params->thresholds, params->weights, params->offset, state->play,
                    @_OPERATORS, input);
}
)";
  if (!code.has_inverse) return code;

  const InversePrandtlIshlinskii inverse(pi, {options.limits.input_min, options.limits.input_max});
  const auto& ip = inverse.inverse_operator().params();
  code.inverse_parameters = {c_array("thresholds", ip.thresholds, CUnit::output,
                                     "inverse play thresholds rh_j", CRule::increasing_from_zero),
                             c_array("weights", ip.weights, CUnit::input_per_output,
                                     "inverse play weights ph_j", CRule::partial_sums_positive),
                             c_scalar("input_min", options.limits.input_min, CUnit::input,
                                      "lowest input returned", CRule::lower_limit),
                             c_scalar("input_max", options.limits.input_max, CUnit::input,
                                      "highest input returned", CRule::upper_limit),
                             c_scalar("offset", p.offset, CUnit::output, "output offset y_off")};
  code.header += R"(
/* Inverse parameters: a PI operator with thresholds rh_j and weights ph_j on target - y_off,
   then the input limits. */
typedef struct {
  @_real thresholds[@_OPERATORS]; /* rh_j [output units] */
  @_real weights[@_OPERATORS];    /* ph_j [input/output units] */
  @_real input_min;               /* admissible input range [input units] */
  @_real input_max;
  @_real offset;                  /* y_off */
} @_inverse_params;
)" + inverse_declarations();
  code.source += "\n" + inverse_functions(writer, c_gain(ip.weights)) +
                 CWriter::fill(
                     "const @_inverse_params @_INVERSE_PARAMS = {\n    %R%,\n    %P%,\n"
                     "    %MIN%, %MAX%, %OFF%};\n\n",
                     {{"R", writer.table(ip.thresholds)},
                      {"P", writer.table(ip.weights)},
                      {"MIN", writer.number(options.limits.input_min)},
                      {"MAX", writer.number(options.limits.input_max)},
                      {"OFF", writer.number(p.offset)}}) +
                 inverse_state_functions(writer, inverse.state_consistent_with(state).play,
                                         inverse.initial_state().play) +
                 R"(@_real @_inverse_step(const @_inverse_params *params, @_inverse_state *state,
                     @_real target) {
  const @_real input =
      target != target ? @_held_input(params->weights, state->play)
                       : @_play_sum(params->thresholds, params->weights, #(0.0), state->play,
                                    @_OPERATORS, @_bounded_target(target) - params->offset);
  return @_clamp(input, params->input_min, params->input_max);
}
)";
  return code;
}

CModelCode emit_c(const ModifiedPrandtlIshlinskii& mpi,
                  const ModifiedPrandtlIshlinskii::State& state, const CWriter& writer,
                  const CExportOptions& options) {
  const auto& p = mpi.params();
  CModelCode code;
  code.title = fmt::format(
      "modified Prandtl-Ishlinskii model (modified_pi), {} play operators, {} dead zones",
      mpi.hysteresis().size(), mpi.dead_zone().size());
  code.description =
      " *     y = y_off + S(q + sum_j p_j w_j),   S(x) = sum_i g_i S_{d_i}(x)   (Kuhnen 2003)\n"
      " * (include/hyst/models/modified_prandtl_ishlinskii.hpp). Inverse, when both parts are\n"
      " * invertible: v = PI^-1[S^-1(y - y_off)], S^-1 again a dead-zone superposition\n"
      " * (include/hyst/inverse/inverse_modified_prandtl_ishlinskii.hpp).\n";
  code.has_inverse = mpi.is_invertible();
  code.state_check = code.inverse_state_check = "fmu_finite(s->play, @_OPERATORS)";
  code.parameters = {
      c_array("thresholds", p.pi.thresholds, CUnit::input, "play thresholds r_j",
              CRule::increasing_from_zero),
      c_array("weights", p.pi.weights, CUnit::none, "play weights p_j"),
      c_scalar("pi_offset", p.pi.offset, CUnit::none, "offset q of the PI part"),
      c_array("dead_zone_thresholds", p.dead_zone.thresholds, CUnit::none,
              "dead-zone thresholds d_i (units of the PI part)", CRule::increasing),
      c_array("dead_zone_weights", p.dead_zone.weights, CUnit::none, "dead-zone weights g_i"),
      c_scalar("offset", p.offset, CUnit::output, "output offset y_off")};
  code.header = CWriter::fill(R"(#define @_OPERATORS %N%
#define @_DEAD_ZONES %D%

/* Parameters: the PI part (thresholds r_j [input units], weights p_j, its offset q [output
   units]), the dead zones (thresholds d_i [output units], weights g_i) and the offset y_off. */
typedef struct {
  @_real thresholds[@_OPERATORS];
  @_real weights[@_OPERATORS];
  @_real pi_offset;
  @_real dead_zone_thresholds[@_DEAD_ZONES];
  @_real dead_zone_weights[@_DEAD_ZONES];
  @_real offset;
} @_params;
)",
                              {{"N", std::to_string(mpi.hysteresis().size())},
                               {"D", std::to_string(mpi.dead_zone().size())}}) +
                model_declarations();
  code.source =
      std::string(c_play_functions()) + std::string(kCopyFunction) +
      std::string(c_dead_zone_function()) +
      CWriter::fill(
          "const @_params @_PARAMS = {\n    %R%,\n    %P%,\n    %Q%,\n    %D%,\n    %G%,\n"
          "    %OFF%};\n\n",
          {{"R", writer.table(p.pi.thresholds)},
           {"P", writer.table(p.pi.weights)},
           {"Q", writer.number(p.pi.offset)},
           {"D", writer.table(p.dead_zone.thresholds)},
           {"G", writer.table(p.dead_zone.weights)},
           {"OFF", writer.number(p.offset)}}) +
      model_state_functions(writer, state.play, mpi.initial_state().play) +
      R"(@_real @_step(const @_params *params, @_state *state, @_real input) {
  const @_real hysteresis = @_play_sum(params->thresholds, params->weights, params->pi_offset,
                                       state->play, @_OPERATORS, input);
  @_real output = params->offset + @_dead_zones(params->dead_zone_thresholds,
                                                params->dead_zone_weights, hysteresis);
)" + c_output_limits(writer, p.output_min, p.output_max) +
      "  return output;\n}\n";
  if (!code.has_inverse) return code;

  const InverseModifiedPrandtlIshlinskii inverse(
      mpi, {options.limits.input_min, options.limits.input_max});
  const auto& ip = inverse.hysteresis_inverse().inverse_operator().params();
  const auto& dz = inverse.dead_zone_inverse().params();
  code.inverse_parameters = {
      c_array("dead_zone_thresholds", dz.thresholds, CUnit::output,
              "inverse dead-zone thresholds d'_i", CRule::increasing),
      c_array("dead_zone_weights", dz.weights, CUnit::none, "inverse dead-zone weights g'_i"),
      c_scalar("offset", p.offset, CUnit::output, "output offset y_off"),
      c_array("thresholds", ip.thresholds, CUnit::none, "inverse play thresholds rh_j",
              CRule::increasing_from_zero),
      c_array("weights", ip.weights, CUnit::none, "inverse play weights ph_j",
              CRule::partial_sums_positive),
      c_scalar("pi_offset", p.pi.offset, CUnit::none, "offset q of the PI part"),
      c_scalar("input_min", options.limits.input_min, CUnit::input, "lowest input returned",
               CRule::lower_limit),
      c_scalar("input_max", options.limits.input_max, CUnit::input, "highest input returned",
               CRule::upper_limit)};
  code.header += R"(
/* Inverse parameters: S^-1 (thresholds d'_i, weights g'_i) on target - y_off, then a PI operator
   with thresholds rh_j and weights ph_j on that minus q, then the input limits. */
typedef struct {
  @_real dead_zone_thresholds[@_DEAD_ZONES]; /* d'_i */
  @_real dead_zone_weights[@_DEAD_ZONES];    /* g'_i */
  @_real offset;                             /* y_off */
  @_real thresholds[@_OPERATORS];            /* rh_j */
  @_real weights[@_OPERATORS];               /* ph_j */
  @_real pi_offset;                          /* q */
  @_real input_min;                          /* admissible input range [input units] */
  @_real input_max;
} @_inverse_params;
)" + inverse_declarations();
  code.source +=
      "\n" + inverse_functions(writer, c_gain(dz.weights) * c_gain(ip.weights)) +
      CWriter::fill(
          "const @_inverse_params @_INVERSE_PARAMS = {\n    %D%,\n    %G%,\n    %OFF%,\n    %R%,\n"
          "    %P%,\n    %Q%, %MIN%, %MAX%};\n\n",
          {{"D", writer.table(dz.thresholds)},
           {"G", writer.table(dz.weights)},
           {"OFF", writer.number(p.offset)},
           {"R", writer.table(ip.thresholds)},
           {"P", writer.table(ip.weights)},
           {"Q", writer.number(p.pi.offset)},
           {"MIN", writer.number(options.limits.input_min)},
           {"MAX", writer.number(options.limits.input_max)}}) +
      inverse_state_functions(writer, inverse.state_consistent_with(state).play,
                              inverse.initial_state().play) +
      R"(@_real @_inverse_step(const @_inverse_params *params, @_inverse_state *state,
                     @_real target) {
  @_real input;
  if (target != target) {
    input = @_held_input(params->weights, state->play);
  } else {
    const @_real hysteresis = @_dead_zones(params->dead_zone_thresholds,
                                           params->dead_zone_weights,
                                           @_bounded_target(target) - params->offset);
    input = @_play_sum(params->thresholds, params->weights, #(0.0), state->play, @_OPERATORS,
                       hysteresis - params->pi_offset);
  }
  return @_clamp(input, params->input_min, params->input_max);
}
)";
  return code;
}

}  // namespace hyst::detail
