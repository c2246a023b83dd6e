// C emitter of the generalized Prandtl-Ishlinskii model (GPI) and its inverse (IGPI)
// (generalized_prandtl_ishlinskii.hpp, envelopes.hpp, inverse_generalized_prandtl_ishlinskii.hpp).

#include <numbers>
#include <string>

#include <fmt/format.h>

#include "c_emitters.hpp"
#include "hyst/inverse/inverse_generalized_prandtl_ishlinskii.hpp"

namespace hyst::detail {
namespace {

// The inverse of a saturating envelope c0 F(c1 v + c2) + c3 (F = tanh or atan, INVERSE = its
// inverse function), as in envelopes.hpp. The saturation limit is emitted as @_SATURATION.
constexpr std::string_view kSaturatingInverse =
    R"(/* v = (%INVERSE%((u - c3) / c0) - c2) / c1; beyond the range the %INVERSE% argument is clamped
   to +-@_SATURATION (the library's below_range / above_range answer). */
static @_real @_envelope_inverse(const @_real *c, @_real u) {
  const @_real x = (u - c[3]) / c[0];
  if (x > -@_SATURATION && x < @_SATURATION) return ($%INVERSE%(x) - c[2]) / c[1];
  {
    const int above = u > c[3];
    const @_real clamped = above == (c[0] > #(0.0)) ? @_SATURATION : -@_SATURATION;
    return ($%INVERSE%(clamped) - c[2]) / c[1];
  }
}

)";

// The envelope gamma(v) and its inverse for each kind, as in envelopes.hpp.
std::string envelope_functions(EnvelopeKind kind) {
  switch (kind) {
    case EnvelopeKind::linear:
      return R"(/* gamma(v) = c0 v + c1 and its inverse (u - c1) / c0. */
static @_real @_envelope(const @_real *c, @_real v) { return c[0] * v + c[1]; }

static @_real @_envelope_inverse(const @_real *c, @_real u) { return (u - c[1]) / c[0]; }

)";
    case EnvelopeKind::arctan:
      return R"(/* gamma(v) = c0 atan(c1 v + c2) + c3. */
static @_real @_envelope(const @_real *c, @_real v) { return c[0] * $atan(c[1] * v + c[2]) + c[3]; }

)" + CWriter::fill(kSaturatingInverse, {{"INVERSE", "tan"}});
    case EnvelopeKind::tanh:
      break;
  }
  return R"(/* tanh(w) from one exponential, t = exp(-2|w|): sign(w) (1 - t) / (1 + t) (the library's
   tanh_by_exp). */
static @_real @_tanh(@_real w) {
  const @_real t = $exp(#(-2.0) * $fabs(w));
  return $copysign((#(1.0) - t) / (#(1.0) + t), w);
}

/* gamma(v) = c0 tanh(c1 v + c2) + c3. */
static @_real @_envelope(const @_real *c, @_real v) { return c[0] * @_tanh(c[1] * v + c[2]) + c[3]; }

)" + CWriter::fill(kSaturatingInverse, {{"INVERSE", "atanh"}});
}

// The clamp limit of the inverse envelope's argument: the library's 1 - 1e-12 in double; in
// float 1 - 1e-6, since 1 - 1e-12 rounds to 1 (an infinite atanh).
double saturation_limit(EnvelopeKind kind, bool single) {
  const double margin = single ? 1e-6 : TanhEnvelope::saturation_margin;
  return kind == EnvelopeKind::arctan ? (1.0 - margin) * std::numbers::pi / 2 : 1.0 - margin;
}

constexpr std::string_view kGpiHeader = R"(#define @_OPERATORS %N%
#define @_COEFFICIENTS %K%

/* Parameters: the ascending envelope gamma_l and the descending one gamma_r (%KIND%,
   coefficients c0..), thresholds r_j and weights p_j of the operators. */
typedef struct {
  @_real ascending[@_COEFFICIENTS];
  @_real descending[@_COEFFICIENTS];
  @_real thresholds[@_OPERATORS];
  @_real weights[@_OPERATORS];
} @_params;

/* State: the generalized play outputs z_j [envelope units]. */
typedef struct {
  @_real play[@_OPERATORS];
} @_state;
%MODEL_DECLARATIONS%
/* Inverse parameters: the inverse PI of the classical PI with the same thresholds and weights
   (thresholds rh_j, weights ph_j), the envelopes to invert, and the input limits. */
typedef struct {
  @_real thresholds[@_OPERATORS];
  @_real weights[@_OPERATORS];
  @_real ascending[@_COEFFICIENTS];
  @_real descending[@_COEFFICIENTS];
  @_real input_min; /* admissible input range [input units] */
  @_real input_max;
} @_inverse_params;

/* State of the inverse: the inverse-PI plays wh_j, the last u and its direction. */
typedef struct {
  @_real play[@_OPERATORS];
  @_real u;
  int ascending; /* 1: u last rose (invert gamma_l), 0: it fell (invert gamma_r) */
} @_inverse_state;
%INVERSE_DECLARATIONS%)";

constexpr std::string_view kGpiFunctions = R"(
void @_init(@_state *state) {
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) state->play[j] = @_PLAY_INIT[j];
}

void @_reset(@_state *state) {
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) state->play[j] = @_PLAY_RESET[j];
}

@_real @_step(const @_params *params, @_state *state, @_real input) {
  const @_real up = @_envelope(params->ascending, input);
  const @_real down = @_envelope(params->descending, input);
  @_real sum = #(0.0);
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) {
    /* z_j = max(gamma_l(v) - r_j, min(gamma_r(v) + r_j, z_j)) */
    const @_real upper = down + params->thresholds[j];
    const @_real lower = up - params->thresholds[j];
    const @_real clipped = state->play[j] < upper ? state->play[j] : upper;
    state->play[j] = lower < clipped ? clipped : lower;
  }
  for (j = 0; j < @_OPERATORS; ++j) sum += params->weights[j] * state->play[j];
  return sum;
}

void @_inverse_init(@_inverse_state *state) {
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) state->play[j] = @_INVERSE_PLAY_INIT[j];
  state->u = @_INVERSE_U_INIT;
  state->ascending = @_INVERSE_ASCENDING_INIT;
}

void @_inverse_reset(@_inverse_state *state) {
  unsigned int j;
  for (j = 0; j < @_OPERATORS; ++j) state->play[j] = @_INVERSE_PLAY_RESET[j];
  state->u = @_INVERSE_U_RESET;
  state->ascending = @_INVERSE_ASCENDING_RESET;
}

@_real @_inverse_step(const @_inverse_params *params, @_inverse_state *state, @_real target) {
  /* A NaN target holds the last input: u, its branch and the plays stay as they are. */
  if (target == target) {
    const @_real u = @_play_sum(params->thresholds, params->weights, #(0.0), state->play,
                                @_OPERATORS, @_bounded_target(target));
    if (u > state->u) {
      state->ascending = 1;
    } else if (u < state->u) {
      state->ascending = 0;
    }
    state->u = u;
  }
  return @_clamp(
      @_envelope_inverse(state->ascending ? params->ascending : params->descending, state->u),
      params->input_min, params->input_max);
}
)";

}  // namespace

template <Envelope E>
CModelCode emit_c(const GeneralizedPrandtlIshlinskii<E>& gpi,
                  const typename GeneralizedPrandtlIshlinskii<E>::State& state,
                  const CWriter& writer, const CExportOptions& options) {
  const GpiParams& params = gpi.params();
  const InverseGeneralizedPrandtlIshlinskii<E> inverse(
      gpi, {options.limits.input_min, options.limits.input_max});
  const auto& ip = inverse.inverse_pi().inverse_operator().params();
  const auto inverse_reset = inverse.initial_state();
  const auto inverse_init = inverse.state_consistent_with(state);

  CModelCode code;
  code.title = fmt::format("generalized Prandtl-Ishlinskii model (gpi), {} envelopes, {} operators",
                           to_string(params.envelope), gpi.size());
  code.description =
      " *     y = sum_j p_j z_j,   z_j = max(gamma_l(v) - r_j, min(gamma_r(v) + r_j, z_j "
      "previous))\n"
      " * (include/hyst/models/generalized_prandtl_ishlinskii.hpp). Inverse (Al Janaideh, Rakheja\n"
      " * & Su 2011): u = inverse PI of the target, v = gamma_l^-1(u) while u rises, "
      "gamma_r^-1(u)\n"
      " * while it falls (include/hyst/inverse/inverse_generalized_prandtl_ishlinskii.hpp).\n";
  code.has_inverse = true;
  const auto envelope = fmt::format("{} envelope coefficients", to_string(params.envelope));
  code.parameters = {
      c_array("ascending", params.ascending, CUnit::none, "ascending " + envelope),
      c_array("descending", params.descending, CUnit::none, "descending " + envelope),
      c_array("thresholds", gpi.thresholds(), CUnit::none,
              "operator thresholds r_j (envelope units)", CRule::increasing_from_zero),
      c_array("weights", gpi.weights(), CUnit::none, "operator weights p_j",
              CRule::partial_sums_positive)};
  code.inverse_parameters = {
      c_array("thresholds", ip.thresholds, CUnit::output, "inverse play thresholds rh_j",
              CRule::increasing_from_zero),
      c_array("weights", ip.weights, CUnit::none, "inverse play weights ph_j",
              CRule::partial_sums_positive),
      c_array("ascending", params.ascending, CUnit::none, "ascending " + envelope),
      c_array("descending", params.descending, CUnit::none, "descending " + envelope),
      c_scalar("input_min", options.limits.input_min, CUnit::input, "lowest input returned",
               CRule::lower_limit),
      c_scalar("input_max", options.limits.input_max, CUnit::input, "highest input returned",
               CRule::upper_limit)};
  code.state_check = "fmu_finite(s->play, @_OPERATORS)";
  code.inverse_state_check =
      "fmu_finite(s->play, @_OPERATORS) && fmu_finite(&s->u, 1) && (s->ascending & ~1) == 0";
  code.header = CWriter::fill(
      kGpiHeader, {{"N", std::to_string(gpi.size())},
                   {"K", std::to_string(E::coefficient_count)},
                   {"KIND", std::string(to_string(params.envelope))},
                   {"MODEL_DECLARATIONS",
                    c_model_declarations("at rest at its initial input, arrived rising",
                                         "both envelopes, every operator, the weighted sum.")},
                   {"INVERSE_DECLARATIONS", c_inverse_declarations("")}});
  const std::string saturation =
      params.envelope == EnvelopeKind::linear
          ? std::string()
          : fmt::format("#define @_SATURATION {}\n\n",
                        writer.number(saturation_limit(params.envelope, writer.single())));
  code.source =
      saturation + std::string(c_play_functions()) +
      c_inverse_target_functions(writer, c_gain(ip.weights)) + envelope_functions(params.envelope) +
      CWriter::fill(
          "const @_params @_PARAMS = {\n    %A%,\n    %B%,\n    %R%,\n    %P%};\n\n"
          "const @_inverse_params @_INVERSE_PARAMS = {\n    %IR%,\n    %IP%,\n    %A%,\n    %B%,\n"
          "    %MIN%, %MAX%};\n\n"
          "/* The states stored in the model file (INIT) and the default initial ones (RESET). */\n"
          "static const @_real @_PLAY_INIT[@_OPERATORS] = %INIT%;\n"
          "static const @_real @_PLAY_RESET[@_OPERATORS] = %RESET%;\n"
          "static const @_real @_INVERSE_PLAY_INIT[@_OPERATORS] = %IINIT%;\n"
          "static const @_real @_INVERSE_PLAY_RESET[@_OPERATORS] = %IRESET%;\n"
          "static const @_real @_INVERSE_U_INIT = %UINIT%;\n"
          "static const @_real @_INVERSE_U_RESET = %URESET%;\n"
          "static const int @_INVERSE_ASCENDING_INIT = %DINIT%;\n"
          "static const int @_INVERSE_ASCENDING_RESET = %DRESET%;\n",
          {{"A", writer.table(params.ascending)},
           {"B", writer.table(params.descending)},
           {"R", writer.table(gpi.thresholds())},
           {"P", writer.table(gpi.weights())},
           {"IR", writer.table(ip.thresholds)},
           {"IP", writer.table(ip.weights)},
           {"MIN", writer.number(options.limits.input_min)},
           {"MAX", writer.number(options.limits.input_max)},
           {"INIT", writer.table(state.play)},
           {"RESET", writer.table(gpi.initial_state().play)},
           {"IINIT", writer.table(inverse_init.pi.play)},
           {"IRESET", writer.table(inverse_reset.pi.play)},
           {"UINIT", writer.number(inverse_init.u)},
           {"URESET", writer.number(inverse_reset.u)},
           {"DINIT", inverse_init.branch == LoopBranch::ascending ? "1" : "0"},
           {"DRESET", inverse_reset.branch == LoopBranch::ascending ? "1" : "0"}}) +
      std::string(kGpiFunctions);
  return code;
}

template CModelCode emit_c(const GeneralizedPrandtlIshlinskii<TanhEnvelope>&,
                           const GeneralizedPrandtlIshlinskii<TanhEnvelope>::State&, const CWriter&,
                           const CExportOptions&);
template CModelCode emit_c(const GeneralizedPrandtlIshlinskii<ArctanEnvelope>&,
                           const GeneralizedPrandtlIshlinskii<ArctanEnvelope>::State&,
                           const CWriter&, const CExportOptions&);
template CModelCode emit_c(const GeneralizedPrandtlIshlinskii<LinearEnvelope>&,
                           const GeneralizedPrandtlIshlinskii<LinearEnvelope>::State&,
                           const CWriter&, const CExportOptions&);

}  // namespace hyst::detail
